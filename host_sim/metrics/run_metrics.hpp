// SPDX-License-Identifier: Apache-2.0
// Per-run figures of docs/metrics.md, computed from a sequence of per-step
// errors. Kept free of tracker types so tests can feed hand-made sequences.
//
//  - RMSE: sqrt(mean e_k^2) over steps that have an estimate; peak: max e_k.
//  - NEES: mean position NEES; NIS: mean NIS over steps that updated.
//  - Track-loss time: T x (steps with e_k > L, or with no estimate).
//  - Lost episode: from the first lost step to the first step back under L;
//    one still open at the end of the run is closed there. Its length is
//    T x its lost steps, so loss time = sum of episode lengths.
//  - Recovery time of a run: the mean length of its episodes (NaN if none).
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace kestrel::sim {

/// The per-step inputs of the run metrics.
struct StepError {
  std::optional<double> error_m;  ///< e_k, m; empty = no estimate (counts as lost).
  double nees = 0.0;              ///< Position NEES; NaN if unavailable.
  double nis = 0.0;               ///< NIS; NaN if the step did not update.
};

/// A lost episode: [first_step, end_step) in indices of the input sequence.
struct LossEpisode {
  std::size_t first_step = 0;
  std::size_t end_step = 0;  ///< First step back under L, or the sequence length if still open.
  bool open_at_end = false;  ///< Closed by the end of the run, not by recovery.
};

struct RunMetrics {
  double rmse_m = 0.0;        ///< NaN if no step had an estimate.
  double peak_m = 0.0;        ///< NaN if no step had an estimate.
  double nees_pos = 0.0;      ///< NaN if no step had a NEES.
  double nis = 0.0;           ///< NaN if no step updated.
  double track_loss_s = 0.0;  ///< T x lost steps, s.
  double recovery_s = 0.0;    ///< Mean episode length, s; NaN without episodes.
  std::size_t scored_steps = 0;   ///< Steps in the sequence.
  std::size_t missing_steps = 0;  ///< Steps without an estimate.
  std::size_t lost_steps = 0;     ///< Steps over L or without an estimate.
  std::vector<LossEpisode> episodes;
};

/// @param period_s T, the frame period, s.
/// @param loss_threshold_m L, m.
RunMetrics compute_run_metrics(std::span<const StepError> steps, double period_s, double loss_threshold_m);

}  // namespace kestrel::sim
