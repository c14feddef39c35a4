// SPDX-License-Identifier: Apache-2.0
// `kestrel-sim pcl`: Monte Carlo runs of the passive-radar scenarios
// (pcl002, pcl002-hard; docs/scenarios.md) with the ready-made PCL tracker,
// scored with the PCL metrics (association accuracy, coverage after
// confirmation, false confirmed tracks, Rb/dRb RMSE, time to confirmation).
// PCL frames, states and metrics differ from the radar ones, so this is its
// own subcommand; its files are listed in report/pcl_files.hpp.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace kestrel::sim::cli {

struct PclOptions {
  std::string scenario = "pcl002";
  std::size_t runs = 200;
  std::uint64_t seed = 0;
  unsigned jobs = 1;
  std::string out;  ///< Default results/<scenario>.
  bool plots = true;
  double budget_us = 1000.0;
  /// --config FILE and --set KEY=VALUE: the tracker's keys
  /// (filters/sensor_settings.hpp), laid under the options of their own.
  std::string config;
  std::vector<std::string> sets;
  // Tracker overrides (unset = PclTrackerParams default).
  std::optional<double> accel_sigma_mps2;
  std::optional<unsigned> confirm_m, confirm_n, max_coast_misses;
  std::optional<double> gate_tentative, gate_confirmed;  ///< 0.90, 0.95, 0.99, 0.995 or 0.999.
  std::optional<double> min_start_doppler_hz;
  // Policies (pipeline/tracker_policies.hpp) and their parameters (unset =
  // the scenario's sensor: its P_D and clutter density).
  std::string associator = "nn";
  std::string manager = "m-of-n";
  std::optional<double> detection_probability, clutter_density, new_target_density;
  std::optional<double> false_track_probability, missed_track_probability;
};

/// Register the subcommand and its options on `app`.
CLI::App* add_pcl_command(CLI::App& app, PclOptions& options);

int cmd_pcl(const PclOptions& options);

}  // namespace kestrel::sim::cli
