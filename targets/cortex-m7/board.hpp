// The Cortex-M7 board's choice of a concrete type for every HAL concept
// (STYLE "Top-level layout": board.hpp binds each concept), and the tracker
// this board runs. Everything is resolved at compile time; the runner calls
// these types directly, with no virtual dispatch.
//
//   MeasurementFeed -> UartRingFeed  (USART3 RX ring -> FrameAssembler)
//   CycleClock      -> DwtCycleClock (DWT CYCCNT at 400 MHz, extended to 64 bits)
//   TrackSink       -> UartTxSink    (KTRK records -> USART3 TX ring)
//   Tracker         -> EKF-CA radar tracker in double (FPv5-D16 does double
//                      in hardware), kMaxTracks x kMaxPlots
#pragma once

#include "board_config.hpp"
#include "kestrel/board/dwt_cycle_clock.hpp"
#include "kestrel/hal/clock.hpp"
#include "kestrel/hal/feed.hpp"
#include "kestrel/hal/radar_adapter.hpp"
#include "kestrel/hal/runner.hpp"
#include "kestrel/hal/sink.hpp"
#include "kestrel/tracking/radar_tracker.hpp"
#include "system.hpp"
#include "uart_feed.hpp"
#include "uart_sink.hpp"

namespace kestrel::m7 {

using Feed = UartRingFeed;
using Clock = board::DwtCycleClock<kCoreClockHz>;
using Sink = UartTxSink;
using Tracker = RadarTracker<EkfCa<double>, kMaxTracks, kMaxPlots>;
using Adapter = hal::RadarAdapter;
using Runner = hal::Runner<Feed, Clock, Tracker, Adapter, Sink>;

static_assert(hal::MeasurementFeed<Feed>);
static_assert(hal::CycleClock<Clock>);
static_assert(hal::TrackSink<Sink, Tracker::Report>);
static_assert(Tracker::Scan::kMaxMeasurements <= hal::kMaxRadarPlots,
              "the scan should not be larger than a radar frame can fill");

}  // namespace kestrel::m7
