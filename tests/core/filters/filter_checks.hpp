// SPDX-License-Identifier: Apache-2.0
// Checks every sigma-point filter must pass, written once and instantiated
// per filter in its own *_test.cpp (ukf_test.cpp, cdkf_test.cpp, ...):
//  - equals the textbook Kalman filter on a linear model (CV-2D, measuring
//    x and y), double and float;
//  - tracks a target whose bearing crosses +-pi exactly as well as the same
//    target rotated by 90 degrees (wrap-safe sigma-point means);
//  - refuses NaN/Inf and indefinite noise with a status, state unchanged;
//  - no heap allocation in reset, predict, innovation or update.
#pragma once

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <type_traits>

#include "core/filters/sigma_test_support.hpp"
#include "kestrel/models/measurement/polar_radar.hpp"
#include "kestrel/models/motion/constant_velocity_2d.hpp"
#include "kestrel/status.hpp"
#include "support/alloc_guard.hpp"

namespace kestrel::test {

/// FilterT<Motion, Measurement> on CV-2D with a linear position measurement
/// against ReferenceKf over steps with varying dt.
template <template <class, class> class FilterT, class S>
void check_equals_kalman_filter() {
  using Motion = ConstantVelocity2D<S>;
  using Meas = LinearPosition<Motion>;
  using Filter = FilterT<Motion, Meas>;
  Motion motion;
  motion.sa = S(0.7);
  Meas meas;
  meas.sigma = S(4);
  Filter f(motion, meas);
  typename Filter::State x0;
  x0 << S(100), S(10), S(-50), S(5);
  typename Filter::Cov P0 = Filter::Cov::Identity() * S(100);
  P0(0, 1) = P0(1, 0) = S(20);
  P0(2, 3) = P0(3, 2) = S(-15);
  P0(0, 2) = P0(2, 0) = S(30);
  REQUIRE(f.reset(x0, P0) == Status::kOk);

  ReferenceKf kf{x0.template cast<double>(), P0.template cast<double>()};
  const double dts[] = {1.0, 0.5, 2.0, 1.0, 1.5, 0.25};
  const double zs[][2] = {{111.0, -46.0}, {114.5, -43.0}, {137.0, -33.5},
                          {146.0, -29.0}, {160.5, -21.0}, {163.0, -20.5}};
  for (int k = 0; k < 6; ++k) {
    const S dt = static_cast<S>(dts[k]);
    REQUIRE(f.predict(dt) == Status::kOk);
    typename Filter::MeasVec z(static_cast<S>(zs[k][0]), static_cast<S>(zs[k][1]));
    REQUIRE(f.update(z) == Status::kOk);
    kf.predict(motion.transition(dt).template cast<double>(), motion.process_noise(dt).template cast<double>());
    kf.update(Eigen::Vector2d(zs[k][0], zs[k][1]), meas.jacobian(x0).template cast<double>(),
              meas.noise().template cast<double>());
  }
  // double: a few dozen rounded products per step, six steps: 1e-10 relative
  // to each entry's own scale; float (24-bit mantissa): 1e-4.
  const double tol = std::is_same_v<S, double> ? 1e-10 : 1e-4;
  CHECK(max_relative_state_diff(f.x(), kf.x, kf.P) < tol);
  CHECK(max_relative_cov_diff(f.P(), kf.P) < tol);
  CHECK(f.diagnostics().fused);
}

/// Rotate a CV-2D state by -90 degrees: (x, y) -> (y, -x).
inline Eigen::Matrix4d rotation_minus_90() {
  Eigen::Matrix4d M = Eigen::Matrix4d::Zero();
  M(0, 2) = 1;   // x' = y
  M(1, 3) = 1;   // vx' = vy
  M(2, 0) = -1;  // y' = -x
  M(3, 1) = -1;  // vy' = -vx
  return M;
}

/// A target passing behind the radar along x = -5000 m: its bearing crosses
/// +-pi at t = 10 s, and the sigma points straddle the cut for several
/// steps. The same run rotated by -90 degrees (bearing near +pi/2, nothing to
/// wrap) must give the same estimates rotated back, and both must track.
template <template <class, class> class FilterT>
void check_bearing_wrap() {
  using Motion = ConstantVelocity2D<double>;
  using Radar = PolarRadar<Motion>;
  using Filter = FilterT<Motion, Radar>;
  Motion motion;
  motion.sa = 0.5;
  Radar radar;
  radar.sigma_range_m = 5.0;
  radar.sigma_bearing_rad = 0.01;
  Filter straddling(motion, radar);
  Filter rotated(motion, radar);
  const Eigen::Matrix4d M = rotation_minus_90();
  Eigen::Vector4d x0(-5000.0, 0.0, -500.0, 50.0);
  Eigen::Vector4d x_est = x0 + Eigen::Vector4d(40.0, 3.0, -60.0, -4.0);
  Eigen::Matrix4d P0 = Eigen::Vector4d(100.0 * 100.0, 10.0 * 10.0, 100.0 * 100.0, 10.0 * 10.0).asDiagonal();
  REQUIRE(straddling.reset(x_est, P0) == Status::kOk);
  REQUIRE(rotated.reset(M * x_est, M * P0 * M.transpose()) == Status::kOk);
  NormalGenerator<double> noise(7);
  double worst_gap = 0.0;
  double worst_error = 0.0;
  for (int k = 1; k <= 20; ++k) {
    const Eigen::Vector4d truth = x0 + Eigen::Vector4d(0.0, 0.0, 50.0 * k, 0.0);
    const Eigen::Vector2d z = polar_measurement(truth(0), truth(2), 5.0, 0.01, noise);
    Eigen::Vector2d z_rot = z;
    z_rot(1) = std::remainder(z(1) - kPi / 2, 2.0 * kPi);
    REQUIRE(straddling.predict(1.0) == Status::kOk);
    REQUIRE(rotated.predict(1.0) == Status::kOk);
    REQUIRE(straddling.update(z) == Status::kOk);
    REQUIRE(rotated.update(z_rot) == Status::kOk);
    const Eigen::Vector4d back = M.transpose() * rotated.x();
    const double sigma_pos = std::sqrt(straddling.P()(0, 0) + straddling.P()(2, 2));
    worst_gap = std::max(worst_gap, (back - straddling.x()).norm() / sigma_pos);
    worst_error = std::max(worst_error, std::hypot(straddling.x()(0) - truth(0), straddling.x()(2) - truth(2)));
  }
  // The two runs differ only by the choice of square root of P (Cholesky of
  // a permuted matrix), which moves the estimate by far less than its own
  // standard deviation on this nearly linear geometry; a plain (unwrapped)
  // mean of points at +-179.9 deg lands near 0 deg and misses by kilometres.
  CHECK(worst_gap < 0.01);
  CHECK(worst_error < 100.0);
}

/// Bad input returns a status and leaves the state as it was.
template <template <class, class> class FilterT>
void check_refuses_bad_input() {
  using Motion = ConstantVelocity2D<double>;
  using Radar = PolarRadar<Motion>;
  using Filter = FilterT<Motion, Radar>;
  Motion motion;
  motion.sa = 0.1;
  Radar radar;
  radar.sigma_range_m = 1.0;
  radar.sigma_bearing_rad = 0.1 * kPi / 180.0;
  Filter f(motion, radar);
  typename Filter::State x0(1000.0, 10.0, 1000.0, 5.0);
  REQUIRE(f.reset(x0, Filter::Cov::Identity() * 25.0) == Status::kOk);
  REQUIRE(f.predict(1.0) == Status::kOk);
  const typename Filter::State x_before = f.x();
  const typename Filter::Cov P_before = f.P();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const typename Filter::MeasVec good(std::hypot(1010.0, 1005.0), std::atan2(1005.0, 1010.0));

  CHECK(f.update(typename Filter::MeasVec(nan, 0.5)) == Status::kNonFinite);
  CHECK(f.update(typename Filter::MeasVec(1400.0, inf)) == Status::kNonFinite);
  CHECK(f.innovation(typename Filter::MeasVec(nan, 0.5)).status == Status::kNonFinite);
  CHECK(f.predict(nan) == Status::kNonFinite);
  typename Filter::MeasCov R = Filter::MeasCov::Zero();
  R(0, 0) = -1e9;
  R(1, 1) = 1e-6;
  CHECK(f.update(good, R) == Status::kNotPositiveDefinite);
  CHECK(f.x() == x_before);
  CHECK(f.P() == P_before);
  CHECK_FALSE(f.diagnostics().fused);

  typename Filter::Cov indefinite = Filter::Cov::Identity();
  indefinite(0, 0) = -1.0;
  CHECK(f.reset(x0, indefinite) == Status::kNotPositiveDefinite);
  typename Filter::State x_nan = x0;
  x_nan(1) = nan;
  CHECK(f.reset(x_nan, Filter::Cov::Identity()) == Status::kNonFinite);
  CHECK(f.x() == x_before);
  CHECK(f.P() == P_before);

  REQUIRE(f.update(good) == Status::kOk);
  CHECK(f.diagnostics().fused);
  CHECK(f.diagnostics().status == Status::kOk);
}

/// reset, predict, innovation and update touch no heap.
template <class Filter>
void check_no_allocation(Filter& f, const typename Filter::State& x0, const typename Filter::Cov& P0,
                         const typename Filter::MeasVec& z) {
  std::size_t allocations = 0;
  Status reset = Status::kNotInitialised, predicted = Status::kNotInitialised, updated = Status::kNotInitialised;
  Status gated = Status::kNotInitialised;
  {
    AllocationGuard guard;
    reset = f.reset(x0, P0);
    predicted = f.predict(typename Filter::Scalar(1));
    gated = f.innovation(z).status;
    updated = f.update(z);
    allocations = guard.allocations();
  }
  REQUIRE(reset == Status::kOk);
  REQUIRE(predicted == Status::kOk);
  REQUIRE(gated == Status::kOk);
  REQUIRE(updated == Status::kOk);
  CHECK(allocations == 0);
}

template <template <class, class> class FilterT, class S>
void check_no_allocation_cv_radar() {
  using Motion = ConstantVelocity2D<S>;
  using Radar = PolarRadar<Motion>;
  using Filter = FilterT<Motion, Radar>;
  Motion motion;
  motion.sa = S(0.1);
  Radar radar;
  radar.sigma_range_m = S(1);
  radar.sigma_bearing_rad = S(0.002);
  Filter f(motion, radar);
  typename Filter::State x0(S(1000), S(10), S(1000), S(5));
  check_no_allocation(f, x0, Filter::Cov::Identity() * S(25),
                      typename Filter::MeasVec(S(1421), S(0.7826)));
}

}  // namespace kestrel::test
