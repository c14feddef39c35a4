// SPDX-License-Identifier: Apache-2.0
// A hal::asterix::ByteTx (hal/asterix_cat062_sink.hpp) over a board's
// transmit ring: write() pushes a run of bytes whole, or returns kTableFull
// and pushes nothing, then calls the board's kick function so the UART
// interrupt drains the ring. The same never-split rule as RingTrackSink, so
// a consumer reading ASTERIX data blocks off the wire never sees half a block.
#pragma once

#include <cstdint>
#include <span>

#include "kestrel/status.hpp"

namespace kestrel::board {

/// @tparam Ring  a hal::ByteRingBuffer (main loop produces, ISR consumes).
/// @tparam kKick makes sure the transmit interrupt runs (e.g. sets TXEIE).
template <class Ring, void (*kKick)()>
class RingTx {
 public:
  RingTx(Ring& ring) : ring_(&ring) {}  // NOLINT(google-explicit-constructor): a board builds its sink from its ring

  /// @return kOk (queued whole); kTableFull (no room for all of it; nothing queued).
  [[nodiscard]] Status write(std::span<const std::uint8_t> bytes) {
    // Only this (main-loop) side adds bytes, so the free space can only grow
    // between this check and the push.
    if (ring_->capacity() - ring_->size() < bytes.size()) return Status::kTableFull;
    (void)ring_->push(bytes);
    kKick();
    return Status::kOk;
  }

 private:
  Ring* ring_;
};

}  // namespace kestrel::board
