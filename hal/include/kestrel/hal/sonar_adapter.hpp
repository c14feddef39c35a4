// SPDX-License-Identifier: Apache-2.0
// Turns a decoded sonar wire frame (integer nanoseconds, beacon id, path) into
// the core's TOA scan (seconds in the tracker's scalar), the sonar twin of
// radar_adapter.hpp. The conversion is an exact integer-to-scalar scaling
// through ScalarTraits, so a fixed-point build does no floating-point work
// here. This is the one place where sonar units change.
//
// The beacon table and the seabed depth are not on the wire: they are the
// installation's geometry, given once in a SonarAdapterParams and turned into the
// tracker's configuration by sonar_tracker_params().
#pragma once

#include <cstddef>
#include <cstdint>

#include "kestrel/hal/frame.hpp"
#include "kestrel/models/measurement/multipath_toa.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"
#include "kestrel/tracking/toa_scan.hpp"
#include "kestrel/tracking/sonar_tracker.hpp"

namespace kestrel::hal {

/// Most beacons a sonar frame can name with both paths (16 arrivals / 2).
inline constexpr std::size_t kMaxSonarBeacons = kMaxSonarArrivals / 2;
static_assert(kMaxSonarBeacons == static_cast<std::size_t>(SonarTrackerParams::kMaxBeacons),
              "the tracker parameters hold one entry per beacon a frame can name");

/// One beacon of the installation.
struct SonarBeacon {
  std::int32_t x_mm;      ///< East-like position, millimetres, installation frame.
  std::int32_t y_mm;      ///< North-like position, millimetres, installation frame.
  std::int32_t depth_mm;  ///< Depth below the surface, millimetres, positive down.
};

/// Installation geometry of a sonar front end: the beacon table (indexed by
/// SonarArrival::beacon_id), the seabed depth and the arrival-time noise.
struct SonarAdapterParams {
  SonarBeacon beacons[kMaxSonarBeacons] = {
      {0, 0, 0}, {2000000, 0, 0}, {0, 2000000, 0}, {2000000, 2000000, 0}};  ///< UW-003's beacons (docs/scenarios.md).
  std::uint8_t beacon_count = 4;        ///< Beacons in use.
  std::uint32_t seabed_depth_mm = 150000;  ///< D, millimetres.
  std::uint32_t sigma_toa_ns = 3000000;    ///< Arrival-time noise sigma, nanoseconds.
};

/// The tracker parameters with the installation's geometry filled in
/// (everything else keeps the values already in `base`).
inline SonarTrackerParams sonar_tracker_params(const SonarAdapterParams& cfg,
                                               SonarTrackerParams base = SonarTrackerParams{}) {
  const std::size_t n = cfg.beacon_count < kMaxSonarBeacons ? cfg.beacon_count : kMaxSonarBeacons;
  base.beacon_count = static_cast<std::uint8_t>(n);
  for (std::size_t i = 0; i < kMaxSonarBeacons; ++i) {
    if (i >= n) break;
    base.beacons_m[i][0] = static_cast<double>(cfg.beacons[i].x_mm) / 1000.0;
    base.beacons_m[i][1] = static_cast<double>(cfg.beacons[i].y_mm) / 1000.0;
    base.beacons_m[i][2] = static_cast<double>(cfg.beacons[i].depth_mm) / 1000.0;
  }
  base.seabed_depth_m = static_cast<double>(cfg.seabed_depth_mm) / 1000.0;
  base.sigma_toa_s = static_cast<double>(cfg.sigma_toa_ns) * 1e-9;
  return base;
}

/// Convert a sonar frame into `scan`: toa_s = time_of_flight_ns / 1e9.
/// Beacon ids and paths are copied as they are; the tracker checks them
/// against its beacon table (kOutOfRange) and for duplicates (kMalformedFrame).
/// @return kOk; kWrongKind (not a sonar frame; scan untouched);
///         kMalformedFrame (a path value that is neither direct nor
///         reflected; scan untouched); kTooManyCandidates (more arrivals than
///         the scan holds: the first kCapacity in frame order are kept and
///         the scan is usable).
template <class Scalar, std::size_t kCapacity>
[[nodiscard]] Status to_scan(const Frame& frame, ToaScan<Scalar, kCapacity>& scan) {
  using T = ScalarTraits<Scalar>;
  if (frame.kind != FrameKind::kSonar) return Status::kWrongKind;
  const std::size_t n = frame.count < kCapacity ? frame.count : kCapacity;
  for (std::size_t i = 0; i < kCapacity; ++i) {
    if (i >= n) break;
    const ToaPath path = frame.sonar[i].path;
    if (path != ToaPath::kDirect && path != ToaPath::kReflected) return Status::kMalformedFrame;
  }
  scan.t_us = frame.t_us;
  scan.count = n;
  for (std::size_t i = 0; i < kCapacity; ++i) {
    if (i >= n) break;
    const SonarArrival& a = frame.sonar[i];
    scan.arrivals[i].toa_s = T::from_ratio(static_cast<std::int64_t>(a.time_of_flight_ns), 1000000000LL);
    scan.arrivals[i].beacon = a.beacon_id;
    scan.arrivals[i].path = a.path == ToaPath::kDirect ? ArrivalPath::kDirect : ArrivalPath::kReflected;
  }
  return frame.count > kCapacity ? Status::kTooManyCandidates : Status::kOk;
}

/// Adapter object for Runner: sonar frames into TOA scans.
struct SonarAdapter {
  template <class Scalar, std::size_t kCapacity>
  [[nodiscard]] Status operator()(const Frame& frame, ToaScan<Scalar, kCapacity>& scan) const {
    return to_scan(frame, scan);
  }
};

}  // namespace kestrel::hal
