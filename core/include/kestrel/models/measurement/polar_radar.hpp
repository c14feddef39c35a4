// SPDX-License-Identifier: Apache-2.0
// Monostatic 2D radar at the origin measuring range and bearing
// (docs/models.md; paper 000 eq. 3-4): h(X) = [sqrt(x^2+y^2), atan2(y, x)],
// R = diag(sr^2, sb^2). Bearing is counter-clockwise from +x. residual()
// is the only place a bearing innovation is wrapped to (-pi, pi].
// Templated on the motion model only to read where x and y sit in its state.
#pragma once

#include <array>

#include "kestrel/math/eigen.hpp"
#include "kestrel/scalar/scalar_traits.hpp"

namespace kestrel {

template <class Motion>
struct PolarRadar {
  using Scalar = typename Motion::Scalar;
  static constexpr int kStateDim = Motion::kStateDim;
  static constexpr int kMeasDim = 2;
  static constexpr int kRange = 0;    ///< Index of range in a measurement, m.
  static constexpr int kBearing = 1;  ///< Index of bearing in a measurement, rad.

  using State = Vec<Scalar, kStateDim>;
  using Measurement = Vec<Scalar, kMeasDim>;
  using Jacobian = Mat<Scalar, kMeasDim, kStateDim>;
  using NoiseCov = Mat<Scalar, kMeasDim, kMeasDim>;

  Scalar sigma_range_m{};      ///< sr, range noise standard deviation, m.
  Scalar sigma_bearing_rad{};  ///< sb, bearing noise standard deviation, rad.

  /// h(X) = [r, b].
  Measurement predict(const State& x) const {
    using T = ScalarTraits<Scalar>;
    const Scalar px = x(Motion::Layout::kX);
    const Scalar py = x(Motion::Layout::kY);
    Measurement z;
    z(kRange) = range_of(px, py);
    z(kBearing) = T::atan2(py, px);
    return z;
  }

  /// The state columns where dh/dX can be non-zero, x and y: structure the
  /// filters use (kestrel/filters/structure.hpp).
  static constexpr std::array<int, 2> kJacobianColumns = {Motion::Layout::kX, Motion::Layout::kY};
  using CompactJacobian = Mat<Scalar, kMeasDim, 2>;

  /// Columns x and y of dh/dX: dr/dx = x/r, dr/dy = y/r, db/dx = -y/r^2,
  /// db/dy = x/r^2. At r = 0 the entries are non-finite and the filter
  /// refuses the update with kNonFinite (the radar cannot see a target on
  /// itself).
  CompactJacobian jacobian_columns(const State& x) const {
    return columns_at(x, range_of(x(Motion::Layout::kX), x(Motion::Layout::kY)));
  }

  /// The same columns where h(x) is already known (z_hat = predict(x)): its
  /// range is the r they need, so the square root is not taken twice (a
  /// 64-step loop in fixed point).
  CompactJacobian jacobian_columns(const State& x, const Measurement& z_hat) const {
    return columns_at(x, z_hat(kRange));
  }

  /// dh/dX: jacobian_columns() in columns x and y, zero elsewhere.
  Jacobian jacobian(const State& x) const {
    const CompactJacobian Hc = jacobian_columns(x);
    Jacobian H = Jacobian::Zero();
    H.col(Motion::Layout::kX) = Hc.col(0);
    H.col(Motion::Layout::kY) = Hc.col(1);
    return H;
  }

  /// R = diag(sr^2, sb^2).
  NoiseCov noise() const {
    NoiseCov R = NoiseCov::Zero();
    R(kRange, kRange) = sigma_range_m * sigma_range_m;
    R(kBearing, kBearing) = sigma_bearing_rad * sigma_bearing_rad;
    return R;
  }

  /// z - z_hat with the bearing difference wrapped to (-pi, pi].
  Measurement residual(const Measurement& z, const Measurement& z_hat) const {
    Measurement nu = z - z_hat;
    nu(kBearing) = wrap_angle(nu(kBearing));
    return nu;
  }

  /// residual(z, predict(x)) of the many states of a particle filter
  /// against one z (the CRPF's risk and cost, paper 001 eqs. 5-6), prepared
  /// once per update about a reference state near them (the CRPF passes its
  /// predicted mean). Floating point: the bearing of x is the reference's
  /// bearing plus the angle between the two position vectors, atan(cross /
  /// dot), which a short series gives while its tangent is below 1/16;
  /// x further out, or a reference that is not finite or sits on the radar,
  /// takes the full atan2, bit for bit residual(z, predict(x)). Within 4 ulp
  /// of pi of the exact residual either way, not bit-identical to
  /// residual(z, predict(x)) (tests/core/models/polar_radar_particle_residual_test.cpp;
  /// why: docs/filters.md, "CRPF h(x) about the cloud's mean"). Fixed point:
  /// always the full path.
  class ParticleResiduals {
   public:
    ParticleResiduals(const Measurement& z, const State& ref)
        : z_(z), ref_x_(ref(Motion::Layout::kX)), ref_y_(ref(Motion::Layout::kY)) {
      using T = ScalarTraits<Scalar>;
      ref_residual_ = wrap_angle(z(kBearing) - T::atan2(ref_y_, ref_x_));
      reference_serves_ = T::is_finite(ref_residual_) && T::is_finite(ref_x_) && T::is_finite(ref_y_);
    }

