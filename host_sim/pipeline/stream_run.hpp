// SPDX-License-Identifier: Apache-2.0
// One run of a tracker over a byte stream, driven exactly as a board drives
// it: host::StreamFileFeed -> hal::RadarAdapter -> Tracker::step ->
// host::MemorySink, inside hal::Runner and timed by host::SteadyClock
// (targets/host/board.hpp). Everything the loop touches is sized in the
// constructor, so run_to_end() makes no allocation (tests assert it), and
// the frame bookkeeping is kept as plain records until result() flattens it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "kestrel/hal/frame_format.hpp"
#include "kestrel/host/board.hpp"
#include "kestrel/host/track_row.hpp"
#include "pipeline/stream_run_result.hpp"

namespace kestrel::sim {

template <class Tracker>
class StreamRun {
 public:
  using Report = typename Tracker::Report;
  using Sink = host::MemorySink<Report>;
  using Runner = host::BoardRunner<Tracker, Sink>;

  /// @param stream wire frames back to back.
  /// @param budget_ns a step longer than this is an overrun.
  StreamRun(Tracker& tracker, std::vector<std::uint8_t> stream, std::uint64_t budget_ns)
      : feed_(std::move(stream)),
        max_frames_(feed_.size_bytes() / kSmallestFrameBytes + 1),
        sink_(max_frames_ * Tracker::Table::kMaxTracks),
        runner_(feed_, clock_, tracker, hal::RadarAdapter{}, sink_, budget_ns) {
    records_.reserve(max_frames_);
  }

  /// Poll until the feed is exhausted. No allocation.
  void run_to_end() {
    for (;;) {
      const std::size_t first_report = sink_.size();
      const std::uint32_t steps_before = runner_.stats().steps;
      const Status status = runner_.poll_once();
      if (status == Status::kNoData) break;
      FrameRecord r;
      r.status = status;
      r.stepped = runner_.stats().steps != steps_before;
      r.step_ns = r.stepped ? runner_.stats().last_cycles : 0;
      // The frame's time is only known if it decoded.
      r.decoded = status_means_decoded(status);
      r.t_us = r.decoded ? runner_.last_frame().t_us : 0;
      r.first_report = first_report;
      r.end_report = sink_.size();
      records_.push_back(r);  // within the reserved capacity: a frame is at least kSmallestFrameBytes
    }
  }

  /// Flatten the run: per frame its status, step time and reports as rows.
  StreamRunResult result() const {
    StreamRunResult out;
    out.stats = runner_.stats();
    out.frames.reserve(records_.size());
    const std::span<const Report> reports = sink_.reports();
    for (const FrameRecord& r : records_) {
      FrameOutcome f;
      f.status = r.status;
      f.decoded = r.decoded;
      f.stepped = r.stepped;
      f.step_ns = r.step_ns;
      f.t_us = r.t_us;
      for (std::size_t i = r.first_report; i < r.end_report; ++i) f.tracks.push_back(host::to_track_row(reports[i]));
      out.frames.push_back(std::move(f));
    }
    return out;
  }

  const hal::RunnerStats& stats() const { return runner_.stats(); }

 private:
  static constexpr std::size_t kSmallestFrameBytes = hal::wire::frame_size(hal::FrameKind::kRadar, 0);

  struct FrameRecord {
    Status status = Status::kOk;
    bool decoded = false;
    bool stepped = false;
    std::uint64_t step_ns = 0;
    std::int64_t t_us = 0;
    std::size_t first_report = 0;
    std::size_t end_report = 0;
  };

  static bool status_means_decoded(Status s) {
    switch (s) {
      case Status::kBadMagic:
      case Status::kTruncated:
      case Status::kBadCrc:
      case Status::kUnsupportedVersion:
      case Status::kUnknownKind:
      case Status::kMalformedFrame:
        return false;
      default:
        return true;
    }
  }

  host::StreamFileFeed feed_;
  host::SteadyClock clock_;
  std::size_t max_frames_;
  Sink sink_;
  Runner runner_;
  std::vector<FrameRecord> records_;
};

/// Build, run and flatten in one call.
template <class Tracker>
StreamRunResult run_stream(Tracker& tracker, std::vector<std::uint8_t> stream, std::uint64_t budget_ns) {
  StreamRun<Tracker> run(tracker, std::move(stream), budget_ns);
  run.run_to_end();
  return run.result();
}

}  // namespace kestrel::sim
