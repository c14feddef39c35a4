// SPDX-License-Identifier: Apache-2.0
// Run one scenario with one filter over N seeds and write its files
// (report/run_files.hpp) into a directory: the shared body of `run` and
// `suite`.
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "montecarlo/monte_carlo.hpp"
#include "report/results_table.hpp"

namespace kestrel::sim::cli {

struct ScenarioReport {
  TableRow row;
  nlohmann::json entry;  ///< summary.json entry.
};

ScenarioReport run_scenario_report(const std::string& scenario_name, const std::string& filter_name,
                                   const MonteCarloConfig& config, const std::filesystem::path& out_dir,
                                   bool plots);

/// Step budget in ns from microseconds (CLI unit).
std::uint64_t budget_ns_from_us(double budget_us);

}  // namespace kestrel::sim::cli
