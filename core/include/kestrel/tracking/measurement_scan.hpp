// SPDX-License-Identifier: Apache-2.0
// One frame of measurements as the core sees it: a time and up to kCapacity
// measurement vectors in SI units of the scalar type (range m, bearing rad,
// ...). The HAL converts its integer wire frames into this
// (kestrel/hal/radar_adapter.hpp); core never sees the wire format.
#pragma once

#include <cstddef>
#include <cstdint>

#include "kestrel/filters/channels.hpp"
#include "kestrel/math/eigen.hpp"

namespace kestrel {

template <class Scalar, int kMeasDim, std::size_t kCapacity>
struct MeasurementScan {
  static_assert(kCapacity > 0, "a scan must be able to hold at least one measurement");
  static constexpr std::size_t kMaxMeasurements = kCapacity;
  using MeasVec = Vec<Scalar, kMeasDim>;

  std::int64_t t_us = 0;    ///< Measurement time, microseconds (sensor clock).
  std::size_t count = 0;    ///< Valid entries in z; step() refuses count > kCapacity.
  MeasVec z[kCapacity]{};   ///< Measurements, model units (e.g. [range_m, bearing_rad]).
};

/// A frame whose measurements carry only some channels of the measurement
/// vector each: a sonar frame is one measurement whose channels are the
/// (beacon, path) arrivals that came. Channels outside present[i] are not
/// read. The tracker of a ChannelFilter takes this scan.
template <class Scalar, int kMeasDim, std::size_t kCapacity>
struct ChannelScan : MeasurementScan<Scalar, kMeasDim, kCapacity> {
  ChannelMask present[kCapacity]{};  ///< Channels z[i] carries.
};

}  // namespace kestrel
