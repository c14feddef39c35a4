// SPDX-License-Identifier: Apache-2.0
// The Cortex-M7 board's choice of a concrete type for every HAL concept and
// of the sensor chain (adapter + tracker) it runs, all resolved at compile
// time with no virtual dispatch (docs/porting.md, "board.hpp: binding the
// HAL concepts" and "Cortex-M7"):
//   MeasurementFeed -> UartRingFeed  (USART3 RX ring -> FrameAssembler)
//   CycleClock      -> DwtCycleClock (DWT CYCCNT, extended to 64 bits)
//   TrackSink       -> UartTxSink (KTRK v2 records), or UartCat062Sink (one
//                      ASTERIX CAT062 block per report) with
//                      KESTREL_BOARD_SINK_CAT062 (kestrel-m7-cat062.elf)
//   Adapter/Tracker -> in double (FPv5-D16): RadarAdapter + EKF-CA radar
//                      tracker (kestrel-m7.elf), or with
//                      KESTREL_BOARD_SENSOR_PCL PclAdapter + the PCL KF on
//                      [Rb, dRb] with PCL-002 parameters (kestrel-m7-pcl.elf).
// main.cpp only calls make_tracker() and make_adapter(), so it is the same
// for every image built from this folder.
#pragma once

#include "board_config.hpp"
#include "kestrel/board/dwt_cycle_clock.hpp"
#include "kestrel/hal/clock.hpp"
#include "kestrel/hal/feed.hpp"
#include "kestrel/hal/runner.hpp"
#include "kestrel/hal/sink.hpp"
#include "system.hpp"
#include "uart_feed.hpp"
#include "uart_sink.hpp"

#if defined(KESTREL_BOARD_SENSOR_PCL)
#include "kestrel/hal/pcl_adapter.hpp"
#include "kestrel/tracking/pcl_tracker.hpp"
#else
#include "kestrel/hal/radar_adapter.hpp"
#include "kestrel/tracking/radar_tracker.hpp"
#endif

namespace kestrel::m7 {

using Feed = UartRingFeed;
using Clock = board::DwtCycleClock;
#if defined(KESTREL_BOARD_SINK_CAT062)
using Sink = UartCat062Sink;
#else
using Sink = UartTxSink;
#endif

#if defined(KESTREL_BOARD_SENSOR_PCL)

using Tracker = PclTracker<PclKf<double>, kPclMaxTracks, kPclMaxCandidates>;
using Adapter = hal::PclAdapter<Tracker>;

/// PCL-002's sensor and track management (core defaults); the adapter takes
/// its carrier from the same parameters so Rb-rate conversion and the
/// filter's wavelength agree.
inline constexpr PclTrackerParams kPclParams{};

inline Tracker make_tracker() {
  return make_pcl_tracker<double, kPclMaxTracks, kPclMaxCandidates>(kPclParams);
}
/// The adapter reads the tracker's tracks to rank an over-capacity frame.
inline Adapter make_adapter(const Tracker& tracker) {
  return Adapter(&tracker, hal::PclAdapterParams{kPclParams.carrier_hz});
}

static_assert(Tracker::Scan::kMaxMeasurements <= hal::kMaxPclCandidates,
              "the scan should not be larger than a PCL frame can fill");

#else

using Tracker = RadarTracker<EkfCa<double>, kMaxTracks, kMaxPlots>;
using Adapter = hal::RadarAdapter;

inline Tracker make_tracker() {
  return make_radar_tracker<double, kMaxTracks, kMaxPlots>(RadarTrackerParams{});
}
inline Adapter make_adapter(const Tracker&) { return Adapter{}; }

static_assert(Tracker::Scan::kMaxMeasurements <= hal::kMaxRadarPlots,
              "the scan should not be larger than a radar frame can fill");

#endif

using Runner = hal::Runner<Feed, Clock, Tracker, Adapter, Sink>;

static_assert(hal::MeasurementFeed<Feed>);
static_assert(hal::CycleClock<Clock>);
static_assert(hal::TrackSink<Sink, Tracker::Report>);

}  // namespace kestrel::m7
