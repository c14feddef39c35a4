// SPDX-License-Identifier: Apache-2.0
// StreamFileFeed: the host's MeasurementFeed (hal/feed.hpp). A stream file is
// wire frames back to back (frame_format.hpp), exactly the bytes a board's
// UART would receive. The whole stream is read into memory when the feed is
// built, so poll() does no I/O and no allocation: it decodes the next frame
// in place, like a board's feed decoding out of its receive buffer.
//
// Damaged input follows the decoder's resynchronisation rules, with one
// difference from a live link: the stream is complete, so a truncated frame
// at the end is reported once (kTruncated) and the rest dropped instead of
// waiting for bytes that will never come, and a run of garbage is skipped up
// to the next frame magic and reported once (kBadMagic), not once per byte.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "kestrel/hal/frame.hpp"
#include "kestrel/status.hpp"

namespace kestrel::host {

class StreamFileFeed {
 public:
  /// A feed over bytes already in memory (kestrel-sim builds streams this way).
  explicit StreamFileFeed(std::vector<std::uint8_t> bytes);

  /// Read a whole stream file. Throws std::runtime_error naming the file when
  /// it cannot be read (host only: boards never open files).
  static StreamFileFeed open(const std::filesystem::path& path);

  /// Decode the next frame into `frame`.
  /// @return kOk; kTooManyCandidates (frame holds its first capacity items);
  ///         kNoData at the end of the stream; otherwise the decode status of
  ///         a frame that was skipped (kBadCrc, kBadMagic, kTruncated,
  ///         kMalformedFrame, kUnsupportedVersion, kUnknownKind).
  [[nodiscard]] Status poll(hal::Frame& frame);

  /// True once every byte has been consumed.
  bool exhausted() const { return offset_ >= bytes_.size(); }
  /// Bytes consumed so far.
  std::size_t offset() const { return offset_; }
  std::size_t size_bytes() const { return bytes_.size(); }

 private:
  std::size_t next_magic_after(std::size_t from) const;

  std::vector<std::uint8_t> bytes_;
  std::size_t offset_ = 0;
};

}  // namespace kestrel::host
