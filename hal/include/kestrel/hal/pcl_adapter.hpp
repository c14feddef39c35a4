// SPDX-License-Identifier: Apache-2.0
// Turns a decoded passive-radar (PCL) wire frame into the core's measurement
// scan [Rb_m, dRb_mps] (paper 002 eq. 2): Rb = bistatic_range_mm / 1000,
// dRb = -lambda * doppler_mhz / 1000, lambda from the illuminator's carrier
// in the config. This is the one place where PCL units change. A frame with
// more candidates than the scan holds keeps exactly kCapacity, in frame
// order, and drops the excess worst first: farthest from every track, then
// lowest SNR, then latest; the result is kTooManyCandidates with a usable
// scan. Ranking by distance needs the tracker's state, so the adapter holds a
// read-only pointer to the tracker it feeds and never changes it. The rule
// and why: docs/pcl.md, "Front end: PCL frames to scans".
#pragma once

#include <cstddef>
#include <cstdint>

#include "kestrel/hal/frame.hpp"
#include "kestrel/math/eigen.hpp"
#include "kestrel/models/measurement/bistatic_range_rate.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"
#include "kestrel/tracking/measurement_scan.hpp"
#include "kestrel/tracking/nearest_track.hpp"

namespace kestrel::hal {

/// The PCL front end's constants.
struct PclAdapterParams {
  double carrier_hz = 701.0e6;  ///< Illuminator carrier frequency, Hz (lambda = c0 / f).
};

/// [Rb_m, dRb_mps] of one candidate: Rb = mm / 1000, dRb = -lambda * mHz / 1000.
/// @param lambda_m carrier wavelength, m.
template <class Scalar>
Vec<Scalar, 2> to_measurement(const PclCandidate& c, Scalar lambda_m) {
  using T = ScalarTraits<Scalar>;
  Vec<Scalar, 2> z;
  z(0) = T::from_ratio(static_cast<std::int64_t>(c.bistatic_range_mm), 1000);
  z(1) = range_rate_from_doppler(T::from_ratio(c.doppler_mhz, 1000), lambda_m);
  return z;
}

namespace detail {

/// true if candidate a should be dropped before candidate b (rules 1-3).
template <class Scalar>
bool drop_before(Scalar d2_a, std::int16_t snr_a, std::size_t a, Scalar d2_b, std::int16_t snr_b, std::size_t b) {
  if (d2_a > d2_b) return true;
  if (d2_b > d2_a) return false;
  if (snr_a != snr_b) return snr_a < snr_b;
  return a > b;
}

/// Shared body: convert every candidate, then drop the excess by the rule
/// with the given per-candidate distances.
template <class Scalar, std::size_t kCapacity>
Status fill_scan(const Frame& frame, const Vec<Scalar, 2> (&z)[kMaxPclCandidates],
                 const Scalar (&d2)[kMaxPclCandidates], MeasurementScan<Scalar, 2, kCapacity>& scan) {
  const std::size_t n = frame.count;
  bool dropped[kMaxPclCandidates] = {};
  const std::size_t excess = n > kCapacity ? n - kCapacity : 0;
  for (std::size_t k = 0; k < kMaxPclCandidates; ++k) {
    if (k >= excess) break;
    std::size_t worst = kMaxPclCandidates;
    for (std::size_t j = 0; j < kMaxPclCandidates; ++j) {
      if (j >= n) break;
      if (dropped[j]) continue;
      if (worst == kMaxPclCandidates ||
          drop_before(d2[j], frame.pcl[j].snr_cdb, j, d2[worst], frame.pcl[worst].snr_cdb, worst)) {
        worst = j;
      }
    }
    dropped[worst] = true;
  }
  scan.t_us = frame.t_us;
  std::size_t kept = 0;
  for (std::size_t j = 0; j < kMaxPclCandidates; ++j) {
    if (j >= n) break;
    if (dropped[j]) continue;
    scan.z[kept++] = z[j];
  }
  scan.count = kept;
  return excess > 0 ? Status::kTooManyCandidates : Status::kOk;
}

}  // namespace detail

/// Convert a PCL frame into `scan` without tracker state (over capacity:
/// lowest SNR dropped first, then the latest in frame order).
/// @param lambda_m carrier wavelength, m (wavelength_m(carrier_hz)).
/// @return kOk; kWrongKind (not a PCL frame; scan untouched); kMalformedFrame
///         (count over kMaxPclCandidates; scan untouched); kTooManyCandidates
///         (more candidates than kCapacity: the excess was dropped by the rule
///         and the scan is usable).
template <class Scalar, std::size_t kCapacity>
[[nodiscard]] Status to_pcl_scan(const Frame& frame, Scalar lambda_m, MeasurementScan<Scalar, 2, kCapacity>& scan) {
  if (frame.kind != FrameKind::kPcl) return Status::kWrongKind;
  if (frame.count > kMaxPclCandidates) return Status::kMalformedFrame;
  Vec<Scalar, 2> z[kMaxPclCandidates];
  Scalar d2[kMaxPclCandidates];
  for (std::size_t j = 0; j < kMaxPclCandidates; ++j) {
    d2[j] = ScalarTraits<Scalar>::max_value();
    if (j < frame.count) z[j] = to_measurement(frame.pcl[j], lambda_m);
  }
  return detail::fill_scan(frame, z, d2, scan);
}

/// Convert a PCL frame into `scan`, ranking candidates against the tracks of
/// `table` (Tracker::tracks()) when the frame is over capacity.
/// @return as the overload without tracks.
template <class Scalar, std::size_t kCapacity, class TrackT, std::size_t kMaxTracks>
[[nodiscard]] Status to_pcl_scan(const Frame& frame, Scalar lambda_m, const TrackTable<TrackT, kMaxTracks>& table,
                                 MeasurementScan<Scalar, 2, kCapacity>& scan) {
  if (frame.kind != FrameKind::kPcl) return Status::kWrongKind;
  if (frame.count > kMaxPclCandidates) return Status::kMalformedFrame;
  Vec<Scalar, 2> z[kMaxPclCandidates];
  Scalar d2[kMaxPclCandidates];
  for (std::size_t j = 0; j < kMaxPclCandidates; ++j) {
    if (j < frame.count) z[j] = to_measurement(frame.pcl[j], lambda_m);
  }
  if (frame.count > kCapacity) {
    nearest_track_d2(table, frame.t_us, z, frame.count, d2);
  } else {
    for (std::size_t j = 0; j < kMaxPclCandidates; ++j) d2[j] = ScalarTraits<Scalar>::max_value();
  }
  return detail::fill_scan(frame, z, d2, scan);
}

/// Adapter object for Runner: PCL frames into [Rb, dRb] scans for `Tracker`,
/// dropping an over-capacity frame's excess farthest from the tracker's
/// tracks first. The tracker is only read. Pass nullptr to rank by SNR only.
template <class Tracker>
class PclAdapter {
 public:
  using Scalar = typename Tracker::Scalar;
  using Scan = typename Tracker::Scan;

  PclAdapter(const Tracker* tracker, const PclAdapterParams& config)
      : tracker_(tracker), lambda_m_(ScalarTraits<Scalar>::from_double(kSpeedOfLightMps / config.carrier_hz)) {}

  /// @return see to_pcl_scan.
  [[nodiscard]] Status operator()(const Frame& frame, Scan& scan) const {
    if (tracker_ == nullptr) return to_pcl_scan(frame, lambda_m_, scan);
    return to_pcl_scan(frame, lambda_m_, tracker_->tracks(), scan);
  }

  /// Carrier wavelength in use, m.
  Scalar lambda_m() const { return lambda_m_; }

 private:
  const Tracker* tracker_;
  Scalar lambda_m_;
};

}  // namespace kestrel::hal
