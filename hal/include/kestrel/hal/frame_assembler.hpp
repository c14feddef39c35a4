// SPDX-License-Identifier: Apache-2.0
// Turns a byte stream into frames: bytes arrive in arbitrary pieces (a UART
// ring buffer on a board, file reads on the host), collect in a fixed linear
// buffer, and next() decodes the frame at its front. Garbage is skipped by
// scanning for the magic, a frame that fails its CRC or content checks is
// skipped whole, and every outcome is counted for diagnostics. Both the
// board's UART feed and the host's stream-file feed are built on this, so a
// host replay sees exactly what a board would. Rules: docs/wire_format.md.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "kestrel/hal/frame.hpp"
#include "kestrel/hal/frame_codec.hpp"
#include "kestrel/hal/frame_format.hpp"
#include "kestrel/hal/ring_buffer.hpp"
#include "kestrel/status.hpp"

namespace kestrel::hal {

/// @tparam kBufferBytes linear buffer size; at least wire::kMaxFrameBytes so
///         any frame the decoder accepts fits whole.
template <std::size_t kBufferBytes = wire::kMaxFrameBytes>
class FrameAssembler {
  static_assert(kBufferBytes >= wire::kMaxFrameBytes,
                "FrameAssembler: the buffer must hold the largest frame the decoder accepts");

 public:
  /// Append bytes from the stream. Takes as many as fit; after next() has
  /// returned kNoData there is room for at least one more byte, so a caller
  /// that alternates push() and draining next() always makes progress.
  /// @return number of bytes taken from the front of `bytes`.
  [[nodiscard]] std::size_t push(std::span<const std::uint8_t> bytes) {
    make_room(bytes.size());
    const std::size_t n = std::min(bytes.size(), kBufferBytes - end_);
    std::copy_n(bytes.begin(), n, buf_.begin() + static_cast<std::ptrdiff_t>(end_));
    end_ += n;
    return n;
  }

  /// Move as many bytes from `ring` as fit (consumer side of the ring).
  /// @return number of bytes moved.
  template <std::size_t kRingCapacity>
  std::size_t pull(ByteRingBuffer<kRingCapacity>& ring) {
    make_room(ring.size());
    const std::size_t n = ring.pop(std::span<std::uint8_t>(buf_).subspan(end_));
    end_ += n;
    return n;
  }

  /// Decode the next frame from the buffered bytes. Work per call is one
  /// decode plus at most one scan of the buffer.
  /// @param out filled on kOk and kTooManyCandidates, untouched otherwise.
  /// @return kOk (a frame); kNoData (no complete frame buffered yet);
  ///         kTooManyCandidates (a frame over its kind's capacity: `out`
  ///         holds its first capacity items and is usable); or the decode
  ///         status of bytes it dropped and has already skipped:
  ///         kBadMagic (garbage up to the next possible magic),
  ///         kMalformedFrame, kUnsupportedVersion, kUnknownKind, kBadCrc
  ///         (the whole frame; kMalformedFrame for an impossible
  ///         payload_len skips one byte and resyncs). Never kTruncated.
  [[nodiscard]] Status next(Frame& out) {
    if (begin_ == end_) return Status::kNoData;
    std::size_t consumed = 0;
    const Status s = decode(buffered_bytes(), out, consumed);
    if (s == Status::kTruncated) return Status::kNoData;
    if (s == Status::kBadMagic) {
      // Skip this byte and every following one that cannot start a frame.
      std::size_t p = begin_ + 1;
      while (p < end_ && !could_start_frame(p)) ++p;
      skipped_bytes_ += static_cast<std::uint32_t>(p - begin_);
      begin_ = p;
    } else {
      begin_ += consumed;
    }
    if (begin_ == end_) begin_ = end_ = 0;
    ++counts_[static_cast<std::size_t>(s)];
    return s;
  }

  /// Bytes buffered and not yet decoded or skipped.
  [[nodiscard]] std::size_t buffered() const { return end_ - begin_; }

  /// How many times next() returned `s` (kNoData is not counted).
  [[nodiscard]] std::uint32_t count(Status s) const { return counts_[static_cast<std::size_t>(s)]; }

  /// Bytes dropped while hunting for a magic (the kBadMagic runs).
  [[nodiscard]] std::uint32_t skipped_bytes() const { return skipped_bytes_; }

  /// Forget the buffered bytes (e.g. after a link reset); counters are kept.
  void clear() { begin_ = end_ = 0; }

 private:
  [[nodiscard]] std::span<const std::uint8_t> buffered_bytes() const {
    return std::span<const std::uint8_t>(buf_).subspan(begin_, end_ - begin_);
  }

  // Could a frame start at buf_[p]? True when the buffered bytes from p match
  // the magic for as far as they go.
  [[nodiscard]] bool could_start_frame(std::size_t p) const {
    for (std::size_t i = 0; i < 4 && p + i < end_; ++i) {
      if (buf_[p + i] != static_cast<std::uint8_t>((wire::kMagic >> (8 * i)) & 0xFFu)) return false;
    }
    return true;
  }

  // Move the buffered bytes to the front when `wanted` more would not fit
  // behind them.
  void make_room(std::size_t wanted) {
    if (begin_ == 0 || kBufferBytes - end_ >= wanted) return;
    const std::size_t n = end_ - begin_;
    std::copy_n(buf_.begin() + static_cast<std::ptrdiff_t>(begin_), n, buf_.begin());
    begin_ = 0;
    end_ = n;
  }

  std::array<std::uint8_t, kBufferBytes> buf_{};
  std::size_t begin_ = 0;  ///< First buffered byte.
  std::size_t end_ = 0;    ///< One past the last buffered byte.
  std::array<std::uint32_t, kStatusCount> counts_{};
  std::uint32_t skipped_bytes_ = 0;
};

}  // namespace kestrel::hal
