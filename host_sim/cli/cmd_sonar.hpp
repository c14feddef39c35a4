// SPDX-License-Identifier: Apache-2.0
// `kestrel-sim sonar`: Monte Carlo runs of the underwater scenarios (uw003 and
// its variants; docs/scenarios.md) with the sonar tracker, scored with the
// UW metrics (3D / horizontal / depth RMSE, sound-speed error std, gated-out
// arrivals against the true outliers). Sonar frames, the 7-state estimate
// and these metrics differ from the radar ones, so this is its own
// subcommand; its files are listed in report/sonar_files.hpp.
//
// `kestrel-sim sonar --study` runs every variant with the paper's gate (k = 2),
// k = 3 and no gate, and writes the comparison table (sonar_study.md / .json).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace kestrel::sim::cli {

struct SonarOptions {
  std::string scenario = "uw003";
  std::size_t runs = 200;
  std::uint64_t seed = 0;
  unsigned jobs = 1;
  std::string out;  ///< Default results/<scenario> (results/sonar_study with --study).
  bool plots = true;
  bool study = false;
  double budget_us = 1000.0;
  /// --config FILE and --set KEY=VALUE: the tracker's keys
  /// (filters/sensor_settings.hpp), laid under the options of their own.
  std::string config;
  std::vector<std::string> sets;
  // Tracker overrides (unset = SonarTrackerParams default).
  std::optional<double> gate_k;
  bool no_gate = false;
  bool ellipsoidal = false;
  std::optional<double> ellipsoid_probability;  ///< 0.90, 0.95, 0.99, 0.995 or 0.999.
  std::optional<double> accel_sigma_mps2;
  std::optional<double> sound_speed_sigma;      ///< m/s per sqrt(s).
  std::optional<unsigned> reacquire_after;      ///< 0 = never.
  bool no_gate_truncation = false;              ///< Tracker without the gate-truncation covariance.
  bool no_depth_projection = false;             ///< Tracker without the depth projection.
};

/// Register the subcommand and its options on `app`.
CLI::App* add_sonar_command(CLI::App& app, SonarOptions& options);

int cmd_sonar(const SonarOptions& options);

}  // namespace kestrel::sim::cli
