// SPDX-License-Identifier: Apache-2.0
// UW-003 (docs/scenarios.md, paper 003): four surface beacons at the corners of
// a 2 km square, a flat seabed at D = 150 m, a target starting at
// (500, 800, 60) m with velocity (1.2, 1.0, -0.2) m/s plus white
// acceleration of 0.05 m/s^2 per axis, T = 1 s, 50 frames. The sound speed
// is 1500 m/s plus a random walk of 0.3 m/s per step kept within +-2 m/s.
// Each beacon reports the direct and the seabed-reflected arrival (image
// source), TOA noise sigma 3 ms, and with probability 5 % an arrival is an
// outlier, late by U(5, 50) ms.
//
// Variants (same seeds, same random draws, so a variant differs from uw003
// only in what it changes): uw003-direct (direct arrivals only),
// uw003-clean (no outliers), uw003-d100 (seabed at 100 m), uw003-1ms (TOA
// noise 1 ms).
//
// Choices the paper leaves open, fixed here (docs/underwater.md lists them):
//  - Motion per step: a ~ N(0, 0.05^2) per axis, p += v T + a T^2 / 2,
//    v += a T (the discrete white-noise-acceleration model the filter uses).
//    A target that would leave the water (depth outside [1, D - 1] m) is
//    reflected back in (position and vertical velocity); counted per run.
//  - Sound speed: c += N(0, 0.3^2) per step, then clamped to 1500 +- 2 m/s.
//    Every arrival of a frame travels at the frame's c.
//  - Frame k is the ping emitted at t = k T; its arrivals carry travel
//    times (the beacons and the target share a clock), quantised to the
//    wire's nanoseconds.
//  - Draw order per frame: 3 accelerations, 1 sound-speed step, then per
//    beacon and path (direct, reflected): noise, outlier coin, outlier size;
//    all are drawn whatever the variant.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "kestrel/hal/frame.hpp"

namespace kestrel::sim {

struct UwScenarioConfig {
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
UwScenarioConfig uw003_config();
/// By name: uw003, uw003-direct, uw003-clean, uw003-d100, uw003-1ms
/// (case-insensitive). Throws std::invalid_argument.
UwScenarioConfig uw_config_by_name(const std::string& name);
/// Every UW scenario name, uw003 first.
std::vector<std::string> uw_scenario_names();

/// The target and the medium at one frame time.
struct UwTruth {
  double t_s = 0.0;                                  ///< Ping time, s.
  double x_m = 0.0, y_m = 0.0, z_m = 0.0;            ///< Position; z is depth, positive down, m.
  double vx_mps = 0.0, vy_mps = 0.0, vz_mps = 0.0;   ///< Velocity, m/s.
  double c_mps = 0.0;                                ///< Sound speed, m/s.
};

/// One arrival as generated (before quantisation), for scoring.
struct UwArrivalRecord {
  std::uint8_t beacon = 0;
  hal::ToaPath path = hal::ToaPath::kDirect;
  double true_toa_s = 0.0;   ///< Noise-free travel time, s.
  double toa_s = 0.0;        ///< With noise and any outlier delay, s.
  bool outlier = false;      ///< Carries an outlier delay.
  double outlier_s = 0.0;    ///< That delay, s.
};

struct UwFrameRecord {
  hal::Frame wire{};                      ///< Quantised frame (arrivals in the order of `arrivals`).
  std::vector<UwArrivalRecord> arrivals;  ///< Same order as wire.sonar.
};

struct UwScenarioRun {
  std::vector<UwTruth> truth;        ///< truth[k] at frames[k].
  std::vector<UwFrameRecord> frames;
  std::size_t depth_reflections = 0; ///< Times the target was turned back into the water.
};

/// Truth and frames of the run with this seed (bit-reproducible).
UwScenarioRun generate_uw(const UwScenarioConfig& config, std::uint64_t seed);

}  // namespace kestrel::sim
