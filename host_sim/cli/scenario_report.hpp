// SPDX-License-Identifier: Apache-2.0
// Run one scenario with one filter over N seeds and write its files
// (report/run_files.hpp) into a directory: the shared body of `run` and
// `suite`.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "montecarlo/monte_carlo.hpp"
#include "report/results_table.hpp"

namespace kestrel::sim::cli {

struct ScenarioReport {
  TableRow row;
  nlohmann::json entry;  ///< summary.json entry.
  std::string label;     ///< The filter and its parameters ("EKF-CA (double), qj 160").
  std::filesystem::path plot_prefix;  ///< <prefix>_xy.png, <prefix>_error.png
  bool plotted = false;  ///< Both figures written by this run.
  bool modes_written = false;  ///< <filter>_modes.csv written (a filter with modes).
  bool modes_plotted = false;  ///< <prefix>_modes.png written by this run.
};

/// `tag` names the files and the summary entry (default: the filter's
/// name), so one filter can run twice with different options.
ScenarioReport run_scenario_report(const std::string& scenario_name, const std::string& filter_name,
                                   const MonteCarloParams& config, const std::filesystem::path& out_dir,
                                   bool plots, const std::string& tag = {});

/// Step budget in ns from microseconds (CLI unit).
std::uint64_t budget_ns_from_us(double budget_us);

/// A command's --runs, --seed, --jobs (one job for a command without it,
/// such as `timing`) and --budget-us as the Monte Carlo parameters of its
/// scenario's kind (MonteCarloParams, PclMonteCarloParams and
/// SonarMonteCarloParams name them alike). Throws std::invalid_argument
/// for 0 runs or a budget that is not positive.
template <class Params, class Options>
Params monte_carlo_params(const Options& o) {
  if (o.runs == 0) throw std::invalid_argument("--runs must be at least 1");
  Params c;
  c.runs = o.runs;
  c.base_seed = o.seed;
  if constexpr (requires { o.jobs; }) {
    c.jobs = o.jobs;
  } else {
    c.jobs = 1;
  }
  c.budget_ns = budget_ns_from_us(o.filter.budget_us);
  return c;
}

}  // namespace kestrel::sim::cli
