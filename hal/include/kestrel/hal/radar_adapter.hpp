// SPDX-License-Identifier: Apache-2.0
// Turns a decoded radar wire frame (integer units) into the core's
// measurement scan ([range_m, bearing_rad] in the tracker's scalar). The
// conversion is exact integer-to-scalar scaling through ScalarTraits, so a
// fixed-point build does no floating-point work here. This is the one place
// where radar units change.
#pragma once

#include <cstddef>

#include "kestrel/hal/frame.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"
#include "kestrel/tracking/measurement_scan.hpp"

namespace kestrel::hal {

/// Convert a radar frame into `scan`.
/// @return kOk; kWrongKind (not a radar frame; scan untouched);
///         kTooManyCandidates (more plots than the scan holds: the first
///         kCapacity plots in frame order are kept and the scan is usable).
template <class Scalar, std::size_t kCapacity>
[[nodiscard]] Status to_scan(const Frame& frame, MeasurementScan<Scalar, 2, kCapacity>& scan) {
  using T = ScalarTraits<Scalar>;
  if (frame.kind != FrameKind::kRadar) return Status::kWrongKind;
  const std::size_t n = frame.count < kCapacity ? frame.count : kCapacity;
  scan.t_us = frame.t_us;
  scan.count = n;
  for (std::size_t i = 0; i < kCapacity; ++i) {
    if (i >= n) break;
    const RadarPlot& p = frame.radar[i];
    scan.z[i](0) = T::from_ratio(static_cast<std::int64_t>(p.range_mm), 1000);
    // bearing = bam * pi / 2^31: exact in double and float, integer in Q.
    scan.z[i](1) = T::from_ratio(p.bearing_bam, 2147483648LL) * T::pi();
  }
  return frame.count > kCapacity ? Status::kTooManyCandidates : Status::kOk;
}

/// Adapter object for Runner: radar frames into [range, bearing] scans.
struct RadarAdapter {
  template <class Scalar, std::size_t kCapacity>
  [[nodiscard]] Status operator()(const Frame& frame, MeasurementScan<Scalar, 2, kCapacity>& scan) const {
    return to_scan(frame, scan);
  }
};

}  // namespace kestrel::hal
