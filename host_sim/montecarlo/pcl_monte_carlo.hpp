// SPDX-License-Identifier: Apache-2.0
// Monte Carlo over seeds for the PCL scenarios (docs/scenarios.md and docs/metrics.md):
// run i uses seed base_seed + i for both the drone's manoeuvre and the
// frames. Runs are independent and each writes only its own slot, so the
// figures do not depend on the number of worker threads (step times do).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "kestrel/tracking/pcl_tracker.hpp"
#include "metrics/pcl_metrics.hpp"
#include "montecarlo/pcl_run.hpp"
#include "pipeline/seeded_runs.hpp"
#include "scenarios/pcl002.hpp"

namespace kestrel::sim {

struct PclMonteCarloParams {
  std::size_t runs = 200;
  std::uint64_t base_seed = 0;
  unsigned jobs = 1;
  std::uint64_t budget_ns = 1'000'000;  ///< Step overrun threshold.
  TrackerPolicies policies;             ///< Associator and track manager.
  PclTolerance tolerance;
};

using PclMonteCarloResult = SeededRuns<PclRunMetrics, PclScenarioRun, PclRunOutput>;

PclMonteCarloResult run_pcl_monte_carlo(const PclScenarioParams& scenario, const PclTrackerParams& params,
                                        const PclMonteCarloParams& config);

}  // namespace kestrel::sim
