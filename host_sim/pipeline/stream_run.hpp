// SPDX-License-Identifier: Apache-2.0
// One run of a tracker over a byte stream, driven exactly as a board drives
// it: host::StreamFileFeed (or host::AsterixFileFeed for a CAT048
// recording) -> hal::RadarAdapter -> Tracker::step -> host::MemorySink
// (and, when asked, hal::asterix::Cat062Sink), inside hal::Runner and timed
// by host::SteadyClock (targets/host/board.hpp). Everything the loop touches
// is sized in the constructor, so run_to_end() makes no allocation (tests
// assert it), and the frame bookkeeping is kept as plain records until
// result() flattens it. For a filter with mode probabilities (the IMM) each
// report's are read from the track table after the step, outside the timed
// call.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "kestrel/hal/asterix_cat062_sink.hpp"
#include "kestrel/hal/frame_format.hpp"
#include "kestrel/host/board.hpp"
#include "kestrel/host/track_row.hpp"
#include "pipeline/poll_frames.hpp"
#include "pipeline/stream_run_result.hpp"

namespace kestrel::sim {

/// A hal::asterix::ByteTx into a buffer whose capacity is fixed when it is
/// built: write() never allocates, and refuses (kTableFull) what would not fit.
class BoundedByteTx {
 public:
  explicit BoundedByteTx(std::size_t capacity) { bytes_.reserve(capacity); }
  [[nodiscard]] Status write(std::span<const std::uint8_t> b) {
    if (bytes_.capacity() - bytes_.size() < b.size()) return Status::kTableFull;
    bytes_.insert(bytes_.end(), b.begin(), b.end());
    return Status::kOk;
  }
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }

 private:
  std::vector<std::uint8_t> bytes_;
};

/// The sink of a kestrel-sim run: every report into memory for scoring and,
/// when a CAT062 source is given, also through a Cat062Sink. Its status is
/// the memory sink's: a report CAT062 cannot carry is counted by the
/// Cat062Sink, not refused to the Runner, so scoring sees every report.
template <class Report>
class ReplaySink {
 public:
  using Cat062 = hal::asterix::Cat062Sink<BoundedByteTx>;

  ReplaySink(std::size_t capacity, std::optional<hal::asterix::Cat062Source> cat062)
      : memory_(capacity),
        cat062_(BoundedByteTx(cat062.has_value() ? capacity * Cat062::kMaxBlockBytes : 0),
                cat062.value_or(hal::asterix::Cat062Source{})),
        cat062_on_(cat062.has_value()) {}

  [[nodiscard]] Status publish(const Report& report) {
    const Status s = memory_.publish(report);
    if (cat062_on_) (void)cat062_.publish(report);  // counted in cat062().counters()
    return s;
  }

  std::span<const Report> reports() const { return memory_.reports(); }
  std::size_t size() const { return memory_.size(); }
  const Cat062& cat062() const { return cat062_; }

 private:
  host::MemorySink<Report> memory_;
  Cat062 cat062_;
  bool cat062_on_;
};

/// Filter::kModes for a filter with mode probabilities, else 0.
template <class Filter>
constexpr std::size_t mode_count() {
  if constexpr (requires(const Filter& f) { f.mode_probabilities(); }) {
    return static_cast<std::size_t>(Filter::kModes);
  } else {
    return 0;
  }
}

template <class Tracker, class Feed = host::StreamFileFeed>
class StreamRun {
 public:
  using Report = typename Tracker::Report;
  using Sink = ReplaySink<Report>;
  using Runner = host::BoardRunnerOver<Feed, Tracker, Sink>;
  using Filter = decltype(Tracker::TrackT::filter);
  static constexpr bool kHasModes = requires(const Filter& f) { f.mode_probabilities(); };

  /// @param stream wire frames back to back (Feed = StreamFileFeed) or
  ///        CAT048 data blocks back to back (Feed = AsterixFileFeed).
  /// @param budget_ns a step longer than this is an overrun.
  /// @param cat062 when set, also write every report as CAT062 with this source.
  StreamRun(Tracker& tracker, std::vector<std::uint8_t> stream, std::uint64_t budget_ns,
            std::optional<hal::asterix::Cat062Source> cat062 = std::nullopt)
      : max_frames_(max_frames_of(stream)),
        max_polls_(std::is_same_v<Feed, host::AsterixFileFeed> ? max_frames_ : stream.size() + 1),
        feed_(std::move(stream)),
        sink_(max_frames_ * Tracker::Table::kMaxTracks, cat062),
        runner_(feed_, clock_, tracker, hal::RadarAdapter{}, sink_, budget_ns),
        tracker_(&tracker) {
    records_.reserve(max_frames_);
    if constexpr (kHasModes) modes_.reserve(max_frames_ * Tracker::Table::kMaxTracks);
  }

