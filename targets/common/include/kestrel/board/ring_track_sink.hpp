// SPDX-License-Identifier: Apache-2.0
// TrackSink of a microcontroller board: each track report becomes one KTRK
// record (ktrk_record.hpp) pushed whole into a transmit ring, which the
// board's UART interrupt drains; after each push the sink calls the board's
// kick function so the interrupt is on. publish() never waits: when the
// ring cannot take a whole record it returns kTableFull and drops the
// report (the runner counts it in publish_failures). A record is never
// split, so a consumer can always resynchronise on the magic.
//
// Used by targets/cortex-m4f (USART2) and targets/cortex-m7 (USART3).
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "kestrel/board/ktrk_record.hpp"
#include "kestrel/status.hpp"
#include "kestrel/tracking/track.hpp"

namespace kestrel::board {

/// @tparam Ring  a hal::ByteRingBuffer (main loop produces, ISR consumes).
/// @tparam kKick makes sure the transmit interrupt runs (e.g. sets TXEIE).
template <class Ring, void (*kKick)()>
class RingTrackSink {
 public:
  explicit RingTrackSink(Ring& ring) : ring_(ring) {}

  /// Queue one report for transmission.
  /// @return kOk (queued whole); kTableFull (the ring has no room for a
  ///         whole record; the report is dropped and counted).
  template <class Filter>
  [[nodiscard]] Status publish(const TrackReport<Filter>& report) {
    std::array<std::uint8_t, report_record::kSize> record;
    encode_track_record(report, std::span<std::uint8_t, report_record::kSize>(record));
    // Only this (main-loop) side adds bytes, so the free space can only grow
    // between this check and the push: the record goes in whole.
    if (ring_.capacity() - ring_.size() < record.size()) {
      ++dropped_;
      return Status::kTableFull;
    }
    (void)ring_.push(std::span<const std::uint8_t>(record));
    kKick();
    return Status::kOk;
  }

  /// Reports dropped because the ring was full.
  [[nodiscard]] std::uint32_t dropped() const { return dropped_; }

 private:
  Ring& ring_;
  std::uint32_t dropped_ = 0;
};

}  // namespace kestrel::board
