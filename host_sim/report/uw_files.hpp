// SPDX-License-Identifier: Apache-2.0
// The files `kestrel-sim uw` writes into its output directory:
//   uw_runs.csv       one row per Monte Carlo run (the per-run figures);
//   uw_steps.csv      per frame over the runs: 3D, horizontal and depth RMSE
//                     and the RMS sound-speed error, and how many runs scored;
//   uw_truth.csv      run 0: the target (x, y, depth, velocity), c, and the
//                     channels and outliers (csv/sensor_truth_csv.hpp);
//   uw_arrivals.csv   run 0: every arrival (beacon, path, true and measured
//                     time, outlier delay) and what the tracker did with it;
//   uw_track.csv      run 0: the estimate and its sigmas per frame, fused and
//                     gated counts, NIS, whether the frame was a fix;
//   uw_summary.json   the Monte Carlo figures with their 95 % intervals, the
//                     scenario and tracker settings (schema
//                     "kestrel-sim-uw-summary/1"; NaN is written as null);
//   uw_track.png, uw_error.png, uw_sound_speed.png  the paper's figures 1-3
//                     (plots/uw_plots.py).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "kestrel/tracking/underwater_tracker.hpp"
#include "metrics/uw_metrics.hpp"

namespace kestrel::sim {

void write_uw_runs_csv(const std::filesystem::path& path, const std::vector<UwRunMetrics>& runs);
void write_uw_steps_csv(const std::filesystem::path& path, const UwSummary& summary);
/// uw_truth.csv, uw_arrivals.csv and uw_track.csv of one run.
void write_uw_run_csvs(const std::filesystem::path& dir, const UwScenarioRun& run, const UwRunOutput& out);

/// uw_track.csv alone: one row per frame (`uw` for run 0, `replay --stream`
/// for a recorded sonar stream); time_s[k] is frame k's time (NaN: empty).
void write_uw_track_csv(const std::filesystem::path& path, const std::vector<UwFrameOutcome>& frames,
                        const std::vector<double>& time_s);

/// The "scenario" object of uw_summary.json (the installation and noise).
nlohmann::json uw_scenario_json(const UwScenarioConfig& scenario);
nlohmann::json uw_params_json(const UnderwaterTrackerParams& params);
nlohmann::json uw_summary_json(const UwScenarioConfig& scenario, const UnderwaterTrackerParams& params,
                               const UwMonteCarloConfig& config, const UwSummary& summary);

/// Run plots/uw_plots.py over the CSVs of `dir` (best effort: a failure
/// prints a warning). @return true on success.
bool plot_uw(const std::filesystem::path& dir, const std::string& title);

}  // namespace kestrel::sim
