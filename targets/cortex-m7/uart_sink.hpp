// SPDX-License-Identifier: Apache-2.0
// TrackSink of the Cortex-M7 board: KTRK v2 records
// (targets/common/include/kestrel/board/ktrk_record.hpp, the record every
// board emits) pushed whole into the USART3 transmit ring, drained by the TX
// interrupt. publish() never waits (kTableFull when the ring lacks room for
// a whole record; the runner counts publish_failures).
#pragma once

#include "kestrel/board/ring_track_sink.hpp"
#include "uart_feed.hpp"

namespace kestrel::m7 {

using UartTxSink = board::RingTrackSink<TxRing, usart3_kick_tx>;

}  // namespace kestrel::m7
