// SPDX-License-Identifier: Apache-2.0
// Constant-acceleration motion in the plane with white-jerk process noise
// (docs/models.md, CA-2D; R2-AEKF paper 000, section 2-1). State
// X = [x vx ax y vy ay]^T: two independent 3-state axes, so F and Q are
// block-diagonal blkdiag(F1, F1), blkdiag(Q1D, Q1D). The per-axis blocks are
// public because the adaptive filter (R2-AEKF) scales Q per axis.
#pragma once

#include "kestrel/math/eigen.hpp"
#include "kestrel/scalar/scalar_traits.hpp"

namespace kestrel {

template <class S>
struct ConstantAcceleration2D {
  using Scalar = S;
  static constexpr int kStateDim = 6;
  static constexpr int kAxisDim = 3;
  /// F1 is unit upper triangular (structure the filters exploit,
  /// kestrel/filters/structure.hpp).
  static constexpr bool kAxisTransitionUnitUpper = true;

  /// Where each quantity sits in the state vector (PX4-style named layout).
  struct Layout {
    static constexpr int kX = 0;    ///< x position, m
    static constexpr int kVx = 1;   ///< x velocity, m/s
    static constexpr int kAx = 2;   ///< x acceleration, m/s^2
    static constexpr int kY = 3;    ///< y position, m
    static constexpr int kVy = 4;   ///< y velocity, m/s
    static constexpr int kAy = 5;   ///< y acceleration, m/s^2
  };
  static_assert(Layout::kY == Layout::kX + kAxisDim, "axes are consecutive blocks");

  using State = Vec<S, kStateDim>;
  using Cov = Mat<S, kStateDim, kStateDim>;
  using AxisMat = Mat<S, kAxisDim, kAxisDim>;

  S qj{};  ///< White-jerk power spectral density, m^2/s^5 (per axis).

  /// x / n for the constant divisors of F1, Q1D and the propagation: a
  /// fixed-point scalar multiplies by the constant 1/n instead (a division
  /// is a 64-step loop there; 1/n is rounded once, exact for 2 and 8),
  /// floating point divides.
  template <int n>
  static S over(S x) {
    if constexpr (ScalarTraits<S>::kIsFixedPoint) {
      return x * S(1.0 / n);
    } else {
      return x / S(n);
    }
  }

  /// F1(dt) = [[1, T, T^2/2], [0, 1, T], [0, 0, 1]].
  AxisMat axis_transition(S dt) const {
    AxisMat F1 = AxisMat::Identity();
    F1(0, 1) = dt;
    F1(0, 2) = over<2>(dt * dt);
    F1(1, 2) = dt;
    return F1;
  }

  /// Q1D(dt) = qj * [[T^5/20, T^4/8, T^3/6], [T^4/8, T^3/3, T^2/2], [T^3/6, T^2/2, T]]
  /// (continuous white jerk integrated over one step).
  AxisMat axis_process_noise(S dt) const {
    const S t2 = dt * dt;
    const S t3 = t2 * dt;
    const S t4 = t3 * dt;
    const S t5 = t4 * dt;
    const S q02 = over<6>(t3) * qj;
    const S q01 = over<8>(t4) * qj;
    const S q12 = over<2>(t2) * qj;
    AxisMat Q1;
    Q1(0, 0) = over<20>(t5) * qj;
    Q1(0, 1) = q01;
    Q1(0, 2) = q02;
    Q1(1, 0) = q01;
    Q1(1, 1) = over<3>(t3) * qj;
    Q1(1, 2) = q12;
    Q1(2, 0) = q02;
    Q1(2, 1) = q12;
    Q1(2, 2) = dt * qj;
    return Q1;
  }

  /// F(dt) = blkdiag(F1, F1).
  Cov transition(S dt) const {
    Cov F = Cov::Zero();
    const AxisMat F1 = axis_transition(dt);
    F.template block<kAxisDim, kAxisDim>(0, 0) = F1;
    F.template block<kAxisDim, kAxisDim>(kAxisDim, kAxisDim) = F1;
    return F;
  }

  /// Q(dt) = blkdiag(Q1D, Q1D).
  Cov process_noise(S dt) const {
    Cov Q = Cov::Zero();
    const AxisMat Q1 = axis_process_noise(dt);
    Q.template block<kAxisDim, kAxisDim>(0, 0) = Q1;
    Q.template block<kAxisDim, kAxisDim>(kAxisDim, kAxisDim) = Q1;
    return Q;
  }

  /// Noise-free propagation x(t + dt) = F(dt) x(t), per axis.
  State propagate(const State& x, S dt) const {
    const S half_t2 = over<2>(dt * dt);
    State out;
    for (int a = 0; a < kStateDim; a += kAxisDim) {
      out(a) = x(a) + dt * x(a + 1) + half_t2 * x(a + 2);
      out(a + 1) = x(a + 1) + dt * x(a + 2);
      out(a + 2) = x(a + 2);
    }
    return out;
  }

  /// Jacobian of propagate() (the model is linear, so it is F).
  Cov jacobian(const State& /*x*/, S dt) const { return transition(dt); }
};

}  // namespace kestrel
