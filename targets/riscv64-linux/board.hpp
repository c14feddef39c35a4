// SPDX-License-Identifier: Apache-2.0
// The riscv64-linux board's choice of a concrete type for every HAL concept
// (docs/porting.md: board.hpp binds each concept), and the tracker
// it runs. Everything is resolved at compile time: no virtual dispatch.
//
//   MeasurementFeed -> FdFeed      (read(2) of a file, pipe or serial device
//                                   -> FrameAssembler)
//   CycleClock      -> CycleClock  (clock_gettime, rdtime or rdcycle:
//                                   cycle_clock.hpp)
//   TrackSink       -> FdTrackSink (KTRK records -> write(2))
//   Tracker         -> EKF-CA radar tracker in double (RV64GC has the D
//                      extension), the host board's capacities
#pragma once

#include "board_config.hpp"
#include "cycle_clock.hpp"
#include "fd_feed.hpp"
#include "fd_sink.hpp"
#include "kestrel/hal/clock.hpp"
#include "kestrel/hal/feed.hpp"
#include "kestrel/hal/radar_adapter.hpp"
#include "kestrel/hal/runner.hpp"
#include "kestrel/hal/sink.hpp"
#include "kestrel/tracking/radar_tracker.hpp"

namespace kestrel::rv64 {

using Feed = FdFeed;
using Clock = CycleClock;
using Sink = FdTrackSink;
using Tracker = RadarTracker<EkfCa<double>, kMaxTracks, kMaxPlots>;
using Adapter = hal::RadarAdapter;
using Runner = hal::Runner<Feed, Clock, Tracker, Adapter, Sink>;

static_assert(hal::MeasurementFeed<Feed>);
static_assert(hal::CycleClock<Clock>);
static_assert(hal::TrackSink<Sink, Tracker::Report>);

}  // namespace kestrel::rv64
