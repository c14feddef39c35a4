// SPDX-License-Identifier: Apache-2.0
// One UW run through the board loop (docs/tracking.md), and Monte Carlo over
// seeds. The scenario's sonar wire frames are encoded into a byte stream and
// driven exactly as a board drives them: host::StreamFileFeed ->
// hal::SonarAdapter (nanoseconds to seconds) -> SonarTracker::step
// (core/include/kestrel/tracking/sonar_tracker.hpp) -> host::MemorySink,
// inside hal::Runner and timed by host::SteadyClock. Per frame it keeps the
// estimate, its covariance and which channels were fused or gated, so the
// metrics can compare the gate with the true outliers.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "kestrel/hal/runner.hpp"
#include "kestrel/status.hpp"
#include "kestrel/tracking/sonar_tracker.hpp"
#include "scenarios/uw003.hpp"

namespace kestrel::sim {

struct SonarFrameOutcome {
  Status status = Status::kOk;   ///< Runner::poll_once() result.
  bool stepped = false;          ///< Reached SonarTracker::step.
  std::uint64_t step_ns = 0;     ///< Adapter + step time, ns.
  double t_s = 0.0;              ///< The frame's wire time, s (NaN if it did not reach the tracker).
  bool reported = false;         ///< The tracker published an estimate.
  std::uint32_t track_id = 0;    ///< Its track id (a new one at every (re)initialisation).
  bool initialised = false;      ///< This frame (re)started the track from a fix.
  bool predict_only = false;     ///< Tracked frame with nothing fused.
  std::array<double, 7> x{};     ///< [x y z vx vy vz c] (m, m/s, m/s).
  std::array<double, 9> p_pos{}; ///< Position covariance, row-major 3 x 3, m^2.
  std::array<double, 7> sd{};    ///< Square roots of the diagonal of P.
  std::uint32_t present = 0;     ///< Channels in the frame (bit 2 beacon + path).
  std::uint32_t fused = 0;       ///< Channels fused.
  std::uint32_t gated = 0;       ///< Channels gated out (or rejected by the fix).
  double nis = 0.0;              ///< NIS over the fused channels.
};

struct SonarRunOutput {
  std::vector<SonarFrameOutcome> frames;  ///< One per wire frame, in order.
  hal::RunnerStats stats;
};

/// Tracker parameters for a scenario: the installation (beacons, seabed,
/// TOA sigma) from the scenario, everything else from `base`.
SonarTrackerParams sonar_params_for(const SonarScenarioParams& scenario,
                                    const SonarTrackerParams& base = SonarTrackerParams{});

/// Run the tracker with `params` over the run's frames (std::runtime_error
/// if the Runner does not see exactly one frame per wire frame).
SonarRunOutput run_sonar(const SonarScenarioRun& run, const SonarTrackerParams& params, std::uint64_t budget_ns);

/// Run the tracker with `params` over a sonar byte stream (any bytes: one
/// outcome per Runner frame, malformed or refused ones included, until the
/// stream is used up).
SonarRunOutput run_sonar_stream(std::vector<std::uint8_t> stream, const SonarTrackerParams& params,
                                std::uint64_t budget_ns);

/// The run's frames as the wire byte stream a sonar sends.
std::vector<std::uint8_t> encode_sonar_stream(const SonarScenarioRun& run);

}  // namespace kestrel::sim
