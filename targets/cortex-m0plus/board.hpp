// SPDX-License-Identifier: Apache-2.0
// The Cortex-M0+ board's choice of a concrete type for every HAL concept and
// the tracker it runs: the EKF-CA radar tracker on the Q31.32 fixed-point
// scalar (docs/fixed-point.md), integer arithmetic only, so the
// image links no soft-float double routines and no libm (checked after each
// link, CMakeLists.txt) and computes the same bits as a host replay:
//
//   MeasurementFeed -> UartRingFeed      (UART0 RX ring -> FrameAssembler)
//   CycleClock      -> SysTickCycleClock (SysTick + wrap count, 64 bits)
//   TrackSink       -> UartTxSink        (KTRK records -> UART0 TX ring)
//   Tracker         -> EKF-CA radar tracker in Q31.32, kMaxTracks x kMaxPlots
#pragma once

#include "board_config.hpp"
#include "kestrel/hal/clock.hpp"
#include "kestrel/hal/feed.hpp"
#include "kestrel/hal/radar_adapter.hpp"
#include "kestrel/hal/runner.hpp"
#include "kestrel/hal/sink.hpp"
#include "kestrel/scalar/fixed_point_eigen.hpp"
#include "kestrel/tracking/radar_tracker.hpp"
#include "system.hpp"
#include "systick_cycle_clock.hpp"
#include "uart_feed.hpp"
#include "uart_sink.hpp"

namespace kestrel::m0plus {

using Feed = UartRingFeed;
using Clock = SysTickCycleClock;
using Sink = UartTxSink;
using Scalar = Q31_32;
using Tracker = RadarTracker<EkfCa<Scalar>, kMaxTracks, kMaxPlots>;
using Adapter = hal::RadarAdapter;
using Runner = hal::Runner<Feed, Clock, Tracker, Adapter, Sink>;

static_assert(hal::MeasurementFeed<Feed>);
static_assert(hal::CycleClock<Clock>);
static_assert(hal::TrackSink<Sink, Tracker::Report>);

}  // namespace kestrel::m0plus
