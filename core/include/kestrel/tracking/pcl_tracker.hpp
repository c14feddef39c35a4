// SPDX-License-Identifier: Apache-2.0
// The ready-made passive-radar (PCL) tracker of paper 002 (PCL-002 in
// docs/scenarios.md): a linear Kalman filter on the bistatic CV-1D model
// [Rb, dRb] with the bistatic range / range-rate measurement (H = I),
// single-point initiation with the zero-Doppler start veto, an ellipsoidal
// gate per track (tighter for tentative tracks), and by default
// nearest-neighbour association and 5-of-6 confirmation; GNN, PDA and the
// sequential track score compose the same way. The filter is Ekf on linear
// models, which is exactly the linear KF term for term
// (tests/core/tracking/pcl_model_test.cpp checks it against a textbook KF),
// so there is no separate kf.hpp. Parameters and choices: docs/pcl.md.
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "kestrel/association/pda.hpp"
#include "kestrel/filters/ekf.hpp"
#include "kestrel/models/measurement/bistatic_range_rate.hpp"
#include "kestrel/models/motion/bistatic_cv_1d.hpp"
#include "kestrel/tracking/sequential_llr.hpp"
#include "kestrel/tracking/single_point_initiator.hpp"
#include "kestrel/tracking/tracker.hpp"

