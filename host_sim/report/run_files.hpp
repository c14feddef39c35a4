// SPDX-License-Identifier: Apache-2.0
// The files `run`, `replay` and `suite` write for one scenario and filter
// into an output directory (names are prefixed with the filter so several
// filters can share a scenario's directory):
//   <filter>_tracks.csv  track CSV of run 0 (docs/host_sim.md, every report)
//   <filter>_steps.csv   per-step CSV of run 0 (csv/step_csv.hpp)
//   <filter>_runs.csv    one row of figures per Monte Carlo run
//   <filter>_xy.png, <filter>_error.png   plots of run 0 (plots/)
//   summary.json         merged entry for (scenario, filter)
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "montecarlo/monte_carlo.hpp"

namespace kestrel::sim {

struct RunFileNames {
  std::filesystem::path tracks_csv, steps_csv, runs_csv, plot_prefix;
};

RunFileNames run_file_names(const std::filesystem::path& dir, const std::string& filter);

/// Track CSV of every report of a run.
void write_track_csv(const std::filesystem::path& path, const StreamRunResult& run);

/// Per-run figures.
void write_runs_csv(const std::filesystem::path& path, const std::vector<RunRecord>& runs);

}  // namespace kestrel::sim
