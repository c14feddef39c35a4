// SPDX-License-Identifier: Apache-2.0
// Runs the plot scripts (plots/*.py) in one Python process per command
// (plots/plot_server.py) with /usr/bin/python3, the interpreter that has
// matplotlib on this project's hosts; KESTREL_PYTHON overrides the
// interpreter and KESTREL_PLOT_SCRIPT the script plot_results.py. Plotting
// is best effort: a failure prints a warning and never fails the command.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace kestrel::sim {

/// Run plots/<script_name> (a script beside plot_results.py, e.g.
/// "pcl_plots.py") with `args`. @return true if it exited with status 0;
/// otherwise a warning naming the command has been printed to stderr.
bool run_named_plot_script(const std::string& script_name, const std::vector<std::string>& args);

/// Run plot_results.py (or the script KESTREL_PLOT_SCRIPT names) with
/// `args`, as run_named_plot_script does.
bool run_plot_script(const std::vector<std::string>& args);

/// Plots of one run: <prefix>_xy.png (truth, plots, track) and
/// <prefix>_error.png (position error over time).
bool plot_run(const std::filesystem::path& steps_csv, const std::filesystem::path& tracks_csv,
              const std::filesystem::path& prefix, const std::string& title, double loss_threshold_m);

/// Mean mode probabilities over the runs of a modes CSV against time, with
/// the truth's manoeuvres (from the steps CSV of run 0) shaded.
bool plot_modes(const std::filesystem::path& modes_csv, const std::filesystem::path& steps_csv,
                const std::filesystem::path& png, const std::string& title);

/// Mean GOSPA and OSPA per step of every associator in a multi_steps.csv
/// (`kestrel-sim run` of a multi-target scenario). @return true only if the PNG was written.
bool plot_gospa(const std::filesystem::path& steps_csv, const std::filesystem::path& png, const std::string& title);

/// Bar chart of the figures in a summary.json, per scenario and filter.
bool plot_summary(const std::filesystem::path& summary_json, const std::filesystem::path& png);

}  // namespace kestrel::sim
