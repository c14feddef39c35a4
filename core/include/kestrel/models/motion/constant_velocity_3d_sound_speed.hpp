// SPDX-License-Identifier: Apache-2.0
// Constant velocity in 3D with the sound speed as an extra random-walk state
// (docs/models.md, CV-3D + sound speed; paper 003 eq. 2 and 4-5). State
// X = [x y z vx vy vz c]^T, depth z positive downward. Per axis the position
// and velocity follow the discrete white-noise-acceleration model
// (Q1D = sa^2 * [[T^4/4, T^3/2], [T^3/2, T^2]], the same form as CV-2D);
// the effective sound speed c is a random walk whose variance grows by
// qc * T (qc in (m/s)^2/s, i.e. a sigma of sqrt(qc) m/s per sqrt(s)).
// The paper prints only "F for constant velocity" and an unnamed Q; these
// two noise forms are the project's choice (docs/sonar.md).
#pragma once

#include "kestrel/math/eigen.hpp"
#include "kestrel/scalar/scalar_traits.hpp"

namespace kestrel {

template <class S>
struct ConstantVelocity3DSoundSpeed {
  using Scalar = S;
  static constexpr int kStateDim = 7;
  static constexpr int kPosDim = 3;

  /// Where each quantity sits in the state vector (PX4-style named layout).
  struct Layout {
    static constexpr int kX = 0;   ///< x (east-like) position, m, beacon frame.
    static constexpr int kY = 1;   ///< y (north-like) position, m, beacon frame.
    static constexpr int kZ = 2;   ///< depth, m, positive downward.
    static constexpr int kVx = 3;  ///< x velocity, m/s.
    static constexpr int kVy = 4;  ///< y velocity, m/s.
    static constexpr int kVz = 5;  ///< depth rate, m/s, positive downward.
    static constexpr int kC = 6;   ///< effective sound speed, m/s.
    static constexpr int kPos = kX;  ///< First of the three position entries.
    static constexpr int kVel = kVx; ///< First of the three velocity entries.
  };
  static_assert(Layout::kVx == Layout::kX + kPosDim && Layout::kC == kStateDim - 1,
                "position block, then velocity block, then sound speed");

  using State = Vec<S, kStateDim>;
  using Cov = Mat<S, kStateDim, kStateDim>;

  S accel_sigma_mps2{};       ///< sa: white acceleration sigma per axis, m/s^2.
  S sound_speed_q_m2ps3{};    ///< qc: sound-speed random-walk rate, (m/s)^2 per s.

  /// F(dt): position += dt * velocity; velocity and c carried over.
  Cov transition(S dt) const {
    Cov F = Cov::Identity();
    for (int a = 0; a < kPosDim; ++a) F(Layout::kPos + a, Layout::kVel + a) = dt;
    return F;
  }

  /// Q(dt): per axis sa^2 * [[T^4/4, T^3/2], [T^3/2, T^2]]; qc * T on c.
  Cov process_noise(S dt) const {
    const S t2 = dt * dt;
    const S q = accel_sigma_mps2 * accel_sigma_mps2;
    Cov Q = Cov::Zero();
    for (int a = 0; a < kPosDim; ++a) {
      const int p = Layout::kPos + a;
      const int v = Layout::kVel + a;
      Q(p, p) = q * t2 * t2 / S(4);
      Q(p, v) = q * t2 * dt / S(2);
      Q(v, p) = Q(p, v);
      Q(v, v) = q * t2;
    }
    Q(Layout::kC, Layout::kC) = sound_speed_q_m2ps3 * dt;
    return Q;
  }

  /// Noise-free propagation x(t + dt) = F(dt) x(t).
  State propagate(const State& x, S dt) const { return transition(dt) * x; }

  /// Jacobian of propagate() (the model is linear, so it is F).
  Cov jacobian(const State& /*x*/, S dt) const { return transition(dt); }
};

}  // namespace kestrel
