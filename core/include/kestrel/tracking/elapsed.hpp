// SPDX-License-Identifier: Apache-2.0
// Differences of frame times. Frame times are any int64 microsecond count a
// sensor sends; the difference of two need not fit, so it saturates.
#pragma once

#include <cstdint>

namespace kestrel {

/// b - a in microseconds, saturated to [INT64_MIN, INT64_MAX].
constexpr std::int64_t elapsed_us(std::int64_t b, std::int64_t a) {
  std::int64_t d = 0;
  if (__builtin_sub_overflow(b, a, &d)) return b > a ? INT64_MAX : INT64_MIN;
  return d;
}

}  // namespace kestrel