namespace kestrel {

/// Parameters of the PCL tracker, SI units (Doppler in Hz). Defaults are
/// the PCL-002 sensor of docs/scenarios.md (701 MHz DTV, sigma_Rb = 10 m,
/// sigma_fD = 0.5 Hz) and the track management a check found workable there
/// (docs/references.md, reference figures).
struct PclTrackerParams {
  double carrier_hz = 701.0e6;            ///< Illuminator carrier; lambda = c0 / f (0.4277 m).
  double sigma_rb_m = 10.0;               ///< Bistatic range noise, m.
  double sigma_doppler_hz = 0.5;          ///< Doppler noise, Hz (sigma_dRb = lambda * sigma_fD).
  double accel_sigma_mps2 = 4.0;          ///< White-acceleration sigma on Rb, m/s^2.
  GateProbability gate_confirmed = GateProbability::k99;  ///< Gate of confirmed tracks.
  GateProbability gate_tentative = GateProbability::k95;  ///< Tighter gate of tentative tracks.
  std::uint8_t confirm_m = 5;             ///< M of M-of-N.
  std::uint8_t confirm_n = 6;             ///< N of M-of-N.
  double min_start_doppler_hz = 2.0;      ///< No track starts from a candidate with |fD| below this, Hz.
  std::uint16_t max_coast_misses = 6;     ///< Consecutive misses before a confirmed track is deleted.
  double max_rb_variance_m2 = 2500.0;     ///< Delete a track whose var(Rb) exceeds this (50 m sigma), m^2.
  double max_bistatic_range_m = 200000.0; ///< Candidates beyond are out of range (frame refused).
  double max_abs_doppler_hz = 5000.0;     ///< |fD| beyond is out of range (frame refused), Hz.
  // The sensor and the targets as the probabilistic policies see them (PDA,
  // the track score), read only by those. Densities are per m x m/s
  // (Rb x dRb) and frame; PCL-002's 21 false candidates a frame spread over
  // 3000 m x 250 Hz (106.9 m/s) are 6.5e-5.
  double detection_probability = 0.9;        ///< P_D of a target's candidate (PDA, track score).
  double clutter_density = 6.5e-5;           ///< False candidates per m x m/s and frame (PDA, track score).
  double new_target_density = 1.0e-6;        ///< Track score: new targets per m x m/s and frame.
  double false_track_probability = 1.0e-4;   ///< Track score: sets the confirmation threshold.
  double missed_track_probability = 0.05;    ///< Track score: sets the deletion threshold.
};

/// PDA's parameters from the PCL parameters (one P_D, one clutter density).
inline PdaParams pcl_pda_params(const PclTrackerParams& p) { return PdaParams{p.detection_probability, p.clutter_density}; }

/// The track score's parameters from the PCL parameters.
inline SequentialLlrParams pcl_score_params(const PclTrackerParams& p) {
  return SequentialLlrParams{p.detection_probability, p.clutter_density, p.new_target_density,
                             p.false_track_probability, p.missed_track_probability};
}

template <class Scalar>
using PclMotion = BistaticCv1D<Scalar>;
template <class Scalar>
using PclMeasurement = BistaticRangeRate<PclMotion<Scalar>>;
/// Paper 002's Kalman filter on [Rb, dRb].
template <class Scalar>
using PclKf = Ekf<PclMotion<Scalar>, PclMeasurement<Scalar>>;
template <class Scalar>
using PclInitiator = SinglePointInitiator<PclMotion<Scalar>, PclMeasurement<Scalar>>;

/// Default capacities for PCL-002: 32 candidates per frame (docs/scenarios.md)
/// and room for the tentative tracks that about 22 clutter candidates a frame
/// start (each lives at least 3 frames under 5-of-6: start, two misses).
inline constexpr std::size_t kPclMaxCandidates = 32;
inline constexpr std::size_t kPclMaxTracks = 128;

template <class Filter, std::size_t kMaxTracks, std::size_t kMaxCandidates,
          template <class, std::size_t, std::size_t> class Associator = NearestNeighbour,
          template <class> class Manager = MOfN>
using PclTracker =
    Tracker<Filter, SinglePointInitiator<typename Filter::MotionModel, typename Filter::MeasurementModel>,
            kMaxTracks, kMaxCandidates, Associator, Manager>;

/// Carrier wavelength of the parameters, m.
template <class Scalar>
Scalar pcl_wavelength_m(const PclTrackerParams& p) {
  return ScalarTraits<Scalar>::from_double(kSpeedOfLightMps / p.carrier_hz);
}

/// Tracker-level configuration from the parameters: gates, M-of-N, the
/// deletion limits, and the valid measurement box [0, max Rb] x
/// [-lambda max|fD|, +lambda max|fD|].
template <class Scalar>
TrackerConfig<Scalar, 2> pcl_tracker_config(const PclTrackerParams& p) {
  using T = ScalarTraits<Scalar>;
  const double lambda = kSpeedOfLightMps / p.carrier_hz;
  TrackerConfig<Scalar, 2> c;
  c.gate_confirmed = p.gate_confirmed;
  c.gate_tentative = p.gate_tentative;
  c.confirm_m = p.confirm_m;
  c.confirm_n = p.confirm_n;
  c.max_coast_misses = p.max_coast_misses;
  c.max_position_variance_m2 = T::from_double(p.max_rb_variance_m2);
  c.z_min << Scalar(0), T::from_double(-lambda * p.max_abs_doppler_hz);
  c.z_max << T::from_double(p.max_bistatic_range_m), T::from_double(lambda * p.max_abs_doppler_hz);
  return c;
}

/// The PCL measurement model of the parameters.
template <class Scalar>
PclMeasurement<Scalar> pcl_measurement(const PclTrackerParams& p) {
  using T = ScalarTraits<Scalar>;
  PclMeasurement<Scalar> m;
  m.sigma_rb_m = T::from_double(p.sigma_rb_m);
  m.sigma_range_rate_mps = T::from_double(kSpeedOfLightMps / p.carrier_hz * p.sigma_doppler_hz);
  return m;
}

/// The single-point initiator with the zero-Doppler veto of the parameters:
/// |dRb| < lambda * min_start_doppler_hz refuses a start.
template <class Scalar>
PclInitiator<Scalar> pcl_initiator(const PclTrackerParams& p) {
  using T = ScalarTraits<Scalar>;
  PclInitiator<Scalar> init{pcl_measurement<Scalar>(p)};
  init.min_abs << Scalar(0), T::from_double(kSpeedOfLightMps / p.carrier_hz * p.min_start_doppler_hz);
  return init;
}

/// The PCL Kalman filter prototype every track copies.
template <class Scalar>
PclKf<Scalar> pcl_filter(const PclTrackerParams& p) {
  PclMotion<Scalar> motion;
  motion.accel_sigma_mps2 = ScalarTraits<Scalar>::from_double(p.accel_sigma_mps2);
  return PclKf<Scalar>(motion, pcl_measurement<Scalar>(p));
}

/// The PCL tracker with the given parameters and policies.
template <class Scalar, std::size_t kMaxTracks = kPclMaxTracks, std::size_t kMaxCandidates = kPclMaxCandidates,
          template <class, std::size_t, std::size_t> class Associator = NearestNeighbour,
          template <class> class Manager = MOfN>
PclTracker<PclKf<Scalar>, kMaxTracks, kMaxCandidates, Associator, Manager> make_pcl_tracker(
    const PclTrackerParams& p) {
  using Composed = PclTracker<PclKf<Scalar>, kMaxTracks, kMaxCandidates, Associator, Manager>;
  using ManagerT = typename Composed::ManagerT;
  using AssociatorParams = typename Composed::AssociatorParams;
  ManagerT manager{};
  if constexpr (std::is_constructible_v<ManagerT, const SequentialLlrParams&>) manager = ManagerT(pcl_score_params(p));
  AssociatorParams associator{};
  if constexpr (std::is_same_v<AssociatorParams, PdaParams>) associator = pcl_pda_params(p);
  return Composed(pcl_filter<Scalar>(p), pcl_initiator<Scalar>(p), pcl_tracker_config<Scalar>(p), manager,
                  associator);
}

}  // namespace kestrel
