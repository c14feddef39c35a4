// SPDX-License-Identifier: Apache-2.0
// Coordinated-turn motion in the plane with the turn rate in the state
// (CT-2D, the manoeuvre model of the IMM; Bar-Shalom, Li, Kirubarajan 2001,
// section 11.7, the coordinated turn with unknown turn rate). State
// X = [x vx y vy w]^T, w in rad/s counter-clockwise; over a step T the speed
// is constant and the velocity turns by a = w T. sin(a)/w, (1 - cos a)/w and
// their derivatives in w are 0/0 at w = 0, so below |a| = kSeriesLimit they
// come from their Taylor series in a: w -> 0 is exactly constant velocity,
// with no division by w and no cancellation. Process noise: DWNA in x and y
// (as CV-2D) and a turn-rate random walk (Q_ww = sw^2 T). Nonlinear, so it
// exposes no block structure and the Ekf takes its dense path. Equations:
// docs/imm.md, "CT-2D".
#pragma once

#include "kestrel/math/eigen.hpp"
#include "kestrel/scalar/scalar_traits.hpp"

namespace kestrel {

template <class S>
struct CoordinatedTurn2D {
  using Scalar = S;
  static constexpr int kStateDim = 5;

  /// Where each quantity sits in the state vector (PX4-style named layout).
  struct Layout {
    static constexpr int kX = 0;   ///< x position, m
    static constexpr int kVx = 1;  ///< x velocity, m/s
    static constexpr int kY = 2;   ///< y position, m
    static constexpr int kVy = 3;  ///< y velocity, m/s
    static constexpr int kW = 4;   ///< turn rate, rad/s (counter-clockwise positive)
  };

  using State = Vec<S, kStateDim>;
  using Cov = Mat<S, kStateDim, kStateDim>;

  /// Below this |w T| (rad) the turn coefficients use their series: their
  /// truncation error (the a^12 term, < 1e-14 relative at 0.3) is below the
  /// cancellation error of the closed forms there (eps / a^3 in the
  /// derivatives, 1e-14 in double and 2e-6 in float).
  static constexpr double kSeriesLimit = 0.3;

  S sa{};  ///< Standard deviation of the white acceleration, m/s^2 (per axis).
  S sw{};  ///< Turn-rate random walk, rad/s per sqrt(s) (Q_ww = sw^2 T).

  /// s1 = sin(wT)/w, c1 = (1 - cos(wT))/w and their derivatives in w.
  struct TurnCoefficients {
    S sin_a;   ///< sin(wT)
    S cos_a;   ///< cos(wT)
    S s1;      ///< sin(wT)/w, s (T at w = 0)
    S c1;      ///< (1 - cos(wT))/w, s (0 at w = 0)
    S ds1_dw;  ///< d s1 / dw, s^2
    S dc1_dw;  ///< d c1 / dw, s^2
  };

  static TurnCoefficients coefficients(S w, S dt) {
    using T = ScalarTraits<S>;
    const S a = w * dt;
    TurnCoefficients c{T::sin(a), T::cos(a), S(0), S(0), S(0), S(0)};
    if (T::abs(a) < S(kSeriesLimit)) {
      // With p_k = (-1)^k a^2k / (2k+1)!: sin(a)/a = sum p_k,
      // d/da sin(a)/a = -a sum p_k / (2k+3), (1 - cos a)/a = a sum p_k / (2k+2),
      // d/da (1 - cos a)/a = sum p_k (2k+1) / (2k+2); six terms reach a^11.
      const S a2 = a * a;
      S p = S(1);
      S sinc = S(0), dsinc = S(0), cosc = S(0), dcosc = S(0);
      for (int k = 0; k < 6; ++k) {
        const S twok = S(2 * k);
        const S q = p / (twok + S(2));
        sinc += p;
        dsinc += p / (twok + S(3));
        cosc += q;
        dcosc += q * (twok + S(1));
        p = -p * a2 / ((twok + S(2)) * (twok + S(3)));
      }
      dsinc = -a * dsinc;
      cosc = a * cosc;
      c.s1 = dt * sinc;
      c.c1 = dt * cosc;
      c.ds1_dw = dt * dt * dsinc;
      c.dc1_dw = dt * dt * dcosc;
    } else {
      const S inv_w = S(1) / w;
      c.s1 = c.sin_a * inv_w;
      c.c1 = (S(1) - c.cos_a) * inv_w;
      // d/dw sin(wT)/w = (T cos(wT) - s1)/w, d/dw (1 - cos(wT))/w = (T sin(wT) - c1)/w.
      c.ds1_dw = (dt * c.cos_a - c.s1) * inv_w;
      c.dc1_dw = (dt * c.sin_a - c.c1) * inv_w;
    }
    return c;
  }

