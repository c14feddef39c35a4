// SPDX-License-Identifier: Apache-2.0
// TrackSink of the Cortex-M4F board: each track report becomes one KTRK v2
// record (targets/common/include/kestrel/board/ktrk_record.hpp, the record
// every board emits) pushed whole into the USART2 transmit ring, which the
// TX interrupt drains. publish() never waits: when the ring cannot take a
// whole record it returns kTableFull and drops the report (the runner counts
// it in publish_failures); a record is never split, so a consumer can
// always resynchronise on the magic. The encoder and the ring sink are the
// shared ones of targets/common; this file binds them to USART2.
#pragma once

#include "kestrel/board/ktrk_record.hpp"
#include "kestrel/board/ring_track_sink.hpp"
#include "uart_feed.hpp"

namespace kestrel::m4f {

namespace report_record = board::report_record;
using board::encode_track_record;

/// TrackSink writing KTRK records into the USART2 transmit ring.
using UartTxSink = board::RingTrackSink<TxRing, usart2_kick_tx>;

}  // namespace kestrel::m4f
