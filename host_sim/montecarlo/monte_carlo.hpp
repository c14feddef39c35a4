// SPDX-License-Identifier: Apache-2.0
// Monte Carlo over seeds (docs/metrics.md): run i uses seed base_seed + i.
// Runs are independent and each writes only its own slot, so the results
// are identical whatever the number of worker threads; only the step times
// change (several runs share the cores), which is why `timing` uses one job.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "filters/filter_registry.hpp"
#include "metrics/monte_carlo_stats.hpp"
#include "montecarlo/single_run.hpp"
#include "scenarios/scenario.hpp"
#include "timing/step_timing.hpp"

namespace kestrel::sim {

struct MonteCarloParams {
  std::size_t runs = 20;
  std::uint64_t base_seed = 0;
  unsigned jobs = 1;                ///< Worker threads (>= 1).
  std::uint64_t budget_ns = 1'000'000;  ///< Step overrun threshold.
  FilterOptions options;
  ScoringParams scoring;
};

/// The mode probabilities of the scored track at one scored step.
struct ModeSample {
  double t_s = 0.0;            ///< Frame time, s.
  std::uint32_t track_id = 0;  ///< The scored track.
  std::vector<double> mu;      ///< In the order of StreamRunResult::mode_names.
};

/// The compact record of one run (the full detail is kept for run 0 only).
struct RunRecord {
  std::uint64_t seed = 0;
  RunMetrics metrics;
  std::vector<std::uint64_t> step_ns;  ///< Every timed step of the run.
  std::size_t max_confirmed_tracks = 0;  ///< Most confirmed tracks in one scored frame.
  std::size_t track_switches = 0;      ///< Scored frames whose track id differs from the previous scored one.
  std::size_t frames_not_ok = 0;       ///< Frames whose final status was not kOk.
  TrackContinuity continuity;          ///< One track on the target from confirmation on?
  std::vector<ModeSample> modes;       ///< Per scored step with a track, for filters with modes (IMM).
};

struct MonteCarloResult {
  std::vector<RunRecord> runs;  ///< In seed order.
  RunDetail first;              ///< Everything about run 0 (for the CSVs and plots).
};

/// Mean and interval of each figure over runs.
struct MonteCarloSummary {
  MeanCi rmse_m, peak_m, nees_pos, nis, track_loss_s, recovery_s;
  std::size_t runs = 0;
  std::size_t runs_without_loss = 0;  ///< Runs with no lost episode.
  std::size_t runs_with_missing = 0;  ///< Runs with a scored frame without a confirmed track.
  std::size_t missing_steps = 0;      ///< Such frames, over all runs.
  std::size_t max_confirmed_tracks = 0;
  MeanCi track_switches;              ///< Changes of the scored track's id per run.
  std::size_t frames_not_ok = 0;
  // Track continuity (metrics/track_continuity.hpp), per run then over runs.
  MeanCi held_fraction;               ///< Frames after confirmation with one confirmed track on target.
  double worst_held_fraction = 0.0;   ///< Lowest held fraction of any run (NaN if none).
  MeanCi loss_episodes;               ///< Lost episodes per run.
  MeanCi track_ids_on_target;         ///< Distinct confirmed track ids within L per run.
  std::size_t max_track_ids_on_target = 0;
  MeanCi false_tracks;                ///< Confirmed tracks never within L per run.
  StepTiming timing;                  ///< Over every step of every run.
};

RunRecord record_of(const RunDetail& detail);

MonteCarloResult run_monte_carlo(const Scenario& scenario, const FilterEntry& filter, const MonteCarloParams& config);

MonteCarloSummary summarise(const std::vector<RunRecord>& runs, std::uint64_t budget_ns);

}  // namespace kestrel::sim
