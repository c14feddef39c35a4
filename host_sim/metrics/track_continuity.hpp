// SPDX-License-Identifier: Apache-2.0
// Track continuity of a single-target run (docs/robustness.md): does the
// tracker hold the target with one confirmed track from its first
// confirmation to the end, or does it lose it, split it or restart it?
// Kept free of tracker types, like run_metrics.hpp: the input per scored
// frame is the ids of the confirmed tracks within L of the truth.
//
//  - Frames after confirmation: scored frames from the first one that has
//    a confirmed track within L, to the end of the run.
//  - Held frames: those with exactly one confirmed track within L (none is
//    a loss, two are a split or a duplicate).
//  - Track ids on target: distinct ids that were ever within L; a drop and
//    restart, or a split, makes it more than one.
//  - False tracks: distinct ids of confirmed tracks never within L in the
//    scored frames (a track started from clutter or outliers).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace kestrel::sim {

/// One scored frame: the confirmed tracks within L of the truth, and the
/// others.
struct OnTargetTracks {
  std::vector<std::uint32_t> ids;      ///< Ids of the confirmed tracks within L.
  std::vector<std::uint32_t> off_ids;  ///< Ids of the confirmed tracks beyond L.
};

struct TrackContinuity {
  std::size_t frames_after_confirmation = 0;  ///< 0 if no track was ever on target.
  std::size_t held_frames = 0;                ///< With exactly one confirmed track on target.
  double held_fraction = 0.0;                 ///< held / after confirmation; NaN if none after.
  std::size_t track_ids_on_target = 0;        ///< Distinct ids ever within L.
  std::size_t false_tracks = 0;               ///< Distinct confirmed ids never within L.
};

TrackContinuity compute_track_continuity(std::span<const OnTargetTracks> steps);

}  // namespace kestrel::sim
