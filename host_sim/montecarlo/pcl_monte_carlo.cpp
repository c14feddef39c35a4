// SPDX-License-Identifier: Apache-2.0
#include "montecarlo/pcl_monte_carlo.hpp"

namespace kestrel::sim {

PclMonteCarloResult run_pcl_monte_carlo(const PclScenarioParams& scenario, const PclTrackerParams& params,
                                        const PclMonteCarloParams& config) {
  return run_seeded<PclMonteCarloResult>(
      config.runs, config.base_seed, config.jobs, scenario.name.c_str(),
      [&](std::uint64_t seed) { return generate_pcl(scenario, seed); },
      [&](const PclScenarioRun& run) { return run_pcl(run, scenario, params, config.policies, config.budget_ns); },
      [&](const PclScenarioRun& run, const PclRunOutput& out) { return score_pcl_run(run, out, config.tolerance); });
}

}  // namespace kestrel::sim
