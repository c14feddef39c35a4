// SPDX-License-Identifier: Apache-2.0
// Scoring a run against truth, frame by frame (docs/metrics.md).
//
// Which estimate is scored: at each frame, the confirmed track nearest to
// the truth (with one target and no clutter there is at most one). Frames
// that did not decode, that the tracker refused (their status is in the
// run's status table), or that have no truth at their time are not scored. Frames before `first_scored_step` (k >= 2 with two-point
// initiation: frame 0 seeds, frame 1 initialises, frame 2 is the first
// predict + update) are not scored either.
//
// A scored frame with no confirmed track has no estimate: it counts as lost
// (track-loss time and episodes), and has no error, so it is left out of
// RMSE, peak, NEES and NIS; the run reports how many such frames it had
// (missing_steps) so that leaving them out never hides a dropped track.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "kestrel/host/track_row.hpp"
#include "pipeline/stream_run_result.hpp"
#include "scenarios/scenario.hpp"

namespace kestrel::sim {

/// One scored frame.
struct ScoredStep {
  std::size_t k = 0;                       ///< Frame index in the stream.
  double t_s = 0.0;                        ///< Frame time, s.
  TruthSample truth;                       ///< Truth at t_s.
  std::optional<host::TrackRow> estimate;  ///< Scored confirmed track, if any.
  std::size_t confirmed_tracks = 0;        ///< Confirmed tracks reported in this frame.
  std::optional<double> error_m;           ///< e_k = |p_hat - p|, m (if estimate).
  double nees = 0.0;                       ///< e^T P_pos^-1 e (NaN without estimate).
  double nis = 0.0;                        ///< NIS of the scored track's update (NaN if it coasted).
};

struct ScoringParams {
  std::size_t first_scored_step = 2;  ///< Frames k < this are not scored.
};

/// Position NEES e^T P^-1 e for a 2x2 covariance [[p_xx, p_xy], [p_xy, p_yy]];
/// NaN when P is not positive definite.
double position_nees(double ex, double ey, double p_xx, double p_xy, double p_yy);

/// Score every frame that reached the tracker and has truth at its time
/// (matched to the microsecond).
std::vector<ScoredStep> score_run(const StreamRunResult& run, const std::vector<TruthSample>& truth,
                                  const ScoringParams& config);

}  // namespace kestrel::sim
