// SPDX-License-Identifier: Apache-2.0
// `kestrel-sim timing`: per-step latency of the real-time loop on the host
// (docs/tracking.md). Runs one job at a time so runs do not compete for the
// cores; every step of every run enters the distribution.
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "cli/commands.hpp"
#include "cli/scenario_report.hpp"
#include "filters/filter_registry.hpp"
#include "montecarlo/monte_carlo.hpp"
#include "report/results_table.hpp"
#include "scenarios/registry.hpp"
#include "scenarios/sensor_kind.hpp"

namespace kestrel::sim::cli {

int cmd_timing(const TimingOptions& o) {
  if (!o.worst_case.empty()) return cmd_timing_worst_case(o.worst_case, o.runs);
  if (o.scenario.empty()) throw std::invalid_argument("timing needs --scenario or --worst-case");
  const std::optional<hal::FrameKind> kind = scenario_kind(o.scenario);
  if (kind.has_value() && *kind != hal::FrameKind::kRadar) {
    throw std::invalid_argument("timing runs radar scenarios; '" + o.scenario + "' is a " + sensor_kind_name(*kind) +
                                " scenario, whose step times `kestrel-sim run -s " + o.scenario + "` prints");
  }
  const auto scenario = make_scenario(o.scenario);
  const FilterEntry& filter = find_filter(o.filter.filter);
  MonteCarloConfig config;
  config.runs = o.runs;
  config.base_seed = o.seed;
  config.jobs = 1;
  config.budget_ns = budget_ns_from_us(o.filter.budget_us);
  config.options = o.filter.options;
  if (config.runs == 0) throw std::invalid_argument("--runs must be at least 1");

  const MonteCarloResult mc = run_monte_carlo(*scenario, filter, config);
  const MonteCarloSummary s = summarise(mc.runs, config.budget_ns);
  const std::string what = scenario->info().name + " / " + filter.setup(config.options).label + ", " +
                           std::to_string(o.runs) + " runs";
  print_timing(stdout, what, s.timing);
  std::printf("  measured by hal::Runner around adapter + Tracker::step with SteadyClock (1 cycle = 1 ns);\n"
              "  wall-clock on a shared host: compare medians, read max as an upper bound only\n");
  return 0;
}

}  // namespace kestrel::sim::cli
