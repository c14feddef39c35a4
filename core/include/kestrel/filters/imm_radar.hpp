// SPDX-License-Identifier: Apache-2.0
// The radar IMM: three EKF modes with the polar radar, CV-2D (quiet
// flight), CA-2D (along-track and lateral acceleration) and CT-2D (turns),
// mixed by kestrel/filters/imm.hpp and seen by the tracker as a CA-2D
// filter (so it takes the EKF-CA's two-point initiator and reports). The
// parameters are SI doubles, converted once to the filter's scalar.
#pragma once

#include "kestrel/filters/ekf.hpp"
#include "kestrel/filters/imm.hpp"
#include "kestrel/models/measurement/polar_radar.hpp"
#include "kestrel/models/motion/constant_acceleration_2d.hpp"
#include "kestrel/models/motion/constant_velocity_2d.hpp"
#include "kestrel/models/motion/coordinated_turn_2d.hpp"
#include "kestrel/scalar/scalar_traits.hpp"

namespace kestrel {

template <class S>
using ImmCvMode = Ekf<ConstantVelocity2D<S>, PolarRadar<ConstantVelocity2D<S>>>;
template <class S>
using ImmCaMode = Ekf<ConstantAcceleration2D<S>, PolarRadar<ConstantAcceleration2D<S>>>;
template <class S>
using ImmCtMode = Ekf<CoordinatedTurn2D<S>, PolarRadar<CoordinatedTurn2D<S>>>;

/// Mode order: 0 CV, 1 CA, 2 CT.
template <class S>
using RadarImm = Imm<ConstantAcceleration2D<S>, PolarRadar<ConstantAcceleration2D<S>>, ImmCvMode<S>, ImmCaMode<S>,
                     ImmCtMode<S>>;

/// Parameters of the radar IMM. The mode noise and the matrix were tuned on
/// the S1/S2 scenarios (docs/imm.md, with the seeds and commands).
struct RadarImmParams {
  double sigma_range_m = 3.0;                                       ///< sr, m.
  double sigma_bearing_rad = 0.3 * 3.14159265358979323846 / 180.0;  ///< sb, rad.
  double cv_sa_mps2 = 1.0;       ///< CV white acceleration sigma, m/s^2.
  double ca_qj = 100.0;          ///< CA white-jerk PSD, m^2/s^5.
  double ct_sa_mps2 = 1.0;       ///< CT white acceleration sigma, m/s^2.
  double ct_sw_radps = 0.03;     ///< CT turn-rate random walk, rad/s per sqrt(s).
  /// Switching matrix p_ij (row: from, column: to) over switching_period_s.
  double switching[3][3] = {{0.8, 0.1, 0.1}, {0.1, 0.8, 0.1}, {0.1, 0.1, 0.8}};
  /// The period the matrix is given for, s: the scan period of S1/S2.
  /// Other time steps scale it (ImmConfig::switching_over); 0: per predict.
  double switching_period_s = 0.5;
  double initial_probabilities[3] = {1.0 / 3, 1.0 / 3, 1.0 / 3};  ///< At reset().
  double min_probability = 1e-4;          ///< Floor of each mode probability.
  double accel_pad_sigma_mps2 = 10.0;     ///< Acceleration sigma of CV and CT when lifted.
  double turn_rate_pad_sigma_radps = 0.1; ///< Turn-rate sigma of CV, CA and at reset().
};

/// The radar IMM with these parameters in scalar S.
template <class S>
RadarImm<S> make_radar_imm(const RadarImmParams& p) {
  using T = ScalarTraits<S>;
  PolarRadar<ConstantVelocity2D<S>> h_cv;
  PolarRadar<ConstantAcceleration2D<S>> h_ca;
  PolarRadar<CoordinatedTurn2D<S>> h_ct;
  h_cv.sigma_range_m = h_ca.sigma_range_m = h_ct.sigma_range_m = T::from_double(p.sigma_range_m);
  h_cv.sigma_bearing_rad = h_ca.sigma_bearing_rad = h_ct.sigma_bearing_rad = T::from_double(p.sigma_bearing_rad);
  ConstantVelocity2D<S> cv;
  cv.sa = T::from_double(p.cv_sa_mps2);
  ConstantAcceleration2D<S> ca;
  ca.qj = T::from_double(p.ca_qj);
  CoordinatedTurn2D<S> ct;
  ct.sa = T::from_double(p.ct_sa_mps2);
  ct.sw = T::from_double(p.ct_sw_radps);
  typename RadarImm<S>::Config ip;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) ip.switching(i, j) = T::from_double(p.switching[i][j]);
    ip.initial_probabilities(i) = T::from_double(p.initial_probabilities[i]);
  }
  ip.min_probability = T::from_double(p.min_probability);
  ip.accel_pad_sigma_mps2 = T::from_double(p.accel_pad_sigma_mps2);
  ip.turn_rate_pad_sigma_radps = T::from_double(p.turn_rate_pad_sigma_radps);
  ip.switching_period_s = T::from_double(p.switching_period_s);
  return RadarImm<S>(h_ca, ip, ImmCvMode<S>(cv, h_cv), ImmCaMode<S>(ca, h_ca), ImmCtMode<S>(ct, h_ct));
}

}  // namespace kestrel
