// SPDX-License-Identifier: Apache-2.0
// TrackSink of the Cortex-M0+ board: KTRK v2 records (targets/common) pushed
// whole into the UART0 transmit ring, drained by the UART0 interrupt.
#pragma once

#include "kestrel/board/ring_track_sink.hpp"
#include "uart_feed.hpp"

namespace kestrel::m0plus {

using UartTxSink = board::RingTrackSink<TxRing, uart0_kick_tx>;

}  // namespace kestrel::m0plus
