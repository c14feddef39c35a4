// SPDX-License-Identifier: Apache-2.0
// Constant velocity in bistatic range (docs/models.md, CV-1D bistatic; paper
// 002 eq. 1 and 3): state x = [Rb dRb]^T, the bistatic range (m) and its rate
// (m/s), F(dt) = [[1, dt], [0, 1]]. The process noise is the discrete white
// noise acceleration model on Rb (the CV-2D per-axis block of docs/models.md):
// Q(dt) = sa^2 * [[dt^4/4, dt^3/2], [dt^3/2, dt^2]], sa the standard deviation
// of d2Rb/dt2 over one step. Paper 002 leaves Q unstated ("set from the
// observed variation"); PCL-002 uses sa of about 4 m/s^2 (docs/pcl.md).
#pragma once

#include "kestrel/math/eigen.hpp"
#include "kestrel/scalar/scalar_traits.hpp"

namespace kestrel {

template <class S>
struct BistaticCv1D {
  using Scalar = S;
  static constexpr int kStateDim = 2;

  /// Where each quantity sits in the state vector (PX4-style named layout).
  struct Layout {
    static constexpr int kRb = 0;   ///< Bistatic range |p-tx| + |p-rx| - |tx-rx|, m.
    static constexpr int kDRb = 1;  ///< Bistatic range rate dRb/dt, m/s (positive opening).
  };
  static_assert(Layout::kDRb == Layout::kRb + 1, "rate follows range");

  using State = Vec<S, kStateDim>;
  using Cov = Mat<S, kStateDim, kStateDim>;

  S accel_sigma_mps2{};  ///< sa: white-acceleration standard deviation on Rb, m/s^2.

  /// F(dt) = [[1, dt], [0, 1]] (paper 002 eq. 3).
  Cov transition(S dt) const {
    Cov F = Cov::Identity();
    F(Layout::kRb, Layout::kDRb) = dt;
    return F;
  }

  /// Q(dt) = sa^2 [[dt^4/4, dt^3/2], [dt^3/2, dt^2]] (discrete white noise acceleration).
  Cov process_noise(S dt) const {
    const S t2 = dt * dt;
    const S t3 = t2 * dt;
    const S t4 = t3 * dt;
    const S q = accel_sigma_mps2 * accel_sigma_mps2;
    Cov Q;
    Q(Layout::kRb, Layout::kRb) = t4 / S(4);
    Q(Layout::kRb, Layout::kDRb) = t3 / S(2);
    Q(Layout::kDRb, Layout::kRb) = t3 / S(2);
    Q(Layout::kDRb, Layout::kDRb) = t2;
    return Q * q;
  }

  /// Noise-free propagation x(t + dt) = F(dt) x(t).
  State propagate(const State& x, S dt) const { return transition(dt) * x; }

  /// Jacobian of propagate() (the model is linear, so it is F).
  Cov jacobian(const State& /*x*/, S dt) const { return transition(dt); }
};

}  // namespace kestrel