  /// Noise-free propagation (header comment).
  State propagate(const State& x, S dt) const {
    const TurnCoefficients c = coefficients(x(Layout::kW), dt);
    const S vx = x(Layout::kVx);
    const S vy = x(Layout::kVy);
    State out;
    out(Layout::kX) = x(Layout::kX) + c.s1 * vx - c.c1 * vy;
    out(Layout::kVx) = c.cos_a * vx - c.sin_a * vy;
    out(Layout::kY) = x(Layout::kY) + c.c1 * vx + c.s1 * vy;
    out(Layout::kVy) = c.sin_a * vx + c.cos_a * vy;
    out(Layout::kW) = x(Layout::kW);
    return out;
  }

  /// d propagate / dX: the transition above differentiated, with the
  /// series coefficients near w = 0.
  Cov jacobian(const State& x, S dt) const {
    const TurnCoefficients c = coefficients(x(Layout::kW), dt);
    const S vx = x(Layout::kVx);
    const S vy = x(Layout::kVy);
    Cov F = Cov::Zero();
    F(Layout::kX, Layout::kX) = S(1);
    F(Layout::kX, Layout::kVx) = c.s1;
    F(Layout::kX, Layout::kVy) = -c.c1;
    F(Layout::kX, Layout::kW) = c.ds1_dw * vx - c.dc1_dw * vy;
    F(Layout::kVx, Layout::kVx) = c.cos_a;
    F(Layout::kVx, Layout::kVy) = -c.sin_a;
    // d cos(wT)/dw = -T sin(wT), d sin(wT)/dw = T cos(wT).
    F(Layout::kVx, Layout::kW) = -dt * (c.sin_a * vx + c.cos_a * vy);
    F(Layout::kY, Layout::kY) = S(1);
    F(Layout::kY, Layout::kVx) = c.c1;
    F(Layout::kY, Layout::kVy) = c.s1;
    F(Layout::kY, Layout::kW) = c.dc1_dw * vx + c.ds1_dw * vy;
    F(Layout::kVy, Layout::kVx) = c.sin_a;
    F(Layout::kVy, Layout::kVy) = c.cos_a;
    F(Layout::kVy, Layout::kW) = dt * (c.cos_a * vx - c.sin_a * vy);
    F(Layout::kW, Layout::kW) = S(1);
    return F;
  }

  /// Q(dt): DWNA sa^2 [[T^4/4, T^3/2], [T^3/2, T^2]] on (x, vx) and on
  /// (y, vy), sw^2 T on w.
  Cov process_noise(S dt) const {
    const S t2 = dt * dt;
    const S q2 = sa * sa;
    Cov Q = Cov::Zero();
    constexpr int kPos[2] = {Layout::kX, Layout::kY};
    constexpr int kVel[2] = {Layout::kVx, Layout::kVy};
    for (int i = 0; i < 2; ++i) {
      Q(kPos[i], kPos[i]) = q2 * t2 * t2 / S(4);
      Q(kPos[i], kVel[i]) = q2 * t2 * dt / S(2);
      Q(kVel[i], kPos[i]) = Q(kPos[i], kVel[i]);
      Q(kVel[i], kVel[i]) = q2 * t2;
    }
    Q(Layout::kW, Layout::kW) = sw * sw * dt;
    return Q;
  }
};

}  // namespace kestrel
