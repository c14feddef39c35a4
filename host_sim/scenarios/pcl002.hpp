// SPDX-License-Identifier: Apache-2.0
// PCL-002 (paper 002; docs/scenarios.md, "PCL-002"): a DTV passive radar
// (701 MHz) with the receiver at the origin and the transmitter 8.5 km
// south, a drone manoeuvring 300-900 m north of the receiver, and every
// 0.5 s a frame of range-Doppler candidates: the drone's detection, Poisson
// clutter uniform over Rb and fD, and 0-3 zero-Doppler ridge candidates. The
// hard variant triples the clutter, lowers Pd to 0.7 and gives the tracker 64
// candidates per scan. The choices the paper leaves open (a random smooth
// manoeuvre per run, uninformative SNR and shuffled candidates, the wire's 64
// strongest) are in docs/pcl.md, "Scenario PCL-002 and the choices made".
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "kestrel/hal/frame.hpp"

namespace kestrel::sim {

struct PclScenarioParams {
  std::string name;                   ///< "pcl002" or "pcl002-hard".
  std::string description;            ///< One line for listings.
  double frame_period_s = 0.5;        ///< T, s.
  std::size_t frames = 120;           ///< Frames per run (60 s).
  double carrier_hz = 701.0e6;        ///< DTV carrier, Hz (lambda = c0 / f).
  double tx_x_m = 0.0, tx_y_m = -8500.0, tx_z_m = 0.0;  ///< Transmitter, m (receiver at the origin).
  double pd = 0.9;                    ///< Target detection probability per frame.
  double sigma_rb_m = 10.0;           ///< Bistatic range noise, m.
  double sigma_fd_hz = 0.5;           ///< Doppler noise, Hz.
  double clutter_mean = 21.0;         ///< Poisson mean of false candidates per frame.
  double clutter_rb_max_m = 3000.0;   ///< Clutter Rb uniform on [0, this], m.
  double clutter_fd_max_hz = 125.0;   ///< Clutter fD uniform on [-this, this], Hz.
  int ridge_max = 3;                  ///< Ridge candidates per frame uniform on 0..ridge_max.
  double ridge_fd_max_hz = 1.0;       ///< Ridge |fD| below this, Hz.
  std::size_t scan_capacity = 32;     ///< Candidates per tracker scan.
  // The drone (docs/scenarios.md).
  double r_min_m = 300.0, r_max_m = 900.0;       ///< Horizontal distance from the receiver, m.
  double alt_min_m = 50.0, alt_max_m = 120.0;    ///< Altitude, m.
  double speed_max_mps = 26.0;                   ///< Speed limit, m/s.
  double lateral_accel_max_mps2 = 3.0;           ///< |a| normal to the track, m/s^2.
  double along_accel_max_mps2 = 2.0;             ///< |a| along the track, m/s^2.
};

/// PCL-002 and its hard variant (docs/scenarios.md).
PclScenarioParams pcl002_config();
PclScenarioParams pcl002_hard_config();
/// By name ("pcl002", "pcl002-hard", case-insensitive). Throws std::invalid_argument.
PclScenarioParams pcl_config_by_name(const std::string& name);
/// The names pcl_config_by_name knows, in listing order.
std::vector<std::string> pcl_scenario_names();

/// The drone at one frame time, and what the sensor would measure noise-free.
struct PclTruth {
  double t_s = 0.0;                          ///< Time, s.
  double x_m = 0.0, y_m = 0.0, z_m = 0.0;    ///< Position (east, north, up), m; receiver at the origin.
  double vx_mps = 0.0, vy_mps = 0.0, vz_mps = 0.0;  ///< Velocity, m/s.
  double rb_m = 0.0;                         ///< Bistatic range, m.
  double drb_mps = 0.0;                      ///< Bistatic range rate, m/s.
  double fd_hz = 0.0;                        ///< Doppler -drb / lambda, Hz.
};

/// What the run generated for one frame: the wire frame and which of its
/// candidates is the target's detection.
struct PclFrameRecord {
  hal::Frame wire{};            ///< Quantised, shuffled, at most 64 candidates.
  int target_index = -1;        ///< Index of the target's detection in wire.pcl, -1 if none.
  bool detected = false;        ///< The sensor detected the target (it may still have been cut to 64).
  std::size_t generated = 0;    ///< Candidates before the 64-candidate cut.
};

struct PclScenarioRun {
  std::vector<PclTruth> truth;         ///< truth[k] at frames[k].
  std::vector<PclFrameRecord> frames;
  std::uint32_t trajectory_attempts = 0;  ///< Sub-seeds drawn until the trajectory met the scenario's box.
};

/// Truth and frames of the run with this seed (bit-reproducible).
PclScenarioRun generate_pcl(const PclScenarioParams& config, std::uint64_t seed);

/// The wavelength of the scenario's carrier, m.
double pcl_lambda_m(const PclScenarioParams& config);

}  // namespace kestrel::sim
