// SPDX-License-Identifier: Apache-2.0
// How close a measurement lies to the tracks a tracker holds, before the
// tracker sees the frame: for each measurement, the smallest normalised
// squared distance nu^T S^-1 nu to any initialised track's prediction at the
// frame time (the quantity the ellipsoidal gate and nearest-neighbour
// association of docs/tracking.md use). A front end that must drop candidates
// from an over-capacity frame uses it to drop those farthest from every
// track first (docs/scenarios.md, PCL-002; kestrel/hal/pcl_adapter.hpp).
// The table is read only: each track's filter is copied and predicted.
// Work: kMaxTracks predictions and kMaxTracks x n innovations.
#pragma once

#include <cstddef>
#include <cstdint>

#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"
#include "kestrel/tracking/elapsed.hpp"
#include "kestrel/tracking/track_table.hpp"

namespace kestrel {

/// For each z[j], j < n (n is clamped to kN): d2[j] = min over initialised
/// tracks of nu^T S^-1 nu against the track predicted to t_us (a track newer
/// than t_us is used as it is). d2[j] = ScalarTraits::max_value() when no
/// track exists or no innovation is valid.
/// @param table the tracker's table (Tracker::tracks()).
/// @param t_us the frame time, microseconds.
template <class TrackT, std::size_t kMaxTracks, class MeasVec, class Scalar, std::size_t kN>
void nearest_track_d2(const TrackTable<TrackT, kMaxTracks>& table, std::int64_t t_us, const MeasVec (&z)[kN],
                      std::size_t n, Scalar (&d2)[kN]) {
  using T = ScalarTraits<Scalar>;
  for (std::size_t j = 0; j < kN; ++j) d2[j] = T::max_value();
  for (std::size_t i = 0; i < kMaxTracks; ++i) {
    if (!table.active(i) || !table[i].initialised) continue;
    auto filter = table[i].filter;
    // Frame and track times are any int64 a sensor sent: their gap saturates.
    const std::int64_t dt_us = t_us > table[i].t_us ? elapsed_us(t_us, table[i].t_us) : 0;
    if (filter.predict(T::from_ratio(dt_us, 1000000)) != Status::kOk) continue;
    for (std::size_t j = 0; j < kN; ++j) {
      if (j >= n) break;
      const auto in = filter.innovation(z[j]);
      if (in.status == Status::kOk && in.d2 < d2[j]) d2[j] = in.d2;
    }
  }
}

}  // namespace kestrel
