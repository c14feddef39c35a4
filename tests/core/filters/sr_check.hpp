// SPDX-License-Identifier: Apache-2.0
// The square-root forms against their plain forms over a whole S1 run
// (docs/filters.md: in double precision each square-root form must match its
// plain form to 1e-9 relative), on CA-2D with the polar radar: velocity and
// acceleration are never measured, so any error in how the square-root
// factor carries the unobserved directions shows up in P.
#pragma once

#include <catch2/catch.hpp>
#include <cmath>

#include "core/filters/sigma_test_support.hpp"
#include "kestrel/models/measurement/polar_radar.hpp"
#include "kestrel/models/motion/constant_acceleration_2d.hpp"
#include "kestrel/status.hpp"

namespace kestrel::test {

struct SrComparison {
  double worst_x = 0.0;   ///< Largest relative difference of x over the run.
  double worst_P = 0.0;   ///< Largest relative difference of P over the run.
  double worst_sqrt = 0.0;  ///< Largest |Sx Sx^T - P| relative, inside the SR filter.
  double rmse_m = 0.0;  ///< Position RMSE of the SR filter over the run.
  int steps = 0;
};

/// Runs Plain and Sr side by side on S1 (300 steps, T = 0.5 s, sr = 3 m,
/// sb = 0.3 deg, seeded noise), CA-2D with qj = 16 m^2/s^5.
template <template <class, class> class Plain, template <class, class> class Sr>
SrComparison compare_square_root_on_s1(std::uint64_t seed) {
  using Motion = ConstantAcceleration2D<double>;
  using Radar = PolarRadar<Motion>;
  Motion motion;
  motion.qj = 16.0;
  Radar radar;
  radar.sigma_range_m = 3.0;
  radar.sigma_bearing_rad = 0.3 * kPi / 180.0;
  Plain<Motion, Radar> plain(motion, radar);
  Sr<Motion, Radar> sr(motion, radar);

  double x, y, vx, vy;
  S1Truth::at(0.0, x, y, vx, vy);
  typename Motion::State x0;
  x0 << x + 60.0, vx - 15.0, 0.0, y - 40.0, vy + 10.0, 0.0;
  typename Motion::Cov P0 = Motion::Cov::Zero();
  P0.diagonal() << 100.0 * 100.0, 30.0 * 30.0, 10.0 * 10.0, 100.0 * 100.0, 30.0 * 30.0, 10.0 * 10.0;
  REQUIRE(plain.reset(x0, P0) == Status::kOk);
  REQUIRE(sr.reset(x0, P0) == Status::kOk);

  NormalGenerator<double> noise(seed);
  SrComparison out;
  double se = 0.0;
  for (int k = 1; k < 300; ++k) {
    const double t = 0.5 * k;
    S1Truth::at(t, x, y, vx, vy);
    const Eigen::Vector2d z = polar_measurement(x, y, radar.sigma_range_m, radar.sigma_bearing_rad, noise);
    REQUIRE(plain.predict(0.5) == Status::kOk);
    REQUIRE(sr.predict(0.5) == Status::kOk);
    out.worst_x = std::max(out.worst_x, max_relative_state_diff(sr.x(), plain.x(), plain.P()));
    out.worst_P = std::max(out.worst_P, max_relative_cov_diff(sr.P(), plain.P()));
    REQUIRE(plain.update(z) == Status::kOk);
    REQUIRE(sr.update(z) == Status::kOk);
    out.worst_x = std::max(out.worst_x, max_relative_state_diff(sr.x(), plain.x(), plain.P()));
    out.worst_P = std::max(out.worst_P, max_relative_cov_diff(sr.P(), plain.P()));
    const Eigen::Matrix<double, 6, 6> SS = sr.sqrt_P() * sr.sqrt_P().transpose();
    out.worst_sqrt = std::max(out.worst_sqrt, max_relative_cov_diff(SS, sr.P()));
    se += std::pow(sr.x()(Motion::Layout::kX) - x, 2) + std::pow(sr.x()(Motion::Layout::kY) - y, 2);
    ++out.steps;
  }
  out.rmse_m = std::sqrt(se / out.steps);
  return out;
}

}  // namespace kestrel::test
