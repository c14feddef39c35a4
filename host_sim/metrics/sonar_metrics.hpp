// SPDX-License-Identifier: Apache-2.0
// UW-003 metrics (docs/scenarios.md and docs/metrics.md), per run and over Monte Carlo runs.
//
// Scored frames: every frame after the one that initialised the track (the
// fix frame itself is not scored; it is frame 0 unless the first fix
// failed), that reached step with status ok. Per run:
//  - 3D, horizontal and depth RMSE over the scored frames, the 3D peak, and
//    the mean position NEES e^T P_pos^-1 e;
//  - the sound-speed error c_hat - c: its mean and standard deviation over
//    the scored frames;
//  - the gate against the truth: true outliers, those gated out (or rejected
//    by the fix), good arrivals gated out, outliers fused.
// Over runs: the mean of each per-run figure with its 95 % interval
// (docs/metrics.md); the sound-speed error std also pooled over every scored frame of
// every run; per-step RMSE curves sqrt(mean over runs of e_k^2).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "metrics/monte_carlo_stats.hpp"
#include "montecarlo/sonar_run.hpp"
#include "pipeline/seeded_runs.hpp"
#include "scenarios/uw003.hpp"
#include "timing/step_timing.hpp"

namespace kestrel::sim {

struct SonarRunMetrics {
  std::uint64_t seed = 0;
  int init_frame = -1;              ///< Frame of the first fix, -1 if none.
  std::size_t scored_frames = 0;
  double rmse_3d_m = 0.0;           ///< NaN when nothing was scored.
  double rmse_h_m = 0.0;
  double rmse_depth_m = 0.0;
  double peak_3d_m = 0.0;
  double nees = 0.0;                ///< Mean position NEES (3 dof).
  double c_err_mean_mps = 0.0;      ///< Mean of c_hat - c.
  double c_err_std_mps = 0.0;       ///< Standard deviation of c_hat - c (population, over the scored frames).
  std::size_t arrivals = 0;         ///< Arrivals in frames that reached step.
  std::size_t outliers = 0;         ///< True outliers among them.
  std::size_t outliers_gated = 0;   ///< True outliers gated out or rejected by the fix.
  std::size_t good_gated = 0;       ///< Good arrivals gated out or rejected.
  std::size_t gated = 0;            ///< All arrivals gated out or rejected.
  std::size_t predict_only = 0;     ///< Tracked frames with nothing fused.
  std::size_t reinitialisations = 0;  ///< Fixes after the first (re-acquisitions).
  std::size_t frames_refused = 0;   ///< Frames with a non-ok status.
  std::size_t depth_reflections = 0;  ///< Truth turned back into the water.
  // Per frame (index k), NaN where not scored.
  std::vector<double> e3_sq, eh_sq, ed_sq, c_err;
  std::vector<std::uint64_t> step_ns;
};

SonarRunMetrics score_sonar_run(const SonarScenarioRun& run, const SonarRunOutput& out);

struct SonarSummary {
  std::size_t runs = 0;
  MeanCi rmse_3d_m, rmse_h_m, rmse_depth_m, peak_3d_m, nees, c_err_std_mps, c_err_mean_mps;
  double pooled_c_err_std_mps = 0.0;   ///< Std of c_hat - c over every scored frame of every run.
  double pooled_c_err_mean_mps = 0.0;
  std::size_t runs_not_initialised = 0;  ///< No fix in the whole run.
  std::size_t runs_late_init = 0;        ///< First fix after frame 0.
  std::size_t arrivals = 0, outliers = 0, outliers_gated = 0, good_gated = 0, gated = 0;
  std::size_t predict_only = 0, reinitialisations = 0, frames_refused = 0, depth_reflections = 0;
  std::vector<double> step_rmse_3d_m, step_rmse_h_m, step_rmse_depth_m, step_c_err_rms_mps;
  std::vector<std::size_t> step_runs;    ///< Runs scored at each frame.
  StepTiming timing;
};

SonarSummary summarise_sonar(const std::vector<SonarRunMetrics>& runs, std::uint64_t budget_ns);

struct SonarMonteCarloParams {
  std::size_t runs = 200;
  std::uint64_t base_seed = 0;   ///< Run i uses seed base_seed + i.
  unsigned jobs = 1;
  std::uint64_t budget_ns = 1'000'000;
};

using SonarMonteCarloResult = SeededRuns<SonarRunMetrics, SonarScenarioRun, SonarRunOutput>;

/// Runs are independent and each writes its own slot: the figures do not
/// depend on `jobs` (step times do).
SonarMonteCarloResult run_sonar_monte_carlo(const SonarScenarioParams& scenario, const SonarTrackerParams& params,
                                            const SonarMonteCarloParams& config);

}  // namespace kestrel::sim
