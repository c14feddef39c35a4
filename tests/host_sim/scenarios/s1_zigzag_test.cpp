// SPDX-License-Identifier: Apache-2.0
// S1 truth against docs/scenarios.md: the printed initial velocity and range
// span, the axial burst, and the analytic velocity against differences of
// the analytic position (catches a wrong derivative or time scale).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "scenarios/registry.hpp"
#include "scenarios/s1_zigzag.hpp"

using kestrel::sim::make_scenario;
using kestrel::sim::s1_truth;
using Catch::Matchers::WithinAbs;

SCENARIO("S1 truth matches its description in the docs", "[host_sim][scenarios][s1]") {
  GIVEN("the S1 scenario") {
    const auto s1 = make_scenario("s1");
    const auto run = s1->generate(0);

    THEN("it has 300 frames at t = kT, T = 0.5 s") {
      REQUIRE(run.frames.size() == 300);
      REQUIRE(run.truth.size() == 300);
      CHECK(run.frames.front().t_s == 0.0);
      CHECK(run.frames.back().t_s == 149.5);
      CHECK(s1->info().loss_threshold_m == 300.0);
    }
    THEN("the initial state is (-15000, 8000) m moving at (200, 125.7) m/s") {
      // docs/scenarios.md prints 125.7 = 300 * 2 pi / 15 rounded to 0.1.
      CHECK_THAT(run.truth[0].x_m, WithinAbs(-15000.0, 1e-9));
      CHECK_THAT(run.truth[0].y_m, WithinAbs(8000.0, 1e-9));
      CHECK_THAT(run.truth[0].vx_mps, WithinAbs(200.0, 1e-12));
      CHECK_THAT(run.truth[0].vy_mps, WithinAbs(125.7, 0.05));
    }
    THEN("the range spans 7.7-18.4 km (to the documented 0.1 km)") {
      double r_min = 1e12;
      double r_max = 0.0;
      for (const auto& t : run.truth) {
        r_min = std::min(r_min, std::hypot(t.x_m, t.y_m));
        r_max = std::max(r_max, std::hypot(t.x_m, t.y_m));
      }
      CHECK_THAT(r_min, WithinAbs(7700.0, 50.0));
      CHECK_THAT(r_max, WithinAbs(18400.0, 50.0));
    }
  }
}

SCENARIO("S1's axial burst takes the speed from 200 to 225 m/s over 80-85 s", "[host_sim][scenarios][s1]") {
  WHEN("the truth is read before, during and after the burst") {
    THEN("the along-track speed is 200, 212.5 and 225 m/s") {
      CHECK_THAT(s1_truth(79.9).vx_mps, WithinAbs(200.0, 1e-12));
      CHECK_THAT(s1_truth(82.5).vx_mps, WithinAbs(212.5, 1e-9));
      CHECK_THAT(s1_truth(85.0).vx_mps, WithinAbs(225.0, 1e-9));
      CHECK_THAT(s1_truth(140.0).vx_mps, WithinAbs(225.0, 1e-9));
    }
  }
}

SCENARIO("S1's velocity is the derivative of its position", "[host_sim][scenarios][s1]") {
  GIVEN("central differences of the analytic position with h = 1 ms") {
    const double h = 1e-3;
    for (const double t : {0.5, 11.25, 40.0, 82.0, 84.0, 120.0}) {
      const auto a = s1_truth(t - h);
      const auto b = s1_truth(t + h);
      const auto mid = s1_truth(t);
      THEN("they match the analytic velocity at t = " << t) {
        // Truncation error of the central difference: |x'''| h^2 / 6, with
        // |y'''| = 300 (2 pi / 15)^3 = 22 m/s^3, far below 1e-3 m/s.
        CHECK_THAT((b.x_m - a.x_m) / (2 * h), WithinAbs(mid.vx_mps, 1e-3));
        CHECK_THAT((b.y_m - a.y_m) / (2 * h), WithinAbs(mid.vy_mps, 1e-3));
      }
    }
  }
}
