// SPDX-License-Identifier: Apache-2.0
// The files `run`, `replay` and `suite` write for one scenario and filter
// into an output directory (names are prefixed with the filter so several
// filters can share a scenario's directory):
//   <filter>_tracks.csv  track CSV of run 0 (docs/host_sim.md, every report)
//   <filter>_steps.csv   per-step CSV of run 0 (csv/step_csv.hpp)
//   <filter>_runs.csv    one row of figures per Monte Carlo run
//   <filter>_modes.csv   filters with modes (IMM): the scored track's mode
//                        probabilities per scored step of every run
//   <filter>_xy.png, <filter>_error.png   plots of run 0 (plots/)
//   <filter>_modes.png   mean mode probabilities over the runs (plots/)
//   summary.json         merged entry for (scenario, filter)
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "montecarlo/monte_carlo.hpp"

namespace kestrel::sim {

struct RunFileNames {
  std::filesystem::path tracks_csv, steps_csv, runs_csv, modes_csv, plot_prefix;
};

RunFileNames run_file_names(const std::filesystem::path& dir, const std::string& filter);

/// Track CSV of every report of a run.
void write_track_csv(const std::filesystem::path& path, const StreamRunResult& run);

/// Per-run figures.
void write_runs_csv(const std::filesystem::path& path, const std::vector<RunRecord>& runs);

/// Mode probabilities of every run: run,seed,time_s,track_id,mu_<name>...
/// (one row per scored step with a track). @return false, writing
/// nothing, when no run has any (a filter without modes).
bool write_modes_csv(const std::filesystem::path& path, const std::vector<RunRecord>& runs,
                     const std::vector<std::string>& mode_names);

}  // namespace kestrel::sim
