// SPDX-License-Identifier: Apache-2.0
// Monostatic 2D radar at the origin measuring range, bearing and range rate
// (the polar radar of docs/models.md plus the radial velocity a pulse-Doppler
// radar reports; the wire plot's range_rate_mmps, docs/range_rate.md):
// h(X) = [r, atan2(y, x), (x vx + y vy) / r], r = sqrt(x^2 + y^2),
// R = diag(sr^2, sb^2, srr^2), range rate positive opening. The range-rate
// row depends on position and velocity, so dh/dX has four non-zero columns
// (x, vx, y, vy). residual() wraps the bearing as PolarRadar does; range and
// range rate are not wrapped. For any motion model whose Layout names kX,
// kY, kVx and kVy (CA-2D, CV-2D).
//
// At r = 0 (a target on the radar) range rate, bearing and every Jacobian
// entry that divides by r are undefined: predict() and jacobian() return
// non-finite values there and the filters refuse the update with kNonFinite,
// leaving the state unchanged (PolarRadar's rule).
#pragma once

#include <array>
#include <cstddef>

#include "kestrel/math/atan2.hpp"
#include "kestrel/math/eigen.hpp"
#include "kestrel/models/measurement/polar_radar.hpp"
#include "kestrel/scalar/scalar_traits.hpp"

namespace kestrel {

template <class Motion>
struct PolarRadarRangeRate {
  using Scalar = typename Motion::Scalar;
  static constexpr int kStateDim = Motion::kStateDim;
  static constexpr int kMeasDim = 3;
  static constexpr int kRange = 0;      ///< Index of range in a measurement, m.
  static constexpr int kBearing = 1;    ///< Index of bearing in a measurement, rad.
  static constexpr int kRangeRate = 2;  ///< Index of range rate in a measurement, m/s, + opening.

  using State = Vec<Scalar, kStateDim>;
  using Measurement = Vec<Scalar, kMeasDim>;
  using Jacobian = Mat<Scalar, kMeasDim, kStateDim>;
  using NoiseCov = Mat<Scalar, kMeasDim, kMeasDim>;

  Scalar sigma_range_m{};          ///< sr, range noise standard deviation, m.
  Scalar sigma_bearing_rad{};      ///< sb, bearing noise standard deviation, rad.
  Scalar sigma_range_rate_mps{};   ///< srr, range-rate noise standard deviation, m/s.

  /// h(X) = [r, b, rr]. rr is taken as (x/r) vx + (y/r) vy, the velocity
  /// along the line-of-sight unit vector: the same value as
  /// (x vx + y vy)/r without the product x vx, which would leave Q23.40's
  /// range at S2's 26 km and 235 m/s.
  Measurement predict(const State& x) const {
    using T = ScalarTraits<Scalar>;
    const Scalar px = x(Motion::Layout::kX);
    const Scalar py = x(Motion::Layout::kY);
    const Scalar r = range_of(px, py);
    Measurement z;
    z(kRange) = r;
    z(kBearing) = T::atan2(py, px);
    z(kRangeRate) = px / r * x(Motion::Layout::kVx) + py / r * x(Motion::Layout::kVy);
    return z;
  }

  /// The state columns where dh/dX can be non-zero (x, vx, y, vy):
  /// structure the filters use (kestrel/filters/structure.hpp).
  static constexpr std::array<int, 4> kJacobianColumns = {Motion::Layout::kX, Motion::Layout::kVx,
                                                           Motion::Layout::kY, Motion::Layout::kVy};
  using CompactJacobian = Mat<Scalar, kMeasDim, 4>;

  /// Columns x, vx, y, vy of dh/dX. With u = (x, y)/r the line-of-sight
  /// unit vector and rr = u . v:
  ///   dr/dp = u^T, db/dp = (-y, x)/r^2 (PolarRadar),
  ///   drr/dp = (v - rr u)^T / r  (the velocity across the line of sight,
  ///   over r: d(u . v)/dp = v^T (I - u u^T)/r), drr/dv = u^T.
  /// Range and bearing do not depend on velocity (zeros in columns vx, vy).
  CompactJacobian jacobian_columns(const State& x) const {
    return columns_at(x, range_of(x(Motion::Layout::kX), x(Motion::Layout::kY)));
  }

