// SPDX-License-Identifier: Apache-2.0
// Turns a decoded radar wire frame (integer units) into the core's
// measurement scan ([range_m, bearing_rad] in the tracker's scalar, or
// [range_m, bearing_rad, range_rate_mps] for a tracker whose measurement has
// a third channel). The conversion is exact integer-to-scalar scaling
// through ScalarTraits, so a fixed-point build does no floating-point work
// here. This is the one place where radar units change.
#pragma once

#include <cstddef>

#include "kestrel/hal/frame.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"
#include "kestrel/tracking/measurement_scan.hpp"

namespace kestrel::hal {

namespace detail {
/// Range (m) and bearing (rad) of a plot into z(0), z(1).
template <class Scalar, class MeasVec>
void convert_range_bearing(const RadarPlot& p, MeasVec& z) {
  using T = ScalarTraits<Scalar>;
  z(0) = T::from_ratio(static_cast<std::int64_t>(p.range_mm), 1000);
  // bearing = bam * pi / 2^31: exact in double and float, integer in Q.
  z(1) = T::from_ratio(p.bearing_bam, 2147483648LL) * T::pi();
}
}  // namespace detail

/// Convert a radar frame into a [range, bearing] `scan`. A plot's range
/// rate, if any, is not used.
/// @return kOk; kWrongKind (not a radar frame; scan untouched);
///         kTooManyCandidates (more plots than the scan holds: the first
///         kCapacity plots in frame order are kept and the scan is usable).
template <class Scalar, std::size_t kCapacity>
[[nodiscard]] Status to_scan(const Frame& frame, MeasurementScan<Scalar, 2, kCapacity>& scan) {
  if (frame.kind != FrameKind::kRadar) return Status::kWrongKind;
  const std::size_t n = frame.count < kCapacity ? frame.count : kCapacity;
  scan.t_us = frame.t_us;
  scan.count = n;
  for (std::size_t i = 0; i < kCapacity; ++i) {
    if (i >= n) break;
    detail::convert_range_bearing<Scalar>(frame.radar[i], scan.z[i]);
  }
  return frame.count > kCapacity ? Status::kTooManyCandidates : Status::kOk;
}

/// Convert a radar frame into a [range, bearing, range_rate] `scan` (the
/// range-rate radar, models/measurement/polar_radar_range_rate.hpp): range
/// rate m/s = range_rate_mmps / 1000, positive opening. A plot without a
/// measured range rate (has_range_rate == 0) cannot be represented in this
/// scan and no value is made up for it: the whole frame is refused, so the
/// tracker never sees a zero range rate that was not measured
/// (docs/range_rate.md).
/// @return kOk; kWrongKind (not a radar frame, or a kept plot has no range
///         rate: the frame is of a sensor this tracker does not take; scan
///         untouched); kTooManyCandidates (more plots than the scan holds:
///         the first kCapacity plots in frame order are kept and the scan
///         is usable; only those are checked for a range rate).
template <class Scalar, std::size_t kCapacity>
[[nodiscard]] Status to_scan(const Frame& frame, MeasurementScan<Scalar, 3, kCapacity>& scan) {
  using T = ScalarTraits<Scalar>;
  if (frame.kind != FrameKind::kRadar) return Status::kWrongKind;
  const std::size_t n = frame.count < kCapacity ? frame.count : kCapacity;
  // Checked before anything is written, so a refused frame leaves the scan as it was.
  for (std::size_t i = 0; i < kCapacity; ++i) {
    if (i >= n) break;
    if (frame.radar[i].has_range_rate == 0) return Status::kWrongKind;
  }
  scan.t_us = frame.t_us;
  scan.count = n;
  for (std::size_t i = 0; i < kCapacity; ++i) {
    if (i >= n) break;
    const RadarPlot& p = frame.radar[i];
    detail::convert_range_bearing<Scalar>(p, scan.z[i]);
    scan.z[i](2) = T::from_ratio(static_cast<std::int64_t>(p.range_rate_mmps), 1000);
  }
  return frame.count > kCapacity ? Status::kTooManyCandidates : Status::kOk;
}

/// Adapter object for Runner: radar frames into [range, bearing] scans, or
/// [range, bearing, range_rate] scans when the tracker's measurement has
/// three channels (to_scan above).
struct RadarAdapter {
  template <class Scalar, int kMeasDim, std::size_t kCapacity>
  [[nodiscard]] Status operator()(const Frame& frame, MeasurementScan<Scalar, kMeasDim, kCapacity>& scan) const {
    return to_scan(frame, scan);
  }
};

}  // namespace kestrel::hal
