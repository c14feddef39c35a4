// SPDX-License-Identifier: Apache-2.0
// Constant-velocity motion in the plane with discrete white-noise
// acceleration (DWNA) process noise (docs/models.md, CV-2D; the target model
// of paper 001, section 2 and eq. 1). State X = [x vx y vy]^T: two
// independent 2-state axes, F = blkdiag(F1, F1) with F1 = [[1, T], [0, 1]],
// and Q = blkdiag(Q1D, Q1D) with Q1D = sa^2 * [[T^4/4, T^3/2], [T^3/2, T^2]]
// (Bar-Shalom, Li, Kirubarajan 2001, section 6.3.2): the acceleration is
// constant over a step and white between steps, so Q1D = sa^2 * G1 G1^T with
// G1 = [T^2/2, T]^T. Q is therefore rank 2 (singular): filters that need a
// square root of Q use noise_gain() or a semidefinite factorisation.
#pragma once

#include "kestrel/math/eigen.hpp"
#include "kestrel/scalar/scalar_traits.hpp"

namespace kestrel {

template <class S>
struct ConstantVelocity2D {
  using Scalar = S;
  static constexpr int kStateDim = 4;
  static constexpr int kAxisDim = 2;
  /// F1 is unit upper triangular (structure the filters exploit,
  /// kestrel/filters/structure.hpp).
  static constexpr bool kAxisTransitionUnitUpper = true;
  static constexpr int kNoiseDim = 2;  ///< One acceleration input per axis.

  /// Where each quantity sits in the state vector (PX4-style named layout).
  struct Layout {
    static constexpr int kX = 0;   ///< x position, m
    static constexpr int kVx = 1;  ///< x velocity, m/s
    static constexpr int kY = 2;   ///< y position, m
    static constexpr int kVy = 3;  ///< y velocity, m/s
  };
  static_assert(Layout::kY == Layout::kX + kAxisDim, "axes are consecutive blocks");
  static_assert(Layout::kVy == Layout::kVx + kAxisDim, "axes are consecutive blocks");

  using State = Vec<S, kStateDim>;
  using Cov = Mat<S, kStateDim, kStateDim>;
  using AxisMat = Mat<S, kAxisDim, kAxisDim>;
  using NoiseGain = Mat<S, kStateDim, kNoiseDim>;

  S sa{};  ///< Standard deviation of the white acceleration, m/s^2 (per axis).

  /// F1(dt) = [[1, T], [0, 1]].
  AxisMat axis_transition(S dt) const {
    AxisMat F1 = AxisMat::Identity();
    F1(0, 1) = dt;
    return F1;
  }

  /// Q1D(dt) = sa^2 * [[T^4/4, T^3/2], [T^3/2, T^2]].
  AxisMat axis_process_noise(S dt) const {
    const S t2 = dt * dt;
    const S t3 = t2 * dt;
    const S t4 = t3 * dt;
    AxisMat Q1;
    Q1 << t4 / S(4), t3 / S(2),
          t3 / S(2), t2;
    return Q1 * (sa * sa);
  }

  /// F(dt) = blkdiag(F1, F1).
  Cov transition(S dt) const {
    Cov F = Cov::Zero();
    const AxisMat F1 = axis_transition(dt);
    F.template block<kAxisDim, kAxisDim>(0, 0) = F1;
    F.template block<kAxisDim, kAxisDim>(kAxisDim, kAxisDim) = F1;
    return F;
  }

  /// Q(dt) = blkdiag(Q1D, Q1D) = sa^2 * G G^T.
  Cov process_noise(S dt) const {
    Cov Q = Cov::Zero();
    const AxisMat Q1 = axis_process_noise(dt);
    Q.template block<kAxisDim, kAxisDim>(0, 0) = Q1;
    Q.template block<kAxisDim, kAxisDim>(kAxisDim, kAxisDim) = Q1;
    return Q;
  }

  /// G(dt): how a unit acceleration held over the step moves the state,
  /// column a for axis a: [T^2/2, T] in that axis' rows. x+ = F x + G a with
  /// a ~ N(0, sa^2 I) has exactly the covariance Q(dt). Used by the CRPF's
  /// particle kick and as an exact square root of Q (sa * G).
  NoiseGain noise_gain(S dt) const {
    NoiseGain G = NoiseGain::Zero();
    G(Layout::kX, 0) = dt * dt / S(2);
    G(Layout::kVx, 0) = dt;
    G(Layout::kY, 1) = dt * dt / S(2);
    G(Layout::kVy, 1) = dt;
    return G;
  }

  /// Noise-free propagation x(t + dt) = F(dt) x(t), written out per axis.
  State propagate(const State& x, S dt) const {
    State out;
    out(Layout::kX) = x(Layout::kX) + dt * x(Layout::kVx);
    out(Layout::kVx) = x(Layout::kVx);
    out(Layout::kY) = x(Layout::kY) + dt * x(Layout::kVy);
    out(Layout::kVy) = x(Layout::kVy);
    return out;
  }

  /// Jacobian of propagate() (the model is linear, so it is F).
  Cov jacobian(const State& /*x*/, S dt) const { return transition(dt); }
};

}  // namespace kestrel