  /// Poll until the feed is exhausted. No allocation.
  void run_to_end() {
    poll_frames(runner_, sink_, max_polls_, [this](const PolledFrame& polled) {
      FrameRecord r;
      r.polled = polled;
      // The frame's time is only known if it decoded.
      r.decoded = status_means_decoded(polled.status);
      r.t_us = r.decoded ? runner_.last_frame().t_us : 0;
      records_.push_back(r);  // within the reserved capacity unless garbage splits the stream finer
      if constexpr (kHasModes) record_modes(polled.first_report, polled.end_report);
    });
  }

  /// Flatten the run: per frame its status, step time and reports as rows.
  StreamRunResult result() const {
    StreamRunResult out;
    out.stats = runner_.stats();
    out.cat062 = sink_.cat062().tx().bytes();
    out.cat062_refused = sink_.cat062().counters().refused + sink_.cat062().counters().tx_dropped;
    if constexpr (std::is_same_v<Feed, host::AsterixFileFeed>) out.asterix = feed_.counters();
    out.frames.reserve(records_.size());
    const std::span<const Report> reports = sink_.reports();
    for (const FrameRecord& r : records_) {
      const PolledFrame& p = r.polled;
      FrameOutcome f;
      f.status = p.status;
      f.decoded = r.decoded;
      f.stepped = p.stepped;
      f.step_ns = p.step_ns;
      f.t_us = r.t_us;
      for (std::size_t i = p.first_report; i < p.end_report; ++i) f.tracks.push_back(host::to_track_row(reports[i]));
      if constexpr (kHasModes) {
        for (std::size_t i = p.first_report; i < p.end_report; ++i) {
          f.mode_probabilities.emplace_back(modes_[i].begin(), modes_[i].end());
        }
      }
      out.frames.push_back(std::move(f));
    }
    return out;
  }

  const hal::RunnerStats& stats() const { return runner_.stats(); }

 private:
  static constexpr std::size_t kSmallestFrameBytes = hal::wire::frame_size(hal::FrameKind::kRadar, 0);

  // Polls that can return something other than kNoData, as reserved for:
  // for a wire stream one per smallest frame (garbage between frames can
  // make more: each poll then consumes at least a byte, the loop's bound);
  // for a CAT048 recording counted by a dry run of the same feed, exact
  // (a record can be 10 bytes, so a bound from the size alone would
  // reserve far more than a long recording needs).
  static std::size_t max_frames_of(const std::vector<std::uint8_t>& stream) {
    if constexpr (std::is_same_v<Feed, host::AsterixFileFeed>) {
      host::AsterixFileFeed dry(stream);
      hal::Frame frame{};
      std::size_t n = 0;
      while (dry.poll(frame) != Status::kNoData) ++n;
      return n + 1;
    } else {
      return stream.size() / kSmallestFrameBytes + 1;
    }
  }

  struct FrameRecord {
    PolledFrame polled;
    bool decoded = false;
    std::int64_t t_us = 0;
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

  static constexpr std::size_t kModes = mode_count<Filter>();
  using ModeProbabilities = std::array<double, kModes>;

  /// The mode probabilities of the tracks of reports [first, end), by id;
  /// NaN for a report whose track is no longer in the table.
  void record_modes(std::size_t first, std::size_t end) {
    const std::span<const Report> reports = sink_.reports();
    const auto& table = tracker_->tracks();
    for (std::size_t i = first; i < end; ++i) {
      ModeProbabilities mu;
      mu.fill(std::numeric_limits<double>::quiet_NaN());
      for (std::size_t slot = 0; slot < Tracker::Table::kMaxTracks; ++slot) {
        if (!table.active(slot) || table[slot].id != reports[i].track_id) continue;
        const auto& m = table[slot].filter.mode_probabilities();
        for (std::size_t j = 0; j < kModes; ++j) {
          mu[j] = ScalarTraits<typename Filter::Scalar>::to_double(m(static_cast<int>(j)));
        }
        break;
      }
      modes_.push_back(mu);  // within the reserved capacity: one per report
    }
  }

  std::size_t max_frames_;
  std::size_t max_polls_;
  Feed feed_;
  host::SteadyClock clock_;
  Sink sink_;
  Runner runner_;
  std::vector<FrameRecord> records_;
  const Tracker* tracker_;
  std::vector<ModeProbabilities> modes_;  ///< One per report, in report order (filters with modes).
};

/// Build, run and flatten in one call, with the feed `input.format` names.
template <class Tracker>
StreamRunResult run_stream(Tracker& tracker, StreamInput input, std::uint64_t budget_ns) {
  if (input.format == StreamFormat::kAsterixCat048) {
    StreamRun<Tracker, host::AsterixFileFeed> run(tracker, std::move(input.bytes), budget_ns, input.cat062);
    run.run_to_end();
    return run.result();
  }
  StreamRun<Tracker> run(tracker, std::move(input.bytes), budget_ns, input.cat062);
  run.run_to_end();
  return run.result();
}

}  // namespace kestrel::sim
