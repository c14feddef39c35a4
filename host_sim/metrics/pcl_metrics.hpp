// SPDX-License-Identifier: Apache-2.0
// PCL-002 metrics, per run and over Monte Carlo runs (docs/metrics.md and
// docs/pcl.md, "Metrics"): a track is on the target in a frame when
// |Rb_hat - Rb| <= 50 m and |dRb_hat - dRb| <= 5 m/s, and a confirmed track
// is a target track when it is on the target in more than half of the
// frames it was reported confirmed (judged over its whole life, so a target
// track dragged onto clutter stays in the accuracy denominator); every other
// confirmed track is a false confirmed track. From these: association
// accuracy, coverage after confirmation, Rb and dRb RMSE and time to first
// confirmation, averaged over runs with a 95 % interval, accuracy and
// coverage also pooled. The exact definitions are in docs/pcl.md.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "metrics/monte_carlo_stats.hpp"
#include "montecarlo/pcl_run.hpp"
#include "scenarios/pcl002.hpp"
#include "timing/step_timing.hpp"

namespace kestrel::sim {

struct PclTolerance {
  double rb_m = 50.0;    ///< |Rb_hat - Rb| bound, m.
  double drb_mps = 5.0;  ///< |dRb_hat - dRb| bound, m/s.
};

struct PclRunMetrics {
  std::uint64_t seed = 0;
  std::size_t assoc_correct = 0;     ///< Numerator of association accuracy.
  std::size_t assoc_frames = 0;      ///< Its denominator.
  double association_accuracy = 0.0; ///< NaN when assoc_frames == 0.
  std::size_t covered_frames = 0;    ///< Numerator of coverage.
  std::size_t coverage_frames = 0;   ///< Its denominator.
  double coverage = 0.0;             ///< NaN when no target track was confirmed.
  std::size_t confirmed_tracks = 0;  ///< Distinct confirmed tracks.
  std::size_t target_tracks = 0;     ///< Of which target tracks.
  std::size_t false_tracks = 0;      ///< Of which false.
  std::size_t rmse_frames = 0;       ///< Frames in the RMSE.
  double rb_rmse_m = 0.0;            ///< NaN when rmse_frames == 0.
  double drb_rmse_mps = 0.0;         ///< NaN when rmse_frames == 0.
  double time_to_confirm_s = 0.0;    ///< NaN when no target track was confirmed.
  std::size_t detections = 0;        ///< Frames with a target detection in the wire frame.
  std::size_t cut_by_adapter = 0;    ///< Of those, frames where the adapter dropped it.
  std::size_t cut_by_sensor = 0;     ///< Detections lost to the 64-candidate wire cut (not in the frame).
  std::size_t refused_starts = 0;    ///< Track starts the zero-Doppler veto refused.
  std::size_t dropped_starts = 0;    ///< Track starts lost to a full table.
  std::size_t max_tracks_in_table = 0;  ///< Most table slots in use after a step.
  std::size_t frames_over_capacity = 0;  ///< Frames with kTooManyCandidates.
  std::size_t frames_refused = 0;    ///< Frames that did not reach step or step refused.
  std::vector<std::uint64_t> step_ns;
};

PclRunMetrics score_pcl_run(const PclScenarioRun& run, const PclRunOutput& out, const PclTolerance& tol);

struct PclSummary {
  std::size_t runs = 0;
  MeanCi association_accuracy, coverage, false_tracks, rb_rmse_m, drb_rmse_mps, time_to_confirm_s;
  double pooled_accuracy = 0.0;      ///< Sum of numerators / sum of denominators.
  double pooled_coverage = 0.0;
  std::size_t runs_never_confirmed = 0;   ///< Runs with no target track.
  std::size_t runs_with_false_track = 0;
  std::size_t total_false_tracks = 0;
  std::size_t detections = 0, cut_by_adapter = 0, cut_by_sensor = 0, frames_over_capacity = 0, frames_refused = 0;
  std::size_t refused_starts = 0, dropped_starts = 0, max_tracks_in_table = 0;
  StepTiming timing;
};

PclSummary summarise_pcl(const std::vector<PclRunMetrics>& runs, std::uint64_t budget_ns);

}  // namespace kestrel::sim
