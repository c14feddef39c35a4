// SPDX-License-Identifier: Apache-2.0
// One sonar frame as the core sees it: a time and up to kCapacity arrivals,
// each a travel time in seconds labelled by beacon and path (docs/models.md,
// TOA with multipath). The HAL converts its integer wire frames into this
// (kestrel/hal/sonar_adapter.hpp); core never sees the wire format.
#pragma once

#include <cstddef>
#include <cstdint>

#include "kestrel/models/measurement/multipath_toa.hpp"

namespace kestrel {

/// One time of arrival.
template <class Scalar>
struct ToaMeasurement {
  Scalar toa_s{};                          ///< Travel time target -> beacon, s.
  std::uint8_t beacon = 0;                 ///< Index into the beacon table.
  ArrivalPath path = ArrivalPath::kDirect; ///< Direct or seabed-reflected.
};

template <class Scalar, std::size_t kCapacity>
struct ToaScan {
  static_assert(kCapacity > 0, "a scan must be able to hold at least one arrival");
  static constexpr std::size_t kMaxArrivals = kCapacity;

  std::int64_t t_us = 0;  ///< Emission time of the ping, microseconds (sensor clock).
  std::size_t count = 0;  ///< Valid entries in arrivals; step() refuses count > kCapacity.
  ToaMeasurement<Scalar> arrivals[kCapacity]{};  ///< Arrivals in any order, one per (beacon, path).
};

}  // namespace kestrel
