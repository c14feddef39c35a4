// SPDX-License-Identifier: Apache-2.0
// TrackSink of the Cortex-M7 board: KTRK v2 records
// (targets/common/include/kestrel/board/ktrk_record.hpp, the record every
// board emits) pushed whole into the USART3 transmit ring, drained by the TX
// interrupt. publish() never waits (kTableFull when the ring lacks room for
// a whole record; the runner counts publish_failures).
//
// UartCat062Sink: the same ring, but each report as an ASTERIX CAT062 data
// block (hal/asterix_cat062_sink.hpp) with this board's SAC/SIC; chosen in
// board.hpp when KESTREL_BOARD_SINK_CAT062 is defined (kestrel-m7-cat062.elf).
#pragma once

#include "board_config.hpp"
#include "kestrel/board/ring_track_sink.hpp"
#include "kestrel/board/ring_tx.hpp"
#include "kestrel/hal/asterix_cat062_sink.hpp"
#include "uart_feed.hpp"

namespace kestrel::m7 {

using UartTxSink = board::RingTrackSink<TxRing, usart3_kick_tx>;

using UartTx = board::RingTx<TxRing, usart3_kick_tx>;

/// TrackSink writing one CAT062 data block per report into the USART3
/// transmit ring (kTableFull when the ring lacks room for a whole block;
/// kOutOfRange/kNonFinite for a report CAT062 cannot carry, such as a frame
/// time that is not a time of day). Both are counted in publish_failures.
class UartCat062Sink : public hal::asterix::Cat062Sink<UartTx> {
 public:
  explicit UartCat062Sink(TxRing& ring)
      : Cat062Sink(UartTx(ring), hal::asterix::Cat062Source{kAsterixSac, kAsterixSic, false, 0}) {}
};

}  // namespace kestrel::m7
