// SPDX-License-Identifier: Apache-2.0
// The loop every board runs: poll the feed for a frame, convert it into the
// core's scan, run Tracker::step, publish the reports to the sink, and keep
// the cycle statistics of each step (min, max, last, overruns against a
// budget) and a counter per status. Everything is a template parameter
// chosen in the board's board.hpp: no virtual dispatch on the hot path.
//
// One frame's path:  Feed::poll(Frame&) -> Adapter(Frame, Scan&) ->
//   Tracker::step(Scan) -> Tracker::reports() -> Sink::publish(Report).
#pragma once

#include <cstdint>

#include "kestrel/hal/clock.hpp"
#include "kestrel/hal/feed.hpp"
#include "kestrel/hal/frame.hpp"
#include "kestrel/hal/sink.hpp"
#include "kestrel/status.hpp"

namespace kestrel::hal {

/// Cycle and status accounting of a Runner.
struct RunnerStats {
  std::uint32_t frames = 0;           ///< Frames received from the feed (any status).
  std::uint32_t steps = 0;            ///< Frames that reached Tracker::step.
  std::uint32_t overruns = 0;         ///< Steps over the cycle budget.
  std::uint32_t publish_failures = 0; ///< Reports the sink refused.
  std::uint64_t min_cycles = UINT64_MAX;  ///< Fastest convert+step, clock cycles.
  std::uint64_t max_cycles = 0;       ///< Slowest convert+step, clock cycles.
  std::uint64_t last_cycles = 0;      ///< Latest convert+step, clock cycles.
  std::uint64_t total_cycles = 0;     ///< Sum over steps (mean = total / steps).
  std::uint32_t by_status[kStatusCount] = {};  ///< Frames per final status.
};

template <MeasurementFeed Feed, CycleClock Clock, class Tracker, class Adapter,
          TrackSink<typename Tracker::Report> Sink>
class Runner {
 public:
  using Scan = typename Tracker::Scan;

  /// @param budget_cycles a step longer than this counts as an overrun.
  Runner(Feed& feed, Clock& clock, Tracker& tracker, const Adapter& adapter, Sink& sink,
         std::uint64_t budget_cycles)
      : feed_(feed), clock_(clock), tracker_(tracker), adapter_(adapter), sink_(sink),
        budget_cycles_(budget_cycles) {}

  /// Poll the feed once and process at most one frame.
  /// @return kNoData if no frame was ready; otherwise the frame's final status:
  ///   a feed/decode status (frame dropped), kWrongKind, the tracker's step
  ///   status, or kTooManyCandidates (excess dropped, the rest tracked).
  [[nodiscard]] Status poll_once() {
    const Status polled = feed_.poll(frame_);
    if (polled == Status::kNoData) return polled;
    ++stats_.frames;
    if (polled != Status::kOk && polled != Status::kTooManyCandidates) return count(polled);

    const std::uint64_t t0 = clock_.now_cycles();
    const Status converted = adapter_(frame_, scan_);
    if (converted != Status::kOk && converted != Status::kTooManyCandidates) return count(converted);
    const Status stepped = tracker_.step(scan_);
    const std::uint64_t cycles = clock_.now_cycles() - t0;
    ++stats_.steps;
    stats_.last_cycles = cycles;
    stats_.total_cycles += cycles;
    if (cycles < stats_.min_cycles) stats_.min_cycles = cycles;
    if (cycles > stats_.max_cycles) stats_.max_cycles = cycles;
    if (cycles > budget_cycles_) ++stats_.overruns;
    if (stepped != Status::kOk) return count(stepped);

    for (const auto& report : tracker_.reports()) {
      if (sink_.publish(report) != Status::kOk) ++stats_.publish_failures;
    }
    const bool truncated = polled == Status::kTooManyCandidates || converted == Status::kTooManyCandidates;
    return count(truncated ? Status::kTooManyCandidates : Status::kOk);
  }

  const RunnerStats& stats() const { return stats_; }
  const Frame& last_frame() const { return frame_; }
  const Scan& last_scan() const { return scan_; }

 private:
  Status count(Status s) {
    ++stats_.by_status[static_cast<std::uint8_t>(s)];
    return s;
  }

  Feed& feed_;
  Clock& clock_;
  Tracker& tracker_;
  Adapter adapter_;
  Sink& sink_;
  std::uint64_t budget_cycles_;
  Frame frame_{};
  Scan scan_{};
  RunnerStats stats_{};
};

}  // namespace kestrel::hal
