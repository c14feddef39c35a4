// SPDX-License-Identifier: Apache-2.0
// The files `kestrel-sim run -s uw003` writes into its output directory:
//   sonar_runs.csv       one row per Monte Carlo run (the per-run figures);
//   sonar_steps.csv      per frame over the runs: 3D, horizontal and depth RMSE
//                     and the RMS sound-speed error, and how many runs scored;
//   sonar_truth.csv      run 0: the target (x, y, depth, velocity), c, and the
//                     channels and outliers (csv/sensor_truth_csv.hpp);
//   sonar_arrivals.csv   run 0: every arrival (beacon, path, true and measured
//                     time, outlier delay) and what the tracker did with it;
//   sonar_track.csv      run 0: the estimate and its sigmas per frame, fused and
//                     gated counts, NIS, whether the frame was a fix;
//   summary.json         results[<scenario>]["sonar-ekf"]: the Monte Carlo
//                     figures with their 95 % intervals, the scenario and
//                     tracker settings, "kind": "sonar" (report/summary_json.hpp's
//                     file; NaN is written as null);
//   sonar_track.png, sonar_error.png, sonar_sound_speed.png  the paper's figures 1-3
//                     (plots/sonar_plots.py).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "kestrel/tracking/sonar_tracker.hpp"
#include "metrics/sonar_metrics.hpp"

namespace kestrel::sim {

void write_sonar_runs_csv(const std::filesystem::path& path, const std::vector<SonarRunMetrics>& runs);
void write_sonar_steps_csv(const std::filesystem::path& path, const SonarSummary& summary);
/// sonar_truth.csv, sonar_arrivals.csv and sonar_track.csv of one run.
void write_sonar_run_csvs(const std::filesystem::path& dir, const SonarScenarioRun& run, const SonarRunOutput& out);

/// sonar_track.csv alone: one row per frame (`run` for run 0, `replay --stream`
/// for a recorded sonar stream); time_s[k] is frame k's time (NaN: empty).
void write_sonar_track_csv(const std::filesystem::path& path, const std::vector<SonarFrameOutcome>& frames,
                        const std::vector<double>& time_s);

/// The "scenario" object of a sonar summary entry (the installation and noise).
nlohmann::json sonar_scenario_json(const SonarScenarioParams& scenario);
nlohmann::json sonar_params_json(const SonarTrackerParams& params);
nlohmann::json sonar_summary_json(const SonarScenarioParams& scenario, const SonarTrackerParams& params,
                               const SonarMonteCarloParams& config, const SonarSummary& summary);

/// Run plots/sonar_plots.py over the CSVs of `dir` (best effort: a failure
/// prints a warning). @return true on success.
bool plot_sonar(const std::filesystem::path& dir, const std::string& title);

}  // namespace kestrel::sim
