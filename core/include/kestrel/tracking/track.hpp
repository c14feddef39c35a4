// SPDX-License-Identifier: Apache-2.0
// One track of the table and the report every tracker publishes for it,
// whatever the sensor kind (docs/tracking.md: stable id, status, age, hit/miss
// counters and the last innovation statistics, per channel in the one
// diagnostics record FusionDiagnostics).
#pragma once

#include <cstdint>

#include "kestrel/filters/innovation.hpp"
#include "kestrel/tracking/track_table.hpp"

namespace kestrel {

/// A track manager's verdict on one track after a frame.
enum class TrackVerdict : std::uint8_t {
  kKeep,     ///< Nothing changes.
  kConfirm,  ///< A tentative track becomes confirmed.
  kDelete,   ///< The track is deleted.
  /// The track is lost: start it again from the plot it took this frame,
  /// with the initiator, if that start fuses more of the plot than the
  /// track did (a new id; otherwise it is kept as it is).
  kRestart,
};

template <class Filter>
struct Track {
  using Scalar = typename Filter::Scalar;
  using MeasVec = typename Filter::MeasVec;

  Filter filter{};                     ///< Estimator; valid once `initialised`.
  std::uint32_t id = 0;                ///< Stable for the track's life, never 0.
  TrackStatus status = TrackStatus::kFree;
  bool initialised = false;            ///< false: a seed holding one measurement only.
  std::int64_t t_us = 0;               ///< Time of the filter state (or of the seed), us.
  MeasVec seed{};                      ///< First measurement while not initialised.
  std::uint16_t age = 0;               ///< Frames since the track started.
  std::uint16_t hits = 0;              ///< Measurements associated in total.
  std::uint16_t misses = 0;            ///< Consecutive frames without a measurement.
  std::uint8_t history = 0;            ///< Association history, bit 0 = latest frame.
  bool associated = false;             ///< A measurement was used in the latest frame.
  /// Index in the latest scan of the measurement the track took, -1 if
  /// none (a channel filter may take one and fuse none of its channels:
  /// then `associated` is false).
  std::int16_t measurement_index = -1;
  std::uint16_t lost_frames = 0;       ///< Frames in a row a manager judged lost (ReacquireWhenLost); fills padding.
  Scalar nis{};                        ///< nu^T S^-1 nu of the latest association, as the gate tested it.
  Scalar test_ratio{};                 ///< nis / association gate threshold (<= 1 inside).
  Scalar score{};                      ///< Track score of a score-based manager (SequentialLlr), 0 otherwise.
  Scalar score_peak{};                 ///< Highest score so far.
};

/// What the tracker publishes per reported track and frame.
template <class Filter>
struct TrackReport {
  using Scalar = typename Filter::Scalar;
  using State = typename Filter::State;
  using Cov = typename Filter::Cov;
  using MeasVec = typename Filter::MeasVec;

  std::int64_t t_us = 0;               ///< Frame time, microseconds.
  std::uint32_t track_id = 0;          ///< Stable track id.
  TrackStatus status = TrackStatus::kFree;
  std::uint16_t age = 0;               ///< Frames since start.
  std::uint16_t hits = 0;              ///< Measurements associated in total.
  std::uint16_t misses = 0;            ///< Consecutive misses.
  bool associated = false;             ///< Updated in this frame.
  std::int16_t measurement_index = -1; ///< Scan entry taken in this frame, -1 if none (see Track).
  /// NIS of the latest association (this frame's if associated) as the
  /// association gate tested it: nu^T S^-1 nu with the S predicted before
  /// the plot was seen, the predictive consistency test.
  Scalar nis{};
  Scalar test_ratio{};                 ///< nis / association gate threshold (0: no gate).
  /// The filter's latest update attempt (this frame's if associated), per
  /// channel: nu_i, S_ii, test ratio where a channel gate ran, present /
  /// rejected / fused channels, the NIS of the update as fused, its status
  /// (a refused update shows here with fused == false). Every filter keeps
  /// this record (TrackingFilter::diagnostics()); the track stores no copy.
  /// fusion.nis is nis for the EKF (to rounding in its sequential form); a
  /// filter that adapts R to the plot (R2-AEKF) fuses with another S, so
  /// its fusion.nis is not the predictive test.
  FusionDiagnostics<Scalar, Filter::kMeasDim> fusion{};
  Scalar score{};                      ///< Track score (SequentialLlr), 0 under M-of-N.
  State x{};                           ///< State estimate, motion-model layout.
  Cov P{};                             ///< State covariance.
};

}  // namespace kestrel
