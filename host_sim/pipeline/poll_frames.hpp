// SPDX-License-Identifier: Apache-2.0
// The one loop by which kestrel-sim drives a hal::Runner over a recorded
// stream, for every sensor kind: poll until the feed has nothing left and
// hand each frame's outcome to the caller, which reads what its kind needs
// (reports, step statistics) from the sink, the runner and the tracker.
#pragma once

#include <cstddef>
#include <cstdint>

#include "kestrel/status.hpp"

namespace kestrel::sim {

/// What one Runner::poll_once() did.
struct PolledFrame {
  Status status = Status::kOk;   ///< Runner::poll_once() result.
  bool stepped = false;          ///< The tracker stepped (the frame decoded and converted).
  std::uint64_t step_ns = 0;     ///< Adapter + Tracker::step (the runner's clock), when stepped.
  std::size_t first_report = 0;  ///< This frame's reports are the sink's [first_report, end_report).
  std::size_t end_report = 0;
};

/// Poll `runner` until its feed returns kNoData, at most `max_polls` times
/// (a bound the caller derives from the stream's size), and call
/// on_frame(const PolledFrame&) after each poll that returned anything else.
template <class Runner, class Sink, class OnFrame>
void poll_frames(Runner& runner, const Sink& sink, std::size_t max_polls, OnFrame&& on_frame) {
  for (std::size_t k = 0; k < max_polls; ++k) {
    PolledFrame f;
    f.first_report = sink.size();
    const std::uint32_t steps_before = runner.stats().steps;
    f.status = runner.poll_once();
    if (f.status == Status::kNoData) return;
    f.stepped = runner.stats().steps != steps_before;
    f.step_ns = f.stepped ? runner.stats().last_cycles : 0;
    f.end_report = sink.size();
    on_frame(f);
  }
}

}  // namespace kestrel::sim
