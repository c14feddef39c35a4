// SPDX-License-Identifier: Apache-2.0
// The R2-AEKF reproduction study of paper 000 (docs/r2aekf.md):
// everything the results page needs, from one command
// (`kestrel-sim r2aekf-study`):
//   1. the tuned EKF-CA baseline: qj chosen once for all four scenarios
//      from a small grid, on seeds disjoint from the reported ones, by the
//      smallest mean RMSE over the scenarios;
//   2. the five-row table per scenario (EKF-CA qj 1.6, EKF-CA tuned qj,
//      R2-AEKF paper mode, R2-AEKF default mode, paper table 2 ratios),
//      each figure the Monte Carlo mean with its 95 % interval;
//   3. a one-at-a-time sensitivity table (tau0, rho, alphaQ, deltaQ);
//   4. per-step cost of EKF-CA and both R2-AEKF modes measured side by
//      side in one run (tracker step through the HAL, and the bare
//      predict + update);
//   5. run-0 files (steps CSV per filter, per-step scale CSV) and the
//      paper-like figures 2-5 (plots/r2aekf_plots.py).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace kestrel::sim {

struct R2AekfStudyOptions {
  std::vector<std::string> scenarios{"s1", "s2", "s1n", "s2n"};
  std::size_t runs = 200;             ///< Monte Carlo runs per scenario and filter.
  std::uint64_t seed = 0;             ///< Seed of run 0 of the reported runs.
  unsigned jobs = 1;                  ///< Worker threads (results do not depend on it).
  std::string out = "results/r2aekf"; ///< Output directory.
  std::vector<double> qj_grid{1.6, 5.0, 16.0, 50.0, 160.0, 500.0};  ///< EKF-CA tuning grid, m^2/s^5.
  std::size_t select_runs = 50;       ///< Runs per scenario for the qj choice.
  std::uint64_t select_seed = 100000; ///< Seed of the selection runs (disjoint from the reported ones).
  std::size_t sensitivity_runs = 200; ///< Runs per scenario and variant (0: skip).
  std::size_t timing_runs = 20;       ///< Runs of S1 timed side by side (0: skip).
  double budget_us = 1000.0;          ///< Step budget (overrun count only).
  bool plots = true;
};

/// Run the study, print the tables and write the files under options.out.
/// Returns the exit status.
int run_r2aekf_study(const R2AekfStudyOptions& options);

}  // namespace kestrel::sim
