// SPDX-License-Identifier: Apache-2.0
// SteadyClock: the host's CycleClock (hal/clock.hpp). One "cycle" is one
// nanosecond of std::chrono::steady_clock, so the Runner's cycle statistics
// read directly as nanoseconds on the host. steady_clock never goes
// backwards, which the Runner relies on when it subtracts two readings.
#pragma once

#include <chrono>
#include <cstdint>

namespace kestrel::host {

class SteadyClock {
 public:
  /// Nanoseconds since an arbitrary epoch (only differences are meaningful).
  std::uint64_t now_cycles() const {
    const auto since_epoch = std::chrono::steady_clock::now().time_since_epoch();
    return static_cast<std::uint64_t>(
        std::chrono::duration_cast<std::chrono::nanoseconds>(since_epoch).count());
  }
  /// One cycle per nanosecond.
  std::uint64_t cycles_per_second() const { return 1'000'000'000u; }
};

}  // namespace kestrel::host
