// SPDX-License-Identifier: Apache-2.0
// Nearest-neighbour association: each track, in the order the tracker
// offers them (oldest first), takes the free measurement of smallest
// normalised distance d2 inside its gate. Greedy: one pass over the
// track-measurement pairs, no storage.
#pragma once

#include <cstddef>

namespace kestrel {

template <class Scalar, std::size_t kMaxTracks, std::size_t kMaxMeasurements>
class NearestNeighbour {
 public:
  struct Params {};  ///< None.
  NearestNeighbour() = default;
  explicit NearestNeighbour(const Params&) {}

  /// @param c the tracker's candidate pairs (tracking/tracker.hpp,
  ///          AssociationCandidates): tracks(), measurements(), free(j),
  ///          track(k), distance(track, j), gated(d),
  ///          assign(k, j, d).
  template <class Candidates>
  void associate(Candidates& c) const {
    for (std::size_t k = 0; k < kMaxTracks; ++k) {
      if (k >= c.tracks()) break;
      const auto track = c.track(k);
      std::size_t best = kMaxMeasurements;
      decltype(c.distance(track, std::size_t{0})) best_d{};  // read only once best is set
      for (std::size_t j = 0; j < kMaxMeasurements; ++j) {
        if (j >= c.measurements()) break;
        if (!c.free(j)) continue;
        const auto d = c.distance(track, j);
        if (!c.gated(d)) continue;
        if (best == kMaxMeasurements || d.d2 < best_d.d2) {
          best = j;
          best_d = d;
        }
      }
      if (best != kMaxMeasurements) c.assign(k, best, best_d);
    }
  }
};

}  // namespace kestrel
