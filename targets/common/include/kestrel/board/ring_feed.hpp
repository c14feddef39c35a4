// SPDX-License-Identifier: Apache-2.0
// MeasurementFeed over a receive ring that a UART interrupt fills: bytes ->
// hal::FrameAssembler -> frames, so a board sees exactly what a host replay
// of the same bytes sees. Never blocks: an empty ring gives kNoData; bytes
// the ring lost (full) are counted by the ring, the frame's CRC then fails
// and the assembler resynchronises on the next magic.
//
// Used by targets/cortex-m4f (USART2) and targets/cortex-m7 (USART3).
#pragma once

#include <cstddef>

#include "kestrel/hal/frame.hpp"
#include "kestrel/hal/frame_assembler.hpp"
#include "kestrel/status.hpp"

namespace kestrel::board {

/// @tparam Ring            a hal::ByteRingBuffer (ISR produces, main loop consumes).
/// @tparam kAssemblerBytes the assembler's linear buffer (>= wire::kMaxFrameBytes).
template <class Ring, std::size_t kAssemblerBytes>
class RingFeed {
 public:
  explicit RingFeed(Ring& ring) : ring_(ring) {}

  /// Return the next frame, never blocking. Work per call: at most two
  /// decode attempts and one copy of the ring's contents.
  /// @return kOk (frame filled); kNoData (no complete frame yet);
  ///         kTooManyCandidates (frame filled with its first capacity
  ///         items); or the status of bytes the assembler dropped: kBadMagic,
  ///         kMalformedFrame, kUnsupportedVersion, kUnknownKind, kBadCrc.
  [[nodiscard]] Status poll(hal::Frame& frame) {
    // Drain what is already assembled first, so a burst of frames is handed
    // out one per call without touching the ring.
    const Status buffered = assembler_.next(frame);
    if (buffered != Status::kNoData) return buffered;
    if (assembler_.pull(ring_) == 0) return Status::kNoData;
    return assembler_.next(frame);
  }

  /// The assembler's per-status counters and skipped-byte count.
  const hal::FrameAssembler<kAssemblerBytes>& assembler() const { return assembler_; }

 private:
  Ring& ring_;
  hal::FrameAssembler<kAssemblerBytes> assembler_{};
};

}  // namespace kestrel::board
