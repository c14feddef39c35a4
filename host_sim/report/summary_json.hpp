// SPDX-License-Identifier: Apache-2.0
// summary.json: the machine-readable result of `run`, `replay`, `suite`
// and `sweep`, one schema for every kind:
//   { "schema": "kestrel-sim-summary/1",
//     "results": { "<scenario>": { "<filter>": { "kind": ..., ...entry... } } } }
// "kind" is the frames' kind (radar, PCL, sonar); a PCL, sonar or
// multi-target entry holds its own figures (report/pcl_files.hpp,
// report/sonar_files.hpp, cli/run_multi.cpp). A single-target radar entry
// holds rmse_m, peak_m, nees_pos, nis, track_loss_s, recovery_s (each
// {mean, ci95_low, ci95_high, n}), runs, runs_without_loss, step_ns
// {min, median, p99, max, mean, steps, budget_ns, overruns}, and the
// settings that produced it. NaN (a figure with no data, e.g. recovery
// when no run lost the track) is written as null.
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "filters/filter_registry.hpp"
#include "montecarlo/monte_carlo.hpp"

namespace kestrel::sim {

/// Where an entry came from.
struct EntryContext {
  std::string scenario;             ///< Scenario name, or "replay".
  std::string filter;               ///< Filter name.
  FilterSetup setup;                ///< Resolved parameters.
  std::uint64_t base_seed = 0;      ///< Seed of run 0 (scenario runs).
  double frame_period_s = 0.0;      ///< T.
  double loss_threshold_m = 0.0;    ///< L.
  std::size_t first_scored_step = 0;
  unsigned jobs = 1;                ///< Worker threads the runs used.
};

/// Every metric of a Monte Carlo summary (intervals as {mean, ci95_low,
/// ci95_high, n}, step times), without where it came from.
nlohmann::json summary_metrics(const MonteCarloSummary& summary);

/// summary_metrics with the context: one results[scenario][filter] entry.
nlohmann::json summary_entry(const EntryContext& context, const MonteCarloSummary& summary);

/// Put `entry` at results[scenario][filter] of the summary file at `path`,
/// keeping the other entries of an existing file (a file that is missing,
/// unreadable or of another schema is replaced).
void merge_summary_file(const std::filesystem::path& path, const std::string& scenario, const std::string& filter,
                        const nlohmann::json& entry);

/// Write a whole summary (the suite's combined file).
void write_summary_file(const std::filesystem::path& path, const nlohmann::json& results);

}  // namespace kestrel::sim
