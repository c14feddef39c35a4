// SPDX-License-Identifier: Apache-2.0
// CDKF: equals the textbook KF on a linear model (double, float); bearings
// straddling +-pi are handled; bad input returns a status with the state
// unchanged; no heap; plugs into the Tracker.
#include <catch2/catch.hpp>

#include "core/filters/filter_checks.hpp"
#include "kestrel/filters/sigma_point_filter.hpp"
#include "kestrel/models/motion/constant_acceleration_2d.hpp"
#include "kestrel/tracking/tracker.hpp"

using kestrel::ConstantVelocity2D;
using kestrel::PolarRadar;
using kestrel::Cdkf;

TEMPLATE_TEST_CASE("Scenario: on a linear model the CDKF is the textbook Kalman filter", "[cdkf]", double,
                   float) {
  kestrel::test::check_equals_kalman_filter<Cdkf, TestType>();
}

SCENARIO("CDKF weights follow Stirling interpolation with h = sqrt(3)", "[cdkf]") {
  GIVEN("n = 4 and h^2 = 3") {
    using F = Cdkf<ConstantVelocity2D<double>, PolarRadar<ConstantVelocity2D<double>>>;
    STATIC_REQUIRE(F::kSigmaCount == 9);
    const auto w = F().weights();
    THEN("Wm0 = (h^2 - n)/h^2 = -1/3, Wm_i = 1/6, Wc1 = 1/12, Wc2 = 2/36") {
      CHECK(w.spread == Approx(std::sqrt(3.0)).epsilon(1e-15));
      CHECK(w.wm0 == Approx(-1.0 / 3.0).epsilon(1e-15));
      CHECK(w.wi == Approx(1.0 / 6.0).epsilon(1e-15));
      CHECK(w.wc1 == Approx(1.0 / 12.0).epsilon(1e-15));
      CHECK(w.wc2 == Approx(2.0 / 36.0).epsilon(1e-15));
    }
  }
}

SCENARIO("the CDKF tracks through the +-pi bearing cut", "[cdkf][wrap]") {
  kestrel::test::check_bearing_wrap<Cdkf>();
}

SCENARIO("the CDKF refuses bad input and keeps its state", "[cdkf][status]") {
  kestrel::test::check_refuses_bad_input<Cdkf>();
}

TEMPLATE_TEST_CASE("Scenario: a CDKF step allocates nothing", "[cdkf][alloc]", double, float) {
  kestrel::test::check_no_allocation_cv_radar<Cdkf, TestType>();
}

SCENARIO("the CDKF is a TrackingFilter", "[cdkf][tracker]") {
  STATIC_REQUIRE(kestrel::TrackingFilter<Cdkf<ConstantVelocity2D<float>, PolarRadar<ConstantVelocity2D<float>>>>);
  STATIC_REQUIRE(kestrel::TrackingFilter<
                 Cdkf<kestrel::ConstantAcceleration2D<double>, PolarRadar<kestrel::ConstantAcceleration2D<double>>>>);
}