  /// The same columns where h(x) is already known (z_hat = predict(x)): its
  /// range is the r they need, so the square root is not taken twice.
  CompactJacobian jacobian_columns(const State& x, const Measurement& z_hat) const {
    return columns_at(x, z_hat(kRange));
  }

  /// dh/dX: jacobian_columns() in columns x, vx, y, vy, zero elsewhere.
  Jacobian jacobian(const State& x) const {
    const CompactJacobian Hc = jacobian_columns(x);
    Jacobian H = Jacobian::Zero();
    for (int j = 0; j < 4; ++j) H.col(kJacobianColumns[static_cast<std::size_t>(j)]) = Hc.col(j);
    return H;
  }

  /// R = diag(sr^2, sb^2, srr^2).
  NoiseCov noise() const {
    NoiseCov R = NoiseCov::Zero();
    R(kRange, kRange) = sigma_range_m * sigma_range_m;
    R(kBearing, kBearing) = sigma_bearing_rad * sigma_bearing_rad;
    R(kRangeRate, kRangeRate) = sigma_range_rate_mps * sigma_range_rate_mps;
    return R;
  }

  /// z - z_hat with the bearing difference wrapped to (-pi, pi].
  Measurement residual(const Measurement& z, const Measurement& z_hat) const {
    Measurement nu = z - z_hat;
    nu(kBearing) = wrap_angle(nu(kBearing));
    return nu;
  }

  /// sqrt(x^2 + y^2), as PolarRadar computes it for this scalar.
  static Scalar range_of(Scalar px, Scalar py) { return PolarRadar<Motion>::range_of(px, py); }

  /// Cartesian position of a measurement and its first-order covariance
  /// J R_rb J^T (J = d(x, y)/d(r, b), R_rb the range-bearing block of R);
  /// the range rate does not enter. Used by two-point initiation
  /// (tracking/two_point_initiator.hpp).
  void to_position(const Measurement& z, Vec<Scalar, 2>& p, Mat<Scalar, 2, 2>& P) const {
    range_bearing().to_position(z.template head<2>(), p, P);
  }

  /// The range-bearing radar this one extends (same sr and sb).
  PolarRadar<Motion> range_bearing() const {
    PolarRadar<Motion> rb;
    rb.sigma_range_m = sigma_range_m;
    rb.sigma_bearing_rad = sigma_bearing_rad;
    return rb;
  }

 private:
  /// Columns x, vx, y, vy of dh/dX at x, whose range r = sqrt(x^2 + y^2) is given.
  CompactJacobian columns_at(const State& x, Scalar r) const {
    using T = ScalarTraits<Scalar>;
    const Scalar px = x(Motion::Layout::kX);
    const Scalar py = x(Motion::Layout::kY);
    const Scalar vx = x(Motion::Layout::kVx);
    const Scalar vy = x(Motion::Layout::kVy);
    const Scalar ux = px / r;
    const Scalar uy = py / r;
    const Scalar rr = ux * vx + uy * vy;
    constexpr int kCx = 0, kCvx = 1, kCy = 2, kCvy = 3;  // order of kJacobianColumns
    CompactJacobian Hc = CompactJacobian::Zero();
    Hc(kRange, kCx) = ux;
    Hc(kRange, kCy) = uy;
    if constexpr (T::kIsFixedPoint) {
      // r^2 would leave Q23.40's range beyond 2.9 km: divide by r twice.
      Hc(kBearing, kCx) = -uy / r;
      Hc(kBearing, kCy) = ux / r;
    } else {
      const Scalar r2 = r * r;
      Hc(kBearing, kCx) = -py / r2;
      Hc(kBearing, kCy) = px / r2;
    }
    Hc(kRangeRate, kCx) = (vx - rr * ux) / r;
    Hc(kRangeRate, kCy) = (vy - rr * uy) / r;
    Hc(kRangeRate, kCvx) = ux;
    Hc(kRangeRate, kCvy) = uy;
    return Hc;
  }
};

}  // namespace kestrel
