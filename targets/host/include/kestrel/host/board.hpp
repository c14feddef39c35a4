// SPDX-License-Identifier: Apache-2.0
// The host board: which concrete type plays each HAL role (docs/porting.md),
// and the capacities of the radar tracker built on the host. A board main
// (targets/host/main.cpp) and kestrel-sim both take their types from here,
// so the simulator runs exactly the loop a board runs:
//
//   StreamFileFeed::poll -> hal::RadarAdapter -> Tracker::step ->
//   Sink::publish, timed by SteadyClock, all inside hal::Runner.
// (AsterixFileFeed replaces StreamFileFeed for a CAT048 recording.)
#pragma once

#include <cstddef>

#include "kestrel/hal/frame.hpp"
#include "kestrel/hal/radar_adapter.hpp"
#include "kestrel/hal/runner.hpp"
#include "kestrel/host/asterix_file_feed.hpp"
#include "kestrel/host/csv_track_sink.hpp"
#include "kestrel/host/memory_sink.hpp"
#include "kestrel/host/steady_clock.hpp"
#include "kestrel/host/stream_file_feed.hpp"
#include "kestrel/tracking/radar_tracker.hpp"

namespace kestrel::host {

/// Track table capacity. One target plus the seeds a frame of plots can
/// start; 16 leaves room for clutter plots in later scenarios.
inline constexpr std::size_t kMaxTracks = 16;
/// Plots per scan: the wire frame's capacity, so no decoded plot is dropped.
inline constexpr std::size_t kMaxPlots = hal::kMaxRadarPlots;

using Feed = StreamFileFeed;
using Clock = SteadyClock;

/// The radar tracker of this board for a given filter (EKF-CA double/float, ...).
template <class Filter>
using BoardRadarTracker = RadarTracker<Filter, kMaxTracks, kMaxPlots>;

/// The board loop for a tracker and a sink.
template <class Tracker, class Sink>
using BoardRunner = hal::Runner<Feed, Clock, Tracker, hal::RadarAdapter, Sink>;

/// The same loop over another feed: AsterixFileFeed for a CAT048 recording.
template <class OtherFeed, class Tracker, class Sink>
using BoardRunnerOver = hal::Runner<OtherFeed, Clock, Tracker, hal::RadarAdapter, Sink>;

}  // namespace kestrel::host
