// SPDX-License-Identifier: Apache-2.0
// Multi-target metrics (docs/metrics.md): OSPA (Schuhmacher, Vo and Vo
// 2008) and GOSPA with alpha = 2 (Rahmathullah, Garcia-Fernandez and
// Svensson 2017) between the true positions and the confirmed tracks of a
// step, with cut-off c and order p; and, from the GOSPA assignment of
// every step, track swaps, false confirmed tracks, track fragmentation and
// time to confirm, as Stone Soup's and MATLAB's track assignment metrics
// count them. Both assignments are solved exactly with the core's
// assignment solver (association/gnn.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace kestrel::sim {

struct Position2 {
  double x_m = 0.0;
  double y_m = 0.0;
};

struct SpaParams {
  double cutoff_m = 500.0;  ///< c: a localisation error counts at most c; a miss or a false track c / 2^(1/p) (GOSPA).
  double order = 2.0;       ///< p.
};

/// GOSPA with alpha = 2 and its decomposition: gospa^p = localisation^p
/// + (missed + false) * c^p / 2.
struct Gospa {
  double gospa = 0.0;            ///< The metric, m.
  double localisation_p = 0.0;   ///< Sum of d^p over the assigned pairs (d < c), m^p.
  std::size_t missed = 0;        ///< Truths left unassigned.
  std::size_t false_tracks = 0;  ///< Tracks left unassigned.
  /// assignment[i]: the track assigned to truth i, or -1.
  std::vector<int> assignment;
};

/// GOSPA (alpha = 2) between truths and tracks: the assignment of pairs
/// closer than c minimising the sum of d^p plus c^p/2 per unassigned truth
/// or track. Both empty: 0.
Gospa gospa(std::span<const Position2> truths, std::span<const Position2> tracks, const SpaParams& c);

/// OSPA: ((min over assignments of the smaller set into the larger of the
/// sum of min(d, c)^p) + c^p * (n - m)) / n)^(1/p), with m <= n the set
/// sizes; 0 if both are empty, c if one is.
double ospa(std::span<const Position2> truths, std::span<const Position2> tracks, const SpaParams& c);

/// One step of a run: every target's true position (all targets exist in
/// every step) and the confirmed tracks reported.
struct MultiTargetStep {
  double t_s = 0.0;
  std::vector<Position2> truths;
  std::vector<std::uint32_t> track_ids;
  std::vector<Position2> tracks;  ///< tracks[n] is track track_ids[n].
};

/// Per-run figures of docs/metrics.md.
struct MultiTargetRunMetrics {
  std::vector<double> gospa_m;  ///< Per step.
  std::vector<double> ospa_m;   ///< Per step.
  double mean_gospa_m = 0.0;
  double mean_ospa_m = 0.0;
  double mean_gospa_localisation_m = 0.0;  ///< Mean of (localisation_p)^(1/p) per step.
  double mean_missed = 0.0;                ///< Mean unassigned truths per step.
  double mean_false = 0.0;                 ///< Mean unassigned tracks per step.
  /// Times a track's assigned truth changed from one target to another
  /// and the new one held for `persistence_steps` assigned steps in a row
  /// (gaps without an assignment do not end the old one; a one-step
  /// cross assignment where two tracks meet is not a swap).
  std::size_t swaps = 0;
  /// Confirmed tracks assigned to no truth in more than half their
  /// reported steps.
  std::size_t false_tracks = 0;
  std::size_t confirmed_tracks = 0;  ///< Distinct confirmed track ids.
  /// Sum over truths of the times its assigned track changed to another id
  /// (with the same persistence rule): 0 when each target kept one track
  /// all along.
  std::size_t fragmentations = 0;
  /// Per truth: time of its first step with an assigned track minus the
  /// first step's time, s; negative: never confirmed.
  std::vector<double> time_to_confirm_s;
};

/// @param persistence_steps how long a changed assignment must hold to be
///        a swap or a fragmentation (1: every change counts).
MultiTargetRunMetrics compute_multi_target_metrics(std::span<const MultiTargetStep> steps, const SpaParams& c,
                                                   std::size_t persistence_steps = 3);

}  // namespace kestrel::sim
