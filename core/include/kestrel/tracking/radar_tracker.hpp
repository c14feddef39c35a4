// SPDX-License-Identifier: Apache-2.0
// The ready-made radar tracker of the walking skeleton: EKF on the CA-2D
// model with the polar radar measurement (paper 000's EKF-CA), two-point
// initiation, nearest-neighbour gating, M-of-N management. Boards and
// kestrel-sim instantiate it through make_radar_tracker(); other filters
// with the same models (R2-AEKF, UKF, ...) plug into the same Tracker.
#pragma once

#include <concepts>
#include <cstddef>

#include "kestrel/filters/ekf.hpp"
#include "kestrel/models/measurement/polar_radar.hpp"
#include "kestrel/models/motion/constant_acceleration_2d.hpp"
#include "kestrel/tracking/tracker.hpp"
#include "kestrel/tracking/two_point_initiator.hpp"

namespace kestrel {

/// Parameters of the radar tracker, SI units. Defaults are the
/// S1/S2 sensor of docs/scenarios.md and paper 000's EKF-CA (qj = 1.6 m^2/s^5).
struct RadarTrackerParams {
  double sigma_range_m = 3.0;                  ///< sr.
  double sigma_bearing_rad = 0.3 * 3.14159265358979323846 / 180.0;  ///< sb (0.30 deg).
  double qj = 1.6;                             ///< White-jerk PSD, m^2/s^5.
  double max_speed_mps = 1000.0;               ///< Two-point pairs faster than this are refused.
  double init_accel_sigma_mps2 = 30.0;         ///< Initial acceleration sigma (about 3 g).
  double max_range_m = 500000.0;               ///< Plots beyond this are out of range.
  double max_position_variance_m2 = 1.0e6;     ///< Delete a track past a 1 km position sigma.
  GateProbability gate = GateProbability::k999;  ///< Gate of confirmed and tentative tracks.
  /// Confirmed tracks take plots up to this factor times the gate's d2 with
  /// a shrunk innovation (TrackerConfig::robust_gate_factor). 0, off, by
  /// default: in clutter the outer gate takes false plots whenever the
  /// target's is missing. 25 (5 gate radii) suits a sensor without clutter
  /// whose noise may grow 5-fold for a while (docs/robustness.md).
  double robust_gate_factor = 0.0;
  /// With the robust gate on, confirmed tracks fuse with lambda R, lambda
  /// in [1, robust_noise_max_scale] following each track's NIS with this
  /// weight per plot (AdaptiveMeasurementNoise, association/adaptive_noise.hpp).
  /// Only a tracker built with AdaptiveMeasurementNoise honours it, through
  /// configure_measurement_noise(radar_measurement_noise<Scalar>(p)); one
  /// built without it (make_radar_tracker(), every board's) refuses any
  /// value but 0 there with kOutOfRange, and make_radar_tracker() does not
  /// read it. 0, off, by default: a filter that lags a manoeuvre (EKF-CA at
  /// qj 1.6 on S1) reads its lag as noise and lags further. 0.2 suits the
  /// IMM (docs/robustness.md).
  double robust_noise_gain = 0.0;
  /// lambda's upper bound: R up to this factor (sigma up to its root).
  double robust_noise_max_scale = 16.0;
  std::uint8_t confirm_m = 2;                  ///< M of M-of-N (the seed and the pairing plot).
  std::uint8_t confirm_n = 3;                  ///< N of M-of-N.
  /// TwoPointHypothesesInitiator's rules: a seed pairs in this many frames
  /// after the next one too, and (seed_from_pairs) a pairing plot starts a
  /// seed of its own. Only a tracker built with that initiator honours them
  /// (kestrel-sim's ekf-ca and imm); make_radar_tracker() builds a
  /// TwoPointInitiator, every board's, and does not read them. Off by
  /// default: with 2-of-3 confirmation every extra pair in clutter is a
  /// false track (docs/robustness.md, "A second hypothesis at the start").
  std::uint8_t seed_extra_frames = 0;
  bool seed_from_pairs = false;
  std::uint16_t max_coast_misses = 5;          ///< Consecutive misses before deletion.
  std::int64_t max_predict_us = 10'000'000;    ///< Delete, not extrapolate, a track older than this (TrackerConfig).
  std::int64_t max_forward_jump_us = 600'000'000;  ///< Refuse a frame this far ahead (TrackerConfig).
  std::uint8_t resync_frames = 3;              ///< Consistent off-clock frames before a restart (TrackerConfig).
};

template <class Scalar>
using CaMotion = ConstantAcceleration2D<Scalar>;
template <class Scalar>
using CaPolarRadar = PolarRadar<CaMotion<Scalar>>;
/// Paper 000's EKF-CA.
template <class Scalar>
using EkfCa = Ekf<CaMotion<Scalar>, CaPolarRadar<Scalar>>;

/// EkfCa checked at every predict, as a filter without predict_unverified()
/// is (VerifiesPredictionLater, tracking/tracker.hpp): the same estimates,
/// for an image where code size counts more than the instructions the
/// once-per-frame check saves (docs/performance.md, "Once per frame").
template <class Scalar>
struct EkfCaCheckedEachPredict : EkfCa<Scalar> {
  using EkfCa<Scalar>::EkfCa;
  Status predict_unverified(Scalar dt) = delete;
};

template <class Filter, std::size_t kMaxTracks, std::size_t kMaxPlots>
using RadarTracker =
    Tracker<Filter, TwoPointInitiator<typename Filter::MotionModel, typename Filter::MeasurementModel>,
            kMaxTracks, kMaxPlots>;

/// The radar tracker with adaptive measurement noise
/// (AdaptiveMeasurementNoise): a compile-time choice, for a filter with a
/// scaled update (EkfCa, RadarImm). Give it its rule with
/// configure_measurement_noise(radar_measurement_noise<Scalar>(p)).
template <class Filter, std::size_t kMaxTracks, std::size_t kMaxPlots>
using AdaptiveRadarTracker =
    Tracker<Filter, TwoPointInitiator<typename Filter::MotionModel, typename Filter::MeasurementModel>,
            kMaxTracks, kMaxPlots, NearestNeighbour, MOfN, AdaptiveMeasurementNoise>;

/// p's adaptive noise rule (robust_noise_gain, robust_noise_max_scale) in
/// the tracker's scalar, for Tracker::configure_measurement_noise().
template <class Scalar>
constexpr MeasurementNoiseConfig<Scalar> radar_measurement_noise(const RadarTrackerParams& p) {
  using T = ScalarTraits<Scalar>;
  return {T::from_double(p.robust_noise_gain), T::from_double(p.robust_noise_max_scale)};
}

/// The radar tracker's configuration: the real-valued fields of
/// RadarTrackerParams in the tracker's scalar. For a fixed-point board,
/// build it in a constant expression,
///   constexpr auto kConfig = radar_tracker_config<Q31_32>(RadarTrackerParams{});
/// so the image converts nothing from double at run time.
template <class Scalar>
struct RadarTrackerConfig {
  Scalar sigma_range_m;             ///< sr, m.
  Scalar sigma_bearing_rad;         ///< sb, rad.
  Scalar qj;                        ///< White-jerk PSD, m^2/s^5.
  Scalar max_speed_mps;             ///< Two-point speed limit, m/s.
  Scalar init_accel_sigma_mps2;     ///< Initial acceleration sigma, m/s^2.
  Scalar max_range_m;               ///< Largest valid range, m.
  Scalar max_position_variance_m2;  ///< Deletion limit on var(x) + var(y), m^2.
  Scalar robust_gate_factor;        ///< Outer gate / chi-square gate, in d2.
};

template <class Scalar>
constexpr RadarTrackerConfig<Scalar> radar_tracker_config(const RadarTrackerParams& p) {
  using T = ScalarTraits<Scalar>;
  return RadarTrackerConfig<Scalar>{T::from_double(p.sigma_range_m), T::from_double(p.sigma_bearing_rad),
                                    T::from_double(p.qj), T::from_double(p.max_speed_mps),
                                    T::from_double(p.init_accel_sigma_mps2), T::from_double(p.max_range_m),
                                    T::from_double(p.max_position_variance_m2),
                                    T::from_double(p.robust_gate_factor)};
}

/// The generic Tracker's TrackerConfig for the radar: the integer fields of
/// p, the real ones from s.
template <class Scalar>
TrackerConfig<Scalar, 2> tracker_config_of(const RadarTrackerParams& p, const RadarTrackerConfig<Scalar>& s) {
  using T = ScalarTraits<Scalar>;
  TrackerConfig<Scalar, 2> c;
  c.gate_confirmed = p.gate;
  c.gate_tentative = p.gate;
  c.confirm_m = p.confirm_m;
  c.confirm_n = p.confirm_n;
  c.max_coast_misses = p.max_coast_misses;
  c.max_predict_us = p.max_predict_us;
  c.max_forward_jump_us = p.max_forward_jump_us;
  c.resync_frames = p.resync_frames;
  c.max_position_variance_m2 = s.max_position_variance_m2;
  c.robust_gate_factor = s.robust_gate_factor;
  c.z_min << Scalar(0), -T::pi();
  c.z_max << s.max_range_m, T::pi();
  return c;
}

/// The generic Tracker's TrackerConfig from the parameters.
template <class Scalar>
TrackerConfig<Scalar, 2> tracker_config_of(const RadarTrackerParams& p) {
  return tracker_config_of<Scalar>(p, radar_tracker_config<Scalar>(p));
}

/// The EKF-CA radar tracker: the integer fields of p, the real ones from s
/// (no double arithmetic: the form a fixed-point board uses).
/// Filter: EkfCa<Scalar> or EkfCaCheckedEachPredict<Scalar>.
template <class Scalar, std::size_t kMaxTracks, std::size_t kMaxPlots, class Filter = EkfCa<Scalar>>
  requires std::derived_from<Filter, EkfCa<Scalar>>
RadarTracker<Filter, kMaxTracks, kMaxPlots> make_radar_tracker(const RadarTrackerParams& p,
                                                               const RadarTrackerConfig<Scalar>& s) {
  CaMotion<Scalar> motion;
  motion.qj = s.qj;
  CaPolarRadar<Scalar> radar;
  radar.sigma_range_m = s.sigma_range_m;
  radar.sigma_bearing_rad = s.sigma_bearing_rad;
  TwoPointInitiator<CaMotion<Scalar>, CaPolarRadar<Scalar>> init{radar, s.max_speed_mps,
                                                                 s.init_accel_sigma_mps2};
  return RadarTracker<Filter, kMaxTracks, kMaxPlots>(Filter(motion, radar), init, tracker_config_of<Scalar>(p, s));
}

/// The EKF-CA radar tracker with the given parameters (converted at run
/// time: exact and host-independent for fixed point too, but a board
/// should pass constexpr RadarTrackerConfig instead).
template <class Scalar, std::size_t kMaxTracks, std::size_t kMaxPlots, class Filter = EkfCa<Scalar>>
  requires std::derived_from<Filter, EkfCa<Scalar>>
RadarTracker<Filter, kMaxTracks, kMaxPlots> make_radar_tracker(const RadarTrackerParams& p) {
  return make_radar_tracker<Scalar, kMaxTracks, kMaxPlots, Filter>(p, radar_tracker_config<Scalar>(p));
}

}  // namespace kestrel
