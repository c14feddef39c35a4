// SPDX-License-Identifier: Apache-2.0
// The radar tracker of radar_tracker.hpp for a radar that also measures
// range rate: the same EKF on the CA-2D model, two-point initiation,
// nearest-neighbour gating and M-of-N management, with the measurement
// [range, bearing, range_rate] (models/measurement/polar_radar_range_rate.hpp).
// The initiator differences positions as the position-only tracker does
// (to_position() reads range and bearing only); the first update then fuses
// the range rate. Boards
// feed it through hal::RadarAdapter, which refuses a frame with a plot
// lacking range rate (kWrongKind) rather than inventing one.
// Parameters and measured effect on S1/S2: docs/range_rate.md.
#pragma once

#include <cstddef>

#include "kestrel/filters/ekf.hpp"
#include "kestrel/models/measurement/polar_radar_range_rate.hpp"
#include "kestrel/tracking/radar_tracker.hpp"

namespace kestrel {

/// Parameters of the range-rate radar tracker, SI units: those of the
/// range-bearing tracker plus the range-rate channel.
struct RadarRangeRateTrackerParams {
  RadarTrackerParams radar{};         ///< Range, bearing, motion, initiation and management.
  /// srr, m/s. Default: the s1rr/s2rr scenarios' generator value (no source
  /// paper fixes one; docs/range_rate.md says why 0.5 m/s).
  double sigma_range_rate_mps = 0.5;
  /// Plots with |range rate| above this are out of range (the frame is
  /// refused, as for range): no track is faster than radar.max_speed_mps.
  double max_range_rate_mps = 1000.0;
};

template <class Scalar>
using CaPolarRadarRangeRate = PolarRadarRangeRate<CaMotion<Scalar>>;
/// EKF-CA with range rate.
template <class Scalar>
using EkfCaRr = Ekf<CaMotion<Scalar>, CaPolarRadarRangeRate<Scalar>>;

/// The range-rate radar tracker's configuration: the real-valued fields of
/// RadarRangeRateTrackerParams in the tracker's scalar (as RadarTrackerConfig).
template <class Scalar>
struct RadarRangeRateTrackerConfig {
  RadarTrackerConfig<Scalar> radar;  ///< As for the range-bearing tracker.
  Scalar sigma_range_rate_mps;        ///< srr, m/s.
  Scalar max_range_rate_mps;          ///< Largest valid |range rate|, m/s.
};

template <class Scalar>
constexpr RadarRangeRateTrackerConfig<Scalar> radar_range_rate_tracker_config(const RadarRangeRateTrackerParams& p) {
  using T = ScalarTraits<Scalar>;
  return RadarRangeRateTrackerConfig<Scalar>{radar_tracker_config<Scalar>(p.radar),
                                             T::from_double(p.sigma_range_rate_mps),
                                             T::from_double(p.max_range_rate_mps)};
}

/// The generic Tracker's TrackerConfig: that of the radar tracker with the range-rate
/// channel's box [-max_range_rate_mps, max_range_rate_mps].
template <class Scalar>
TrackerConfig<Scalar, 3> tracker_config_of(const RadarRangeRateTrackerParams& p,
                                           const RadarRangeRateTrackerConfig<Scalar>& s) {
  const TrackerConfig<Scalar, 2> rb = tracker_config_of<Scalar>(p.radar, s.radar);
  TrackerConfig<Scalar, 3> c;
  c.gate_confirmed = rb.gate_confirmed;
  c.gate_tentative = rb.gate_tentative;
  c.gate_confirmed_threshold = rb.gate_confirmed_threshold;
  c.robust_gate_factor = rb.robust_gate_factor;
  c.confirm_m = rb.confirm_m;
  c.confirm_n = rb.confirm_n;
  c.max_coast_misses = rb.max_coast_misses;
  c.max_position_variance_m2 = rb.max_position_variance_m2;
  c.report_tentative = rb.report_tentative;
  c.max_predict_us = rb.max_predict_us;
  c.max_forward_jump_us = rb.max_forward_jump_us;
  c.resync_frames = rb.resync_frames;
  c.z_min << rb.z_min(0), rb.z_min(1), -s.max_range_rate_mps;
  c.z_max << rb.z_max(0), rb.z_max(1), s.max_range_rate_mps;
  return c;
}

/// The EKF-CA range-rate radar tracker: the integer fields of p, the real
/// ones from s (no double arithmetic: the form a fixed-point board uses).
template <class Scalar, std::size_t kMaxTracks, std::size_t kMaxPlots>
RadarTracker<EkfCaRr<Scalar>, kMaxTracks, kMaxPlots> make_radar_range_rate_tracker(
    const RadarRangeRateTrackerParams& p, const RadarRangeRateTrackerConfig<Scalar>& s) {
  CaMotion<Scalar> motion;
  motion.qj = s.radar.qj;
  CaPolarRadarRangeRate<Scalar> radar;
  radar.sigma_range_m = s.radar.sigma_range_m;
  radar.sigma_bearing_rad = s.radar.sigma_bearing_rad;
  radar.sigma_range_rate_mps = s.sigma_range_rate_mps;
  TwoPointInitiator<CaMotion<Scalar>, CaPolarRadarRangeRate<Scalar>> init{radar, s.radar.max_speed_mps,
                                                                          s.radar.init_accel_sigma_mps2};
  return RadarTracker<EkfCaRr<Scalar>, kMaxTracks, kMaxPlots>(EkfCaRr<Scalar>(motion, radar), init,
                                                              tracker_config_of<Scalar>(p, s));
}

/// The same with the parameters converted at run time.
template <class Scalar, std::size_t kMaxTracks, std::size_t kMaxPlots>
RadarTracker<EkfCaRr<Scalar>, kMaxTracks, kMaxPlots> make_radar_range_rate_tracker(
    const RadarRangeRateTrackerParams& p) {
  return make_radar_range_rate_tracker<Scalar, kMaxTracks, kMaxPlots>(p, radar_range_rate_tracker_config<Scalar>(p));
}

}  // namespace kestrel
