// SPDX-License-Identifier: Apache-2.0
#include "montecarlo/pcl_monte_carlo.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>

namespace kestrel::sim {

PclMonteCarloResult run_pcl_monte_carlo(const PclScenarioConfig& scenario, const PclTrackerParams& params,
                                        const PclMonteCarloConfig& config) {
  PclMonteCarloResult result;
  result.runs.resize(config.runs);
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;

  const auto worker = [&] {
    for (;;) {
      const std::size_t i = next.fetch_add(1);
      if (i >= config.runs) return;
      try {
        const std::uint64_t seed = config.base_seed + i;
        PclScenarioRun run = generate_pcl(scenario, seed);
        PclRunOutput out = run_pcl(run, scenario, params, config.policies, config.budget_ns);
        result.runs[i] = score_pcl_run(run, out, config.tolerance);
        result.runs[i].seed = seed;
        if (i == 0) {  // only the worker that takes i == 0 writes these
          result.first_run = std::move(run);
          result.first_output = std::move(out);
        }
      } catch (...) {
        const std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        next = config.runs;
      }
    }
  };
  const unsigned jobs =
      std::max(1u, std::min<unsigned>(config.jobs, static_cast<unsigned>(std::max<std::size_t>(config.runs, 1))));
  if (jobs == 1) {
    worker();
  } else {
    std::vector<std::thread> threads;
    for (unsigned j = 0; j < jobs; ++j) threads.emplace_back(worker);
    for (std::thread& t : threads) t.join();
  }
  if (failure) std::rethrow_exception(failure);
  return result;
}

}  // namespace kestrel::sim
