// SPDX-License-Identifier: Apache-2.0
// Shared by the sigma-point and CRPF tests: a linear position-only
// measurement (for the "equals the Kalman filter" checks), the S1 zig-zag
// truth of docs/scenarios.md with seeded polar measurements, the MC-001 truth
// (CV-2D with white acceleration), a textbook KF in dynamic double Eigen, and
// the relative-difference measure the square-root tests use.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "kestrel/math/eigen.hpp"
#include "kestrel/math/prng.hpp"

namespace kestrel::test {

inline constexpr double kPi = 3.14159265358979323846;

/// Linear test measurement: x and y of any motion model with a Layout.
template <class Motion>
struct LinearPosition {
  using Scalar = typename Motion::Scalar;
  using S = Scalar;
  static constexpr int kStateDim = Motion::kStateDim;
  static constexpr int kMeasDim = 2;
  using Measurement = Vec<S, 2>;
  using Jacobian = Mat<S, 2, kStateDim>;
  using NoiseCov = Mat<S, 2, 2>;
  S sigma{};
  Measurement predict(const typename Motion::State& x) const {
    return Measurement(x(Motion::Layout::kX), x(Motion::Layout::kY));
  }
  Jacobian jacobian(const typename Motion::State&) const {
    Jacobian H = Jacobian::Zero();
    H(0, Motion::Layout::kX) = S(1);
    H(1, Motion::Layout::kY) = S(1);
    return H;
  }
  NoiseCov noise() const { return NoiseCov::Identity() * (sigma * sigma); }
  Measurement residual(const Measurement& z, const Measurement& zh) const { return z - zh; }
};

/// Textbook linear KF in double, dynamic Eigen, standard covariance form.
struct ReferenceKf {
  Eigen::VectorXd x;
  Eigen::MatrixXd P;
  void predict(const Eigen::MatrixXd& F, const Eigen::MatrixXd& Q) {
    x = F * x;
    P = F * P * F.transpose() + Q;
  }
  void update(const Eigen::VectorXd& z, const Eigen::MatrixXd& H, const Eigen::MatrixXd& R) {
    const Eigen::MatrixXd S = H * P * H.transpose() + R;
    const Eigen::MatrixXd K = P * H.transpose() * S.inverse();
    x = x + K * (z - H * x);
    P = (Eigen::MatrixXd::Identity(x.size(), x.size()) - K * H) * P;
  }
};

/// S1 zig-zag truth (docs/scenarios.md): position and velocity at time t.
struct S1Truth {
  static void at(double t, double& x, double& y, double& vx, double& vy) {
    double s = 200.0 * t;
    double v = 200.0;
    if (t >= 80.0 && t < 85.0) {
      s += 2.5 * (t - 80.0) * (t - 80.0);
      v += 5.0 * (t - 80.0);
    } else if (t >= 85.0) {
      s += 62.5 + 25.0 * (t - 85.0);
      v += 25.0;
    }
    x = -15000.0 + s;
    y = 8000.0 + 300.0 * std::sin(2.0 * kPi * t / 15.0);
    vx = v;
    vy = 300.0 * 2.0 * kPi / 15.0 * std::cos(2.0 * kPi * t / 15.0);
  }
};

/// One polar measurement [range, bearing] of (x, y) with N(0, s^2) noise,
/// bearing wrapped to (-pi, pi].
inline Eigen::Vector2d polar_measurement(double x, double y, double sr, double sb,
                                         NormalGenerator<double>& n) {
  // The bearing's draw first, in its own statement: as two constructor
  // arguments the draws were unsequenced, and the recorded hashes (CRPF)
  // hold the order GCC gave them, right to left; clang goes left to right.
  const double bearing_noise = sb * n();
  const double range_noise = sr * n();
  Eigen::Vector2d z(std::hypot(x, y) + range_noise, std::atan2(y, x) + bearing_noise);
  z(1) = std::remainder(z(1), 2.0 * kPi);
  return z;
}

/// MC-001 truth (docs/scenarios.md): CV-2D from (1000, 10, 1000, 5), T = 1 s, white
/// acceleration sigma sa per axis; states at k = 0..steps.
inline std::vector<Eigen::Vector4d> mc001_truth(int steps, double sa, NormalGenerator<double>& n) {
  std::vector<Eigen::Vector4d> xs;
  Eigen::Vector4d x(1000.0, 10.0, 1000.0, 5.0);
  xs.push_back(x);
  for (int k = 0; k < steps; ++k) {
    const double ax = sa * n();
    const double ay = sa * n();
    x(0) += x(1) + 0.5 * ax;
    x(1) += ax;
    x(2) += x(3) + 0.5 * ay;
    x(3) += ay;
    xs.push_back(x);
  }
  return xs;
}

/// Largest relative difference of a from b, entry by entry, where each entry
/// is measured against max(|b_ij|, scale_ij): for a state, scale_i is its own
/// standard deviation sqrt(P_ii); for a covariance, sqrt(P_ii P_jj) (the
/// size a correlation of 1 would give). Pure relative difference on entries
/// that are not near zero, and no division by a cancelled cross-term.
template <class A, class B, class P>
double max_relative_state_diff(const A& a, const B& b, const P& Pb) {
  double worst = 0.0;
  for (int i = 0; i < b.size(); ++i) {
    const double ref = std::max(std::fabs(static_cast<double>(b(i))), std::sqrt(static_cast<double>(Pb(i, i))));
    worst = std::max(worst, std::fabs(static_cast<double>(a(i)) - static_cast<double>(b(i))) / ref);
  }
  return worst;
}

template <class A, class B>
double max_relative_cov_diff(const A& a, const B& b) {
  double worst = 0.0;
  for (int i = 0; i < b.rows(); ++i) {
    for (int j = 0; j < b.cols(); ++j) {
      const double scale = std::sqrt(static_cast<double>(b(i, i)) * static_cast<double>(b(j, j)));
      const double ref = std::max(std::fabs(static_cast<double>(b(i, j))), scale);
      worst = std::max(worst, std::fabs(static_cast<double>(a(i, j)) - static_cast<double>(b(i, j))) / ref);
    }
  }
  return worst;
}

}  // namespace kestrel::test