    Measurement operator()(const State& x) const {
      using T = ScalarTraits<Scalar>;
      const Scalar px = x(Motion::Layout::kX);
      const Scalar py = x(Motion::Layout::kY);
      const Scalar range_residual = z_(kRange) - range_of(px, py);
      // Built whole in each return: filled element by element, GCC stores
      // the halves and reloads them as one vector (a stall per particle).
      if constexpr (!T::kIsFixedPoint) {
        // x's bearing minus the reference's is atan2(cross, dot) of the two
        // position vectors: the series while 16 |cross| < dot (false for a
        // NaN, and for x on the radar or not in front of the reference).
        const Scalar dot = ref_x_ * px + ref_y_ * py;
        const Scalar cross = ref_x_ * py - ref_y_ * px;
        if (reference_serves_ && T::abs(cross) * Scalar(16) < dot) {
          return Measurement(range_residual, wrap_angle(ref_residual_ - small_atan(cross / dot)));
        }
      }
      return Measurement(range_residual, wrap_angle(z_(kBearing) - T::atan2(py, px)));
    }

   private:
    /// atan(u) for |u| < 1/16: the Taylor series u - u^3/3 + u^5/5 - ...
    /// up to u^11 in double and u^5 in float, whose first term left out,
    /// |u|^13/13 < 2^-55 (double) and |u|^7/7 < 2^-30 (float), bounds the
    /// error (an alternating series).
    static Scalar small_atan(Scalar u) {
      const Scalar z = u * u;
      Scalar p;
      if constexpr (sizeof(Scalar) == 8) {
        p = Scalar(1.0 / 11);
        p = Scalar(-1.0 / 9) + z * p;
        p = Scalar(1.0 / 7) + z * p;
        p = Scalar(-1.0 / 5) + z * p;
        p = Scalar(1.0 / 3) + z * p;
      } else {
        p = Scalar(-1.0 / 5);
        p = Scalar(1.0 / 3) + z * p;
      }
      return u - u * (z * p);
    }

    Measurement z_;
    Scalar ref_x_;
    Scalar ref_y_;
    Scalar ref_residual_{};  ///< wrap(z_b - bearing of the reference).
    bool reference_serves_ = false;
  };

  ParticleResiduals particle_residuals(const Measurement& z, const State& ref) const {
    return ParticleResiduals(z, ref);
  }

  /// sqrt(x^2 + y^2). Floating point: the plain formula (no overflow below
  /// 1e154 m in double and 1e19 m in float, and within an ulp of
  /// std::hypot, whose rescaling is costly twice per update). Fixed point:
  /// its own hypot, which keeps the squares inside the Q range.
  static Scalar range_of(Scalar px, Scalar py) {
    using T = ScalarTraits<Scalar>;
    if constexpr (T::kIsFixedPoint) {
      return T::hypot(px, py);
    } else {
      return T::sqrt(px * px + py * py);
    }
  }

  /// Cartesian position of a measurement and its first-order covariance
  /// J R J^T (J = d(x, y)/d(r, b)); used by two-point initiation.
  void to_position(const Measurement& z, Vec<Scalar, 2>& p, Mat<Scalar, 2, 2>& P) const {
    using T = ScalarTraits<Scalar>;
    const Scalar c = T::cos(z(kBearing));
    const Scalar s = T::sin(z(kBearing));
    p << z(kRange) * c, z(kRange) * s;
    Mat<Scalar, 2, 2> J;
    J << c, -z(kRange) * s,
         s, z(kRange) * c;
    P = J * noise() * J.transpose();
  }

 private:
  /// Columns x and y of dh/dX at x, whose range r = sqrt(x^2 + y^2) is given.
  CompactJacobian columns_at(const State& x, Scalar r) const {
    using T = ScalarTraits<Scalar>;
    const Scalar px = x(Motion::Layout::kX);
    const Scalar py = x(Motion::Layout::kY);
    CompactJacobian Hc;
    if constexpr (T::kIsFixedPoint) {
      // One division (a 64-step loop in fixed point) instead of four: the
      // reciprocal 2^16 / r, scaled so that it keeps its relative precision
      // at long range (Q31.32 at 10 km: 4e-11 instead of 2e-6 for 1 / r),
      // each product then taken back by 2^-16 (exact scale, one rounding).
      // r^2 would leave Q23.40's range beyond 2.9 km, so the bearing row
      // applies 1/r twice. Below r = 2^16 LSB (Q31.32: 15 um) the
      // reciprocal saturates and the update is refused (kNonFinite), as at
      // r = 0.
      constexpr Scalar kScale(65536.0);
      constexpr Scalar kUnscale(1.0 / 65536.0);
      const Scalar inv_r = kScale / r;
      Hc(kRange, 0) = px * inv_r * kUnscale;
      Hc(kRange, 1) = py * inv_r * kUnscale;
      Hc(kBearing, 0) = -Hc(kRange, 1) * inv_r * kUnscale;
      Hc(kBearing, 1) = Hc(kRange, 0) * inv_r * kUnscale;
    } else {
      Hc(kRange, 0) = px / r;
      Hc(kRange, 1) = py / r;
      const Scalar r2 = r * r;
      Hc(kBearing, 0) = -py / r2;
      Hc(kBearing, 1) = px / r2;
    }
    return Hc;
  }
};

}  // namespace kestrel
