// SPDX-License-Identifier: Apache-2.0
// Global nearest-neighbour association: the assignment of tracks to free
// measurements that minimises the summed d2 of the pairs plus the gate
// threshold for every track left without one (association/gnn.hpp). Where
// two tracks compete for one plot, nearest neighbour lets the older track
// take it even if that leaves the other with nothing; GNN gives each the
// plot that keeps the total smallest. Storage: the cost matrix and the
// solver's arrays, bounded by the capacities (kept in the tracker object,
// no heap).
#pragma once

#include <cstddef>

#include "kestrel/association/gnn.hpp"
#include "kestrel/status.hpp"

namespace kestrel {

template <class Scalar, std::size_t kMaxTracks, std::size_t kMaxMeasurements>
class GlobalNearestNeighbour {
 public:
  struct Params {};  ///< None.
  GlobalNearestNeighbour() = default;
  explicit GlobalNearestNeighbour(const Params&) {}

  /// @param c the tracker's candidate pairs (see NearestNeighbour).
  template <class Candidates>
  void associate(Candidates& c) {
    const std::size_t n = c.tracks();
    const std::size_t m = c.measurements();
    if (n == 0 || m == 0) return;
    // A pair outside the gate (or a used plot) costs more than a miss:
    // the solver never assigns it.
    const Scalar miss = c.gate_threshold();
    const Scalar forbidden = miss + miss + Scalar(1);
    cost_.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(m));
    bool any = false;
    for (std::size_t k = 0; k < kMaxTracks; ++k) {
      if (k >= n) break;
      const auto track = c.track(k);
      for (std::size_t j = 0; j < kMaxMeasurements; ++j) {
        if (j >= m) break;
        Scalar cost = forbidden;
        if (c.free(j)) {
          const auto d = c.distance(track, j);
          if (c.gated(d)) {
            cost = d.d2;
            any = true;
          }
        }
        cost_(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(j)) = cost;
      }
    }
    if (!any) return;
    int col_of_row[kMaxTracks];
    Scalar total{};
    // Gated d2 are finite and non-negative and miss is finite, so the
    // solver cannot refuse this problem; if it ever did, nothing is assigned.
    if (solver_.solve(cost_, miss, col_of_row, total) != Status::kOk) return;
    for (std::size_t k = 0; k < kMaxTracks; ++k) {
      if (k >= n) break;
      const int j = col_of_row[k];
      if (j < 0) continue;
      c.assign(k, static_cast<std::size_t>(j));
    }
  }

 private:
  Gnn<Scalar, kMaxTracks, kMaxMeasurements> solver_{};
  typename Gnn<Scalar, kMaxTracks, kMaxMeasurements>::CostMatrix cost_{};
};

}  // namespace kestrel
