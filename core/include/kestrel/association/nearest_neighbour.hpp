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
  ///          innovation(k, j), gated(in), assign(k, j, in).
  template <class Candidates>
  void associate(Candidates& c) const {
    for (std::size_t k = 0; k < kMaxTracks; ++k) {
      if (k >= c.tracks()) break;
      std::size_t best = kMaxMeasurements;
      typename Candidates::Innov best_in;  // read only once best is set; zeroed for the compiler's sake
      best_in.nu.setZero();
      best_in.S.setZero();
      best_in.d2 = Scalar(0);
      for (std::size_t j = 0; j < kMaxMeasurements; ++j) {
        if (j >= c.measurements()) break;
        if (!c.free(j)) continue;
        const auto in = c.innovation(k, j);
        if (!c.gated(in)) continue;
        if (best == kMaxMeasurements || in.d2 < best_in.d2) {
          best = j;
          best_in = in;
        }
      }
      if (best != kMaxMeasurements) c.assign(k, best, best_in);
    }
  }
};

}  // namespace kestrel
