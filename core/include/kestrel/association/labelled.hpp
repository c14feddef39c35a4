// SPDX-License-Identifier: Apache-2.0
// Association by label: the sensor has already said whose each measurement
// is, so there is nothing to choose. A sonar frame is one target's (its
// arrivals are labelled by beacon and path), so the one track takes it
// whole, with no association gate: the filter's own per-channel gate
// decides what of it to fuse. In general each track, in the order the
// tracker offers them, takes the first free measurement.
#pragma once

#include <cstddef>

namespace kestrel {

template <class Scalar, std::size_t kMaxTracks, std::size_t kMaxMeasurements>
class LabelledAssociation {
 public:
  struct Params {};  ///< None.
  LabelledAssociation() = default;
  explicit LabelledAssociation(const Params&) {}

  template <class Candidates>
  void associate(Candidates& c) const {
    std::size_t j = 0;
    for (std::size_t k = 0; k < kMaxTracks; ++k) {
      if (k >= c.tracks()) break;
      while (j < c.measurements() && j < kMaxMeasurements && !c.free(j)) ++j;  // at most kMaxMeasurements steps in all
      if (j >= c.measurements() || j >= kMaxMeasurements) return;
      c.assign(k, j);
      ++j;
    }
  }
};

}  // namespace kestrel
