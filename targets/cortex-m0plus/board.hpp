// The Cortex-M0+ board's choice of a concrete type for every HAL concept and
// the tracker it runs (float soft-float until the fixed-point scalar of
// issue 8 takes over this board):
//
//   MeasurementFeed -> UartRingFeed      (UART0 RX ring -> FrameAssembler)
//   CycleClock      -> SysTickCycleClock (SysTick + wrap count, 64 bits)
//   TrackSink       -> UartTxSink        (KTRK records -> UART0 TX ring)
//   Tracker         -> EKF-CA radar tracker in float, kMaxTracks x kMaxPlots
#pragma once

#include "board_config.hpp"
#include "kestrel/hal/clock.hpp"
#include "kestrel/hal/feed.hpp"
#include "kestrel/hal/radar_adapter.hpp"
#include "kestrel/hal/runner.hpp"
#include "kestrel/hal/sink.hpp"
#include "kestrel/tracking/radar_tracker.hpp"
#include "system.hpp"
#include "systick_cycle_clock.hpp"
#include "uart_feed.hpp"
#include "uart_sink.hpp"

namespace kestrel::m0plus {

using Feed = UartRingFeed;
using Clock = SysTickCycleClock;
using Sink = UartTxSink;
using Tracker = RadarTracker<EkfCa<float>, kMaxTracks, kMaxPlots>;
using Adapter = hal::RadarAdapter;
using Runner = hal::Runner<Feed, Clock, Tracker, Adapter, Sink>;

static_assert(hal::MeasurementFeed<Feed>);
static_assert(hal::CycleClock<Clock>);
static_assert(hal::TrackSink<Sink, Tracker::Report>);

}  // namespace kestrel::m0plus
