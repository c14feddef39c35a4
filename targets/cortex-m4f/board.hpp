// SPDX-License-Identifier: Apache-2.0
// The Cortex-M4F board's choice of a concrete type for every HAL concept
// (docs/porting.md: board.hpp binds each concept), and the tracker
// this board runs. Everything is resolved at compile time; the runner calls
// these types directly, with no virtual dispatch.
//
//   MeasurementFeed -> UartRingFeed  (USART2 RX ring -> FrameAssembler)
//   CycleClock      -> DwtCycleClock (DWT CYCCNT extended to 64 bits)
//   TrackSink       -> UartTxSink    (KTRK records -> USART2 TX ring)
//   Tracker         -> EKF-CA radar tracker in float, kMaxTracks x kMaxPlots
#pragma once

#include "board_config.hpp"
#include "dwt_cycle_clock.hpp"
#include "kestrel/hal/clock.hpp"
#include "kestrel/hal/feed.hpp"
#include "kestrel/hal/radar_adapter.hpp"
#include "kestrel/hal/runner.hpp"
#include "kestrel/hal/sink.hpp"
#include "kestrel/tracking/radar_tracker.hpp"
#include "system.hpp"
#include "uart_feed.hpp"
#include "uart_sink.hpp"

namespace kestrel::m4f {

using Feed = UartRingFeed;
using Clock = DwtCycleClock;
using Sink = UartTxSink;
// P checked at every predict: the once-per-frame check is faster but puts
// this image over 16 KiB (docs/performance.md, "Once per frame").
using TrackFilter = EkfCaCheckedEachPredict<float>;
using Tracker = RadarTracker<TrackFilter, kMaxTracks, kMaxPlots>;
using Adapter = hal::RadarAdapter;
using Runner = hal::Runner<Feed, Clock, Tracker, Adapter, Sink>;

static_assert(hal::MeasurementFeed<Feed>);
static_assert(hal::CycleClock<Clock>);
static_assert(hal::TrackSink<Sink, Tracker::Report>);
static_assert(Tracker::Scan::kMaxMeasurements <= hal::kMaxRadarPlots,
              "the scan should not be larger than a radar frame can fill");

}  // namespace kestrel::m4f
