// SPDX-License-Identifier: Apache-2.0
// The oracle associator of a simulation (docs/multitarget.md): it is told
// each plot's true origin, so a track takes the plot of the target it
// follows (if that plot is inside its gate) and never a false alarm. A
// track is labelled with the target of the first plot it takes; an
// unlabelled track takes the nearest gated plot of a target. Tracks still
// start from any plot (the initiator is the tracker's), so the oracle
// removes association errors, not initiation from clutter. Host only: the
// labels live in a std::map.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>

#include "montecarlo/multi_run.hpp"

namespace kestrel::sim {

template <class Scalar, std::size_t kMaxTracks, std::size_t kMaxMeasurements>
class OracleAssociation {
 public:
  struct Params {
    const OracleLabels* labels = nullptr;  ///< Must outlive the tracker.
  };
  OracleAssociation() = default;
  explicit OracleAssociation(const Params& p) : labels_(p.labels) {}

  template <class Candidates>
  void associate(Candidates& c) {
    if (labels_ == nullptr) return;
    const auto frame = labels_->origins.find(c.t_us());
    if (frame == labels_->origins.end()) return;
    const std::vector<int>& origin = frame->second;
    const std::size_t m = c.measurements() < origin.size() ? c.measurements() : origin.size();
    // Labelled tracks take their target's plot.
    for (std::size_t k = 0; k < c.tracks(); ++k) {
      const auto label = label_.find(c.track_id(k));
      if (label == label_.end()) continue;
      for (std::size_t j = 0; j < m; ++j) {
        if (origin[j] != label->second || !c.free(j)) continue;
        const auto d = c.distance(c.track(k), j);
        if (c.gated(d)) c.assign(k, j, d);
        break;
      }
    }
    // The others take the nearest gated plot of a target and its label.
    for (std::size_t k = 0; k < c.tracks(); ++k) {
      const std::uint32_t id = c.track_id(k);
      if (label_.count(id) != 0) continue;
      const auto track = c.track(k);
      std::size_t best = m;
      Scalar best_d2{};
      for (std::size_t j = 0; j < m; ++j) {
        if (origin[j] < 0 || !c.free(j)) continue;
        const auto d = c.distance(track, j);
        if (!c.gated(d)) continue;
        if (best == m || d.d2 < best_d2) {
          best = j;
          best_d2 = d.d2;
        }
      }
      if (best == m) continue;
      label_[id] = origin[best];
      c.assign(k, best);
    }
  }

 private:
  const OracleLabels* labels_ = nullptr;
  std::map<std::uint32_t, int> label_;  ///< Track id -> target index.
};

}  // namespace kestrel::sim
