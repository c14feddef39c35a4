// SPDX-License-Identifier: Apache-2.0
// The frames a recorded feed (a Kestrel stream or ASTERIX file) gives, in
// the order the Runner would see them.
#pragma once

#include <cstddef>
#include <limits>
#include <vector>

#include "kestrel/hal/frame.hpp"
#include "kestrel/status.hpp"
#include "stream/quantise.hpp"

namespace kestrel::sim {

/// Poll `feed` to its end. A frame that did not decode keeps its place (so
/// indices match the Runner's frame count) as a placeholder with t_s = NaN
/// and no plots, counted in `skipped`.
template <class Feed>
std::vector<MeasurementFrame> frames_of_feed(Feed& feed, std::size_t& skipped) {
  std::vector<MeasurementFrame> frames;
  skipped = 0;
  hal::Frame frame{};
  for (;;) {
    const Status s = feed.poll(frame);
    if (s == Status::kNoData) break;
    if (s == Status::kOk || s == Status::kTooManyCandidates) {
      frames.push_back(from_wire_frame(frame));
    } else {
      MeasurementFrame placeholder;
      placeholder.t_s = std::numeric_limits<double>::quiet_NaN();
      frames.push_back(placeholder);
      ++skipped;
    }
  }
  return frames;
}

}  // namespace kestrel::sim
