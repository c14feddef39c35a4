// SPDX-License-Identifier: Apache-2.0
// `kestrel-sim timing`: per-step latency of the real-time loop on the host
// (docs/tracking.md), for a radar scenario and filter (a multi-target one:
// the tracker `run` uses for it) or the PCL or sonar tracker on its
// scenario. Runs one job at a time so runs do not compete for the cores;
// every step of every run enters the distribution.
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/scenario_report.hpp"
#include "filters/sensor_settings.hpp"
#include "filters/filter_registry.hpp"
#include "metrics/sonar_metrics.hpp"
#include "montecarlo/monte_carlo.hpp"
#include "montecarlo/pcl_monte_carlo.hpp"
#include "report/results_table.hpp"
#include "scenarios/registry.hpp"
#include "scenarios/sensor_kind.hpp"
#include "timing/step_timing.hpp"

namespace kestrel::sim::cli {

namespace {

/// The PCL or sonar tracker over `o.runs` seeds of a PCL or sonar
/// scenario, one job, with the tracker's keys of --config/--set: the same
/// Monte Carlo as `run`, its step times alone.
StepTiming sensor_scenario_timing(const TimingOptions& o, hal::FrameKind kind, std::string& what) {
  const std::vector<Setting> settings = read_settings(o.filter.config, o.filter.sets);
  if (kind == hal::FrameKind::kPcl) {
    const PclScenarioParams scenario = pcl_config_by_name(o.scenario);
    PclTrackerParams params = pcl_params_for(scenario);
    apply_pcl_settings(settings, params);
    const auto config = monte_carlo_params<PclMonteCarloParams>(o);
    what = scenario.name + " / PCL tracker (" + std::string(kPclFilterName) + ", nn, M-of-N), " +
           std::to_string(o.runs) + " runs";
    return summarise_pcl(run_pcl_monte_carlo(scenario, params, config).runs, config.budget_ns).timing;
  }
  const SonarScenarioParams scenario = sonar_config_by_name(o.scenario);
  SonarTrackerParams params = sonar_params_for(scenario);
  apply_sonar_settings(settings, params);
  const auto config = monte_carlo_params<SonarMonteCarloParams>(o);
  what = scenario.name + " / sonar tracker (" + std::string(kSonarFilterName) + "), " + std::to_string(o.runs) +
         " runs";
  return summarise_sonar(run_sonar_monte_carlo(scenario, params, config).runs, config.budget_ns).timing;
}

/// The step times of o's scenario (a radar one), with the filter of o or,
/// for several targets, the tracker `run` uses for them.
StepTiming radar_scenario_timing(const TimingOptions& o, std::string& what) {
  const auto scenario = make_scenario(o.scenario);
  auto config = monte_carlo_params<MonteCarloParams>(o);
  if (scenario->info().targets > 1) {
    return summarise_step_times(multi_target_step_times(o, what), config.budget_ns);
  }
  const FilterEntry& filter = find_filter(o.filter.filter);
  config.options = o.filter.options;
  what = scenario->info().name + " / " + filter.setup(config.options).label + ", " + std::to_string(o.runs) + " runs";
  return summarise(run_monte_carlo(*scenario, filter, config).runs, config.budget_ns).timing;
}

}  // namespace

int cmd_timing(const TimingOptions& o) {
  if (!o.worst_case.empty()) return cmd_timing_worst_case(o.worst_case, o.runs);
  if (o.scenario.empty()) throw std::invalid_argument("timing needs --scenario or --worst-case");
  const std::optional<hal::FrameKind> kind = scenario_kind(o.scenario);
  std::string what;
  StepTiming timing;
  if (kind.has_value() && *kind != hal::FrameKind::kRadar) {
    check_filter_fits(o.filter, *kind, "scenario '" + o.scenario + "' is a " + sensor_kind_name(*kind) + " scenario");
    timing = sensor_scenario_timing(o, *kind, what);
  } else {
    timing = radar_scenario_timing(o, what);
  }
  print_timing(stdout, what, timing);
  std::printf("  measured by hal::Runner around adapter + Tracker::step with SteadyClock (1 cycle = 1 ns);\n"
              "  wall-clock on a shared host: compare medians, read max as an upper bound only\n");
  return 0;
}

}  // namespace kestrel::sim::cli
