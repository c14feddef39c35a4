// SPDX-License-Identifier: Apache-2.0
// UKF: equals the textbook KF on a linear model (double, float); sigma-point
// means of bearings straddling +-pi are wrap-safe; bad input returns a status
// with the state unchanged; no heap; plugs into the Tracker.
#include <catch2/catch.hpp>

#include "core/filters/filter_checks.hpp"
#include "kestrel/filters/sigma_point_filter.hpp"
#include "kestrel/filters/sigma_points.hpp"
#include "kestrel/models/motion/constant_acceleration_2d.hpp"
#include "kestrel/tracking/tracker.hpp"

using kestrel::ConstantVelocity2D;
using kestrel::PolarRadar;
using kestrel::Ukf;

TEMPLATE_TEST_CASE("Scenario: on a linear model the UKF is the textbook Kalman filter", "[ukf]", double,
                   float) {
  kestrel::test::check_equals_kalman_filter<Ukf, TestType>();
}

SCENARIO("UKF weights follow the scaled unscented transform with the documented defaults", "[ukf]") {
  GIVEN("n = 4 and alpha = 1, beta = 2, kappa = 3 - n") {
    using F = Ukf<ConstantVelocity2D<double>, PolarRadar<ConstantVelocity2D<double>>>;
    STATIC_REQUIRE(F::kSigmaCount == 9);
    const auto w = F().weights();
    THEN("lambda = -1, so c = sqrt(3), Wm0 = -1/3, Wc0 = 5/3, Wi = 1/6") {
      CHECK(w.spread == Approx(std::sqrt(3.0)).epsilon(1e-15));
      CHECK(w.wm0 == Approx(-1.0 / 3.0).epsilon(1e-15));
      CHECK(w.wc0 == Approx(5.0 / 3.0).epsilon(1e-15));
      CHECK(w.wi == Approx(1.0 / 6.0).epsilon(1e-15));
      CHECK(w.wm0 + 8 * w.wi == Approx(1.0).epsilon(1e-15));
    }
  }
}

SCENARIO("a sigma-point mean of bearings straddling +-pi stays near pi", "[ukf][sigma][wrap]") {
  using Radar = PolarRadar<ConstantVelocity2D<double>>;
  Radar radar;
  GIVEN("points at pi - 0.01 (centre, weight 0), -pi + 0.02 and pi - 0.04 (weight 1/2 each)") {
    kestrel::Mat<double, 2, 3> Z;
    Z << 5000.0, 5000.0, 5000.0, kestrel::test::kPi - 0.01, -kestrel::test::kPi + 0.02, kestrel::test::kPi - 0.04;
    WHEN("the mean is taken through residual()") {
      const auto z = kestrel::sigma::measurement_mean(radar, Z, 0.5);
      THEN("it is pi - 0.01 (the two outer points are +-0.03 from it), not near 0") {
        // Reference form: Z0 + 0.5 * (0.03 + -0.03); a plain average of the
        // outer points would be -0.01.
        CHECK(z(1) == Approx(kestrel::test::kPi - 0.01).margin(1e-12));
        CHECK(z(0) == Approx(5000.0).margin(1e-9));
        CHECK(std::fabs(radar.residual(Z.col(1), z)(1)) < 0.04);
      }
    }
  }
}

SCENARIO("the UKF tracks through the +-pi bearing cut", "[ukf][wrap]") {
  kestrel::test::check_bearing_wrap<Ukf>();
}

SCENARIO("the UKF refuses bad input and keeps its state", "[ukf][status]") {
  kestrel::test::check_refuses_bad_input<Ukf>();
}

TEMPLATE_TEST_CASE("Scenario: a UKF step allocates nothing", "[ukf][alloc]", double, float) {
  kestrel::test::check_no_allocation_cv_radar<Ukf, TestType>();
}

SCENARIO("the UKF is a TrackingFilter", "[ukf][tracker]") {
  STATIC_REQUIRE(kestrel::TrackingFilter<Ukf<ConstantVelocity2D<float>, PolarRadar<ConstantVelocity2D<float>>>>);
  STATIC_REQUIRE(kestrel::TrackingFilter<
                 Ukf<kestrel::ConstantAcceleration2D<double>, PolarRadar<kestrel::ConstantAcceleration2D<double>>>>);
}
