// SPDX-License-Identifier: Apache-2.0
// S2 truth against docs/scenarios.md: start, range span, the heading changes
// of the two left/right pairs, the turn radius, the jerk bursts' speed
// gains and the final speed.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "scenarios/registry.hpp"
#include "scenarios/s2_scurve.hpp"

using kestrel::sim::TruthSample;
using Catch::Matchers::WithinAbs;

namespace {
double heading_deg(const TruthSample& s) { return std::atan2(s.vy_mps, s.vx_mps) * 180.0 / std::numbers::pi; }
double speed(const TruthSample& s) { return std::hypot(s.vx_mps, s.vy_mps); }
// Truth at t (samples are every 0.5 s from 0).
const TruthSample& at(const std::vector<TruthSample>& truth, double t) {
  return truth.at(static_cast<std::size_t>(std::lround(t / 0.5)));
}
double max_heading_deg(const std::vector<TruthSample>& truth, double t0, double t1) {
  double m = -180.0;
  for (const auto& s : truth) {
    if (s.t_s >= t0 && s.t_s <= t1) m = std::max(m, heading_deg(s));
  }
  return m;
}
}  // namespace

SCENARIO("S2 truth matches its description in the docs", "[host_sim][scenarios][s2]") {
  GIVEN("the S2 scenario") {
    const auto s2 = kestrel::sim::make_scenario("s2");
    const auto truth = s2->generate(0).truth;
    REQUIRE(truth.size() == 300);

    THEN("it starts at (-8000, 12000) m heading +x at 180 m/s") {
      CHECK(truth[0].x_m == -8000.0);
      CHECK(truth[0].y_m == 12000.0);
      CHECK(truth[0].vx_mps == 180.0);
      CHECK(truth[0].vy_mps == 0.0);
    }
    THEN("the range spans 12.7-26.3 km (to the documented 0.1 km)") {
      double r_min = 1e12;
      double r_max = 0.0;
      for (const auto& t : truth) {
        r_min = std::min(r_min, std::hypot(t.x_m, t.y_m));
        r_max = std::max(r_max, std::hypot(t.x_m, t.y_m));
      }
      CHECK_THAT(r_min, WithinAbs(12700.0, 50.0));
      CHECK_THAT(r_max, WithinAbs(26300.0, 50.0));
    }
    THEN("it flies straight until the first turn at t = 20 s") {
      CHECK(heading_deg(at(truth, 20.0)) == 0.0);
    }
    THEN("each pair turns left by 90 deg, then back right by 90 deg") {
      // Sampled every 0.5 s, the peak may fall between samples: at most
      // speed/R * 0.25 s = 0.16 rad/s * 0.25 s = 2.3 deg below 90.
      CHECK_THAT(max_heading_deg(truth, 20.0, 60.0), WithinAbs(89.0, 1.0 + 1e-9));
      CHECK_THAT(heading_deg(at(truth, 60.0)), WithinAbs(0.0, 1e-9));
      CHECK_THAT(max_heading_deg(truth, 95.0, 125.0), WithinAbs(89.0, 1.0 + 1e-9));
      CHECK_THAT(heading_deg(at(truth, 140.0)), WithinAbs(0.0, 1e-9));
      CHECK(heading_deg(at(truth, 94.5)) == Approx(0.0).margin(1e-9));
    }
    THEN("turns have a 1500 m radius (turn rate = speed / 1500)") {
      // Mid first left turn, no along-track acceleration: rate from heading differences.
      const double rate = (heading_deg(at(truth, 26.0)) - heading_deg(at(truth, 25.0))) * std::numbers::pi / 180.0;
      CHECK_THAT(speed(at(truth, 25.5)) / rate, WithinAbs(1500.0, 1.0));
    }
    THEN("the t = 40 s burst falls inside the first right turn") {
      CHECK(heading_deg(at(truth, 40.0)) > 0.0);
      CHECK(heading_deg(at(truth, 43.0)) < heading_deg(at(truth, 40.0)));
      CHECK(heading_deg(at(truth, 43.0)) > 0.0);
    }
    THEN("each 3 s jerk burst adds 10 * 3 * 2 / pi = 19.1 m/s (minus 0.6 m/s of slow-down at 75 s)") {
      const double gain = 60.0 / std::numbers::pi;
      // 1 ms midpoint integration of a smooth acceleration: errors ~1e-6 m/s.
      CHECK_THAT(speed(at(truth, 43.0)) - speed(at(truth, 40.0)), WithinAbs(gain, 1e-3));
      CHECK_THAT(speed(at(truth, 78.0)) - speed(at(truth, 75.0)), WithinAbs(gain - 0.6, 1e-3));
      CHECK_THAT(speed(at(truth, 128.0)) - speed(at(truth, 125.0)), WithinAbs(gain, 1e-3));
    }
    THEN("the final speed is near 235 m/s: 180 - 6 + 4 + 3 * 19.1") {
      CHECK_THAT(speed(truth.back()), WithinAbs(180.0 - 6.0 + 4.0 + 3.0 * 60.0 / std::numbers::pi, 1e-3));
    }
  }
}
