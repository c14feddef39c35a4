// SPDX-License-Identifier: Apache-2.0
#include "cli/scenario_report.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "csv/step_csv.hpp"
#include "filters/filter_registry.hpp"
#include "plots/plot_runner.hpp"
#include "report/run_files.hpp"
#include "report/summary_json.hpp"
#include "scenarios/registry.hpp"

namespace kestrel::sim::cli {

std::uint64_t budget_ns_from_us(double budget_us) {
  if (!(budget_us > 0.0) || !std::isfinite(budget_us)) throw std::invalid_argument("--budget-us must be positive");
  return static_cast<std::uint64_t>(std::llround(budget_us * 1000.0));
}

ScenarioReport run_scenario_report(const std::string& scenario_name, const std::string& filter_name,
                                   const MonteCarloParams& config, const std::filesystem::path& out_dir,
                                   bool plots, const std::string& tag) {
  const auto scenario = make_scenario(scenario_name);
  const FilterEntry& filter = find_filter(filter_name);
  const ScenarioInfo& info = scenario->info();
  if (filter.kind != info.kind) {
    throw std::invalid_argument("filter '" + std::string(filter.name) + "' does not take the frames of scenario '" +
                                info.name + "'");
  }
  if (config.runs == 0) throw std::invalid_argument("--runs must be at least 1");

  const MonteCarloResult mc = run_monte_carlo(*scenario, filter, config);
  ScenarioReport report;
  const std::string name = tag.empty() ? std::string(filter.name) : tag;
  report.row = TableRow{info.name, name, summarise(mc.runs, config.budget_ns)};

  EntryContext context;
  context.scenario = info.name;
  context.filter = std::string(filter.name);
  context.setup = filter.setup(config.options);
  context.base_seed = config.base_seed;
  context.frame_period_s = info.frame_period_s;
  context.loss_threshold_m = info.loss_threshold_m;
  context.first_scored_step = config.scoring.first_scored_step;
  context.jobs = config.jobs;
  report.entry = summary_entry(context, report.row.summary);

  std::filesystem::create_directories(out_dir);
  const RunFileNames names = run_file_names(out_dir, name);
  write_track_csv(names.tracks_csv, mc.first.stream);
  write_step_csv(names.steps_csv, mc.first.steps, mc.first.frames, info.loss_threshold_m);
  write_runs_csv(names.runs_csv, mc.runs);
  report.modes_written = write_modes_csv(names.modes_csv, mc.runs, mc.first.stream.mode_names);
  merge_summary_file(out_dir / "summary.json", context.scenario, name, report.entry);
  report.label = context.setup.label;
  report.plot_prefix = names.plot_prefix;
  if (plots) {
    report.plotted = plot_run(names.steps_csv, names.tracks_csv, names.plot_prefix,
             info.name + " / " + context.setup.label + " / seed " + std::to_string(config.base_seed),
             info.loss_threshold_m);
    if (report.modes_written) {
      report.modes_plotted =
          plot_modes(names.modes_csv, names.steps_csv, names.plot_prefix.string() + "_modes.png",
                     info.name + " / " + name + " / seeds " + std::to_string(config.base_seed) + "+");
    }
  }
  return report;
}

}  // namespace kestrel::sim::cli
