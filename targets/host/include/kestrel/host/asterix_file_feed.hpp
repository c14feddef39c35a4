// SPDX-License-Identifier: Apache-2.0
// AsterixFileFeed: a host MeasurementFeed (hal/feed.hpp) over a recording of
// ASTERIX CAT048 data blocks back to back (the common .ast form: no
// per-block timestamps or framing, exactly the bytes a radar sends). Each
// poll() returns the next frame the hal CAT048 reader makes of the current
// block (docs/asterix.md, "Grouping rule"), so the board loop behind it is
// the same as behind a wire stream. The whole file is read into memory when
// the feed is built; poll() does no I/O and no allocation.
//
// A recording is complete, so the reader's "wait for more bytes" cases end
// it: a block cut short at the end is reported once (kTruncated) and a
// block whose LEN is below 3 (its end cannot be known, so no block after it
// can be found) is reported once (kMalformedFrame) and the rest dropped. A
// block of another category is skipped by its LEN (kUnknownKind, once per
// block); a malformed record drops the rest of its block (kMalformedFrame).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "kestrel/hal/asterix_cat048.hpp"
#include "kestrel/hal/frame.hpp"
#include "kestrel/status.hpp"

namespace kestrel::host {

/// What the feed did with the recording's blocks, beside the reader's own
/// counters (records, plots, records without a plot, plots over capacity).
struct AsterixFeedCounters {
  std::uint32_t blocks = 0;            ///< CAT048 blocks opened.
  std::uint32_t unknown_category = 0;  ///< Blocks of another category, skipped.
  std::uint32_t malformed = 0;         ///< Malformed records or block headers (rest of block or file dropped).
  std::uint32_t truncated = 0;         ///< A block cut short at the end of the file (0 or 1).
  std::uint32_t frames = 0;            ///< Frames returned (kOk or kTooManyCandidates).
};

class AsterixFileFeed {
 public:
  /// A feed over bytes already in memory.
  explicit AsterixFileFeed(std::vector<std::uint8_t> bytes);

  /// Read a whole recording. Throws std::runtime_error naming the file when
  /// it cannot be read (host only).
  static AsterixFileFeed open(const std::filesystem::path& path);

  /// The next frame of the recording.
  /// @return kOk; kTooManyCandidates (the frame holds the first
  ///         kMaxRadarPlots plots of its group); kNoData at the end; or the
  ///         status of bytes that were dropped: kUnknownKind (a block of
  ///         another category), kMalformedFrame, kTruncated.
  [[nodiscard]] Status poll(hal::Frame& frame);

  bool exhausted() const { return offset_ >= bytes_.size() && !block_open_; }
  std::size_t size_bytes() const { return bytes_.size(); }
  const AsterixFeedCounters& counters() const { return counters_; }
  const hal::asterix::Cat048Counters& reader_counters() const { return reader_.counters(); }

 private:
  std::vector<std::uint8_t> bytes_;
  std::size_t offset_ = 0;   ///< Start of the next block.
  bool block_open_ = false;  ///< The reader holds an open block.
  hal::asterix::Cat048Reader reader_;
  AsterixFeedCounters counters_{};
};

}  // namespace kestrel::host
