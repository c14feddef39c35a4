// SPDX-License-Identifier: Apache-2.0
// Passive-radar (PCL) measurement of bistatic range and range rate
// (docs/models.md, bistatic; paper 002 eq. 2). A range-Doppler candidate gives
// [Rb, fD]; the Doppler is converted to the range rate dRb = -lambda * fD
// (lambda = c0 / f_carrier, 0.4277 m for 701 MHz DTV; a target closing in
// bistatic range has a positive Doppler), so the measurement is [Rb, dRb],
// the very quantities of the state: h(x) = H x with H = I and
// R = diag(sigma_Rb^2, sigma_dRb^2), sigma_dRb = lambda * sigma_fD. With the
// linear CV-1D model the tracking filter is therefore a linear KF.
// Templated on the motion model only to read where Rb and dRb sit.
#pragma once

#include "kestrel/math/eigen.hpp"
#include "kestrel/scalar/scalar_traits.hpp"

namespace kestrel {

/// Speed of light in vacuum, m/s (exact by definition of the metre).
inline constexpr double kSpeedOfLightMps = 299792458.0;

/// Carrier wavelength lambda = c0 / f, m. 701 MHz gives 0.42766 m.
template <class S>
S wavelength_m(S carrier_hz) {
  return ScalarTraits<S>::from_double(kSpeedOfLightMps) / carrier_hz;
}

/// Bistatic range rate from Doppler (docs/models.md): dRb = -lambda * fD, m/s.
/// @param doppler_hz fD, Hz; positive for a target closing in bistatic range.
/// @param lambda_m carrier wavelength, m.
template <class S>
S range_rate_from_doppler(S doppler_hz, S lambda_m) {
  return -lambda_m * doppler_hz;
}

/// Inverse of range_rate_from_doppler: fD = -dRb / lambda, Hz.
template <class S>
S doppler_from_range_rate(S range_rate_mps, S lambda_m) {
  return -range_rate_mps / lambda_m;
}

template <class Motion>
struct BistaticRangeRate {
  using Scalar = typename Motion::Scalar;
  static constexpr int kStateDim = Motion::kStateDim;
  static constexpr int kMeasDim = 2;
  static constexpr int kRb = 0;   ///< Index of the bistatic range in a measurement, m.
  static constexpr int kDRb = 1;  ///< Index of the bistatic range rate in a measurement, m/s.

  using State = Vec<Scalar, kStateDim>;
  using StateCov = Mat<Scalar, kStateDim, kStateDim>;
  using Measurement = Vec<Scalar, kMeasDim>;
  using Jacobian = Mat<Scalar, kMeasDim, kStateDim>;
  using NoiseCov = Mat<Scalar, kMeasDim, kMeasDim>;

  Scalar sigma_rb_m{};           ///< Bistatic range noise standard deviation, m.
  Scalar sigma_range_rate_mps{}; ///< Range-rate noise standard deviation (lambda * sigma_fD), m/s.

  /// h(x) = [Rb, dRb].
  Measurement predict(const State& x) const {
    Measurement z;
    z << x(Motion::Layout::kRb), x(Motion::Layout::kDRb);
    return z;
  }

  /// H: a 1 where each measured quantity sits in the state, 0 elsewhere.
  Jacobian jacobian(const State& /*x*/) const {
    Jacobian H = Jacobian::Zero();
    H(kRb, Motion::Layout::kRb) = Scalar(1);
    H(kDRb, Motion::Layout::kDRb) = Scalar(1);
    return H;
  }

  /// R = diag(sigma_Rb^2, sigma_dRb^2).
  NoiseCov noise() const {
    NoiseCov R = NoiseCov::Zero();
    R(kRb, kRb) = sigma_rb_m * sigma_rb_m;
    R(kDRb, kDRb) = sigma_range_rate_mps * sigma_range_rate_mps;
    return R;
  }

  /// z - z_hat (no angle in this measurement, so no wrap).
  Measurement residual(const Measurement& z, const Measurement& z_hat) const { return z - z_hat; }

  /// The state one measurement determines, since it measures every state
  /// quantity: x = z placed by the layout, P = R (the measurement is the only
  /// information). Used by single-point initiation.
  void to_state(const Measurement& z, State& x, StateCov& P) const {
    static_assert(kStateDim == kMeasDim, "one measurement determines the state only if it measures all of it");
    const NoiseCov R = noise();
    x = State::Zero();
    P = StateCov::Zero();
    constexpr int kIdx[kMeasDim] = {Motion::Layout::kRb, Motion::Layout::kDRb};
    for (int i = 0; i < kMeasDim; ++i) {
      x(kIdx[i]) = z(i);
      for (int j = 0; j < kMeasDim; ++j) P(kIdx[i], kIdx[j]) = R(i, j);
    }
  }
};

}  // namespace kestrel
