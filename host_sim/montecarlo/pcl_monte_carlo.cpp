// SPDX-License-Identifier: Apache-2.0
#include "montecarlo/pcl_monte_carlo.hpp"

#include <algorithm>
#include <utility>

#include "pipeline/worker_pool.hpp"

namespace kestrel::sim {

PclMonteCarloResult run_pcl_monte_carlo(const PclScenarioParams& scenario, const PclTrackerParams& params,
                                        const PclMonteCarloParams& config) {
  PclMonteCarloResult result;
  result.runs.resize(config.runs);
  for_each_index(
      config.runs, config.jobs,
      [&](std::size_t i) {
        const std::uint64_t seed = config.base_seed + i;
        PclScenarioRun run = generate_pcl(scenario, seed);
        PclRunOutput out = run_pcl(run, scenario, params, config.policies, config.budget_ns);
        result.runs[i] = score_pcl_run(run, out, config.tolerance);
        result.runs[i].seed = seed;
        if (i == 0) {  // only the worker that takes i == 0 writes these
          result.first_run = std::move(run);
          result.first_output = std::move(out);
        }
      },
      Progress{scenario.name.c_str()});
  return result;
}

}  // namespace kestrel::sim
