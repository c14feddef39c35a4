// SPDX-License-Identifier: Apache-2.0
// The files `kestrel-sim run -s pcl002` writes into its output directory:
//   pcl_runs.csv        one row per Monte Carlo run (the per-run figures);
//   pcl_truth.csv       run 0: the drone (x, y, z, velocity) and its Rb, dRb, fD,
//                       and the target's detection (csv/sensor_truth_csv.hpp);
//   pcl_candidates.csv  run 0: every candidate of every frame (Rb, fD, SNR),
//                       whether it is the target's detection, whether the
//                       adapter kept it, and the confirmed track that took it;
//   pcl_tracks.csv      run 0: every confirmed track per frame: estimate,
//                       covariance, prediction, NIS, test ratio, on-target;
//   summary.json        results[<scenario>]["pcl-kf"]: the Monte Carlo figures
//                       with their 95 % intervals, the scenario and tracker
//                       settings, "kind": "PCL" (report/summary_json.hpp's
//                       file; NaN is written as null);
//   pcl_range_doppler.png  run 0 as in paper 002's figure 2 (plots/pcl_plots.py).
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "kestrel/tracking/pcl_tracker.hpp"
#include "montecarlo/pcl_monte_carlo.hpp"

namespace kestrel::sim {

void write_pcl_runs_csv(const std::filesystem::path& path, const std::vector<PclRunMetrics>& runs);

/// pcl_truth.csv, pcl_candidates.csv and pcl_tracks.csv of one run.
void write_pcl_run_csvs(const std::filesystem::path& dir, const PclScenarioParams& scenario,
                        const PclScenarioRun& run, const PclRunOutput& out, const PclTolerance& tolerance);

/// pcl_tracks.csv alone: every confirmed track of every frame (`run` for
/// run 0, `replay --stream` for a recorded PCL stream). time_s[k] is frame
/// k's time; with `truth` (frame k's truth at index k), on_target is 0/1,
/// without it (or where that truth's rb_m is NaN) the cell is empty.
void write_pcl_tracks_csv(const std::filesystem::path& path, const std::vector<PclFrameOutcome>& frames,
                          const std::vector<double>& time_s, double lambda_m, const std::vector<PclTruth>* truth,
                          const PclTolerance& tolerance);

/// The "scenario" (sensor) and "tracker" objects of a PCL summary entry.
nlohmann::json pcl_scenario_json(const PclScenarioParams& scenario);
nlohmann::json pcl_tracker_json(const PclTrackerParams& params, const TrackerPolicies& policies);

nlohmann::json pcl_summary_json(const PclScenarioParams& scenario, const PclTrackerParams& params,
                                const PclMonteCarloParams& config, const PclSummary& summary);

/// Run plots/pcl_plots.py over the run-0 CSVs of `dir` (best effort, like
/// the other plots: a failure prints a warning). @return true on success.
bool plot_pcl(const std::filesystem::path& dir, const std::string& title);

}  // namespace kestrel::sim
