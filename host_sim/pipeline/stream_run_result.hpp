// SPDX-License-Identifier: Apache-2.0
// What one run of a tracker over a stream produced, independent of the
// filter type: per frame the Runner's status, the step time and the
// published reports flattened to host::TrackRow. StreamInput says what the
// run reads (a wire stream or a CAT048 recording) and whether it also writes
// its reports as CAT062.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "kestrel/hal/asterix_cat062.hpp"
#include "kestrel/hal/runner.hpp"
#include "kestrel/host/asterix_file_feed.hpp"
#include "kestrel/host/track_row.hpp"
#include "kestrel/status.hpp"

namespace kestrel::sim {

/// Byte format of a run's input.
enum class StreamFormat : std::uint8_t {
  kWire,           ///< Wire frames back to back (host::StreamFileFeed).
  kAsterixCat048,  ///< ASTERIX CAT048 data blocks back to back (host::AsterixFileFeed).
};

/// What a run reads, and what it writes beside its reports.
struct StreamInput {
  /// A wire stream: what every caller passed before ASTERIX input existed.
  StreamInput(std::vector<std::uint8_t> stream) : bytes(std::move(stream)) {}  // NOLINT(google-explicit-constructor)
  StreamInput(std::vector<std::uint8_t> stream, StreamFormat f) : bytes(std::move(stream)), format(f) {}

  std::vector<std::uint8_t> bytes;
  StreamFormat format = StreamFormat::kWire;
  /// When set, every published report is also written as a CAT062 data
  /// block with this source (hal::asterix::Cat062Sink), into
  /// StreamRunResult::cat062.
  std::optional<hal::asterix::Cat062Source> cat062;
};

struct FrameOutcome {
  Status status = Status::kOk;   ///< Runner::poll_once() result for this frame.
  bool decoded = false;          ///< The frame decoded (t_us is valid).
  bool stepped = false;          ///< It reached Tracker::step (step_ns is valid).
  std::uint64_t step_ns = 0;     ///< Convert + step time, ns (SteadyClock).
  std::int64_t t_us = 0;         ///< Frame time, us.
  std::vector<host::TrackRow> tracks;  ///< Reports published for this frame.
  /// For a filter with mode probabilities (the IMM), those of each reported
  /// track after this frame, parallel to `tracks`, in the filter's mode
  /// order; empty for other filters.
  std::vector<std::vector<double>> mode_probabilities;
};

struct StreamRunResult {
  std::vector<FrameOutcome> frames;  ///< In stream order.
  hal::RunnerStats stats;            ///< The Runner's own accounting.
  std::vector<std::uint8_t> cat062;  ///< CAT062 blocks of every report, when StreamInput::cat062 asked.
  std::uint32_t cat062_refused = 0;  ///< Reports not written: CAT062 cannot carry them, or the buffer was full.
  std::optional<host::AsterixFeedCounters> asterix;  ///< What the CAT048 feed found (ASTERIX input only).
  /// Names of the modes of FrameOutcome::mode_probabilities ("cv", ...),
  /// set by the filter's run function; empty without modes.
  std::vector<std::string> mode_names;
};

}  // namespace kestrel::sim
