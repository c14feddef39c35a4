// SPDX-License-Identifier: Apache-2.0
// UW-003 (paper 003; docs/scenarios.md, "UW-003"): four surface beacons at
// the corners of a 2 km square over a flat seabed, one target with white
// acceleration, a sound speed on a bounded random walk, and per beacon the
// direct and the seabed-reflected arrival with TOA noise and occasional late
// outliers. Variants (uw003-direct, -clean, -d100, -1ms) make every draw in
// the same order, so with one seed they share truth and noise and differ
// only in what they change. The numbers and the choices the paper leaves
// open are in docs/scenarios.md and docs/sonar.md, "Scenario choices
// the paper leaves open".
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "kestrel/hal/frame.hpp"

namespace kestrel::sim {

struct SonarScenarioParams {
  std::string name;                  ///< "uw003", "uw003-direct", ...
  std::string description;           ///< One line for listings.
  double period_s = 1.0;             ///< T, s.
  std::size_t frames = 50;           ///< Frames per run.
  std::vector<std::array<double, 3>> beacons_m{{0, 0, 0}, {2000, 0, 0}, {0, 2000, 0}, {2000, 2000, 0}};
  double seabed_depth_m = 150.0;     ///< D, m.
  std::array<double, 3> start_m{500, 800, 60};      ///< Initial position (x, y, depth), m.
  std::array<double, 3> start_v_mps{1.2, 1.0, -0.2};  ///< Initial velocity, m/s.
  double accel_sigma_mps2 = 0.05;    ///< White acceleration per axis, m/s^2.
  double sound_speed_mps = 1500.0;   ///< Mean sound speed, m/s.
  double sound_speed_step_mps = 0.3; ///< Random-walk sigma per step, m/s.
  double sound_speed_limit_mps = 2.0;  ///< |c - mean| kept at most this, m/s.
  double sigma_toa_s = 3e-3;         ///< TOA noise sigma, s.
  bool reflected = true;             ///< Emit the seabed-reflected arrivals.
  double outlier_probability = 0.05; ///< Per arrival.
  double outlier_min_s = 5e-3;       ///< Outlier delay U(min, max), s.
  double outlier_max_s = 50e-3;
};

/// UW-003 and its variants (docs/scenarios.md).
SonarScenarioParams uw003_config();
/// By name: uw003, uw003-direct, uw003-clean, uw003-d100, uw003-1ms
/// (case-insensitive). Throws std::invalid_argument.
SonarScenarioParams sonar_config_by_name(const std::string& name);
/// Every UW scenario name, uw003 first.
std::vector<std::string> sonar_scenario_names();

/// The target and the medium at one frame time.
struct SonarTruth {
  double t_s = 0.0;                                  ///< Ping time, s.
  double x_m = 0.0, y_m = 0.0, z_m = 0.0;            ///< Position; z is depth, positive down, m.
  double vx_mps = 0.0, vy_mps = 0.0, vz_mps = 0.0;   ///< Velocity, m/s.
  double c_mps = 0.0;                                ///< Sound speed, m/s.
};

/// One arrival as generated (before quantisation), for scoring.
struct SonarArrivalRecord {
  std::uint8_t beacon = 0;
  hal::ToaPath path = hal::ToaPath::kDirect;
  double true_toa_s = 0.0;   ///< Noise-free travel time, s.
  double toa_s = 0.0;        ///< With noise and any outlier delay, s.
  bool outlier = false;      ///< Carries an outlier delay.
  double outlier_s = 0.0;    ///< That delay, s.
};

struct SonarFrameRecord {
  hal::Frame wire{};                      ///< Quantised frame (arrivals in the order of `arrivals`).
  std::vector<SonarArrivalRecord> arrivals;  ///< Same order as wire.sonar.
};

struct SonarScenarioRun {
  std::vector<SonarTruth> truth;        ///< truth[k] at frames[k].
  std::vector<SonarFrameRecord> frames;
  std::size_t depth_reflections = 0; ///< Times the target was turned back into the water.
};

/// Truth and frames of the run with this seed (bit-reproducible).
SonarScenarioRun generate_sonar(const SonarScenarioParams& config, std::uint64_t seed);

}  // namespace kestrel::sim
