// SPDX-License-Identifier: Apache-2.0
// What one run of a tracker over a stream produced, independent of the
// filter type: per frame the Runner's status, the step time and the
// published reports flattened to host::TrackRow.
#pragma once

#include <cstdint>
#include <vector>

#include "kestrel/hal/runner.hpp"
#include "kestrel/host/track_row.hpp"
#include "kestrel/status.hpp"

namespace kestrel::sim {

struct FrameOutcome {
  Status status = Status::kOk;   ///< Runner::poll_once() result for this frame.
  bool decoded = false;          ///< The frame decoded (t_us is valid).
  bool stepped = false;          ///< It reached Tracker::step (step_ns is valid).
  std::uint64_t step_ns = 0;     ///< Convert + step time, ns (SteadyClock).
  std::int64_t t_us = 0;         ///< Frame time, us.
  std::vector<host::TrackRow> tracks;  ///< Reports published for this frame.
};

struct StreamRunResult {
  std::vector<FrameOutcome> frames;  ///< In stream order.
  hal::RunnerStats stats;            ///< The Runner's own accounting.
};

}  // namespace kestrel::sim
