// SPDX-License-Identifier: Apache-2.0
// S1n/S2n against docs/scenarios.md: range sigma x3 for 60 <= t < 75 s and
// bearing sigma x3 for 110 <= t < 120 s, and the S1/S2 sensor itself
// (sr = 3 m, sb = 0.30 deg) checked on the generated plots.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "scenarios/radar_scenario.hpp"
#include "scenarios/registry.hpp"

using namespace kestrel::sim;  // NOLINT(google-build-using-namespace)
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {
constexpr double kSigmaBearingRad = 0.30 * std::numbers::pi / 180.0;
double range_residual(const ScenarioRun& run, std::size_t k) {
  return run.frames[k].radar[0].range_m - std::hypot(run.truth[k].x_m, run.truth[k].y_m);
}
double bearing_residual(const ScenarioRun& run, std::size_t k) {
  return run.frames[k].radar[0].bearing_rad - std::atan2(run.truth[k].y_m, run.truth[k].x_m);
}
}  // namespace

SCENARIO("The n variants scale the noise at the documented times", "[host_sim][scenarios][noise]") {
  GIVEN("the S1n/S2n noise profile") {
    const RadarNoise n = paper000_varying_radar_noise();
    THEN("range sigma is x3 exactly on [60, 75) s") {
      CHECK(n.range_sigma_at(59.5) == 3.0);
      CHECK(n.range_sigma_at(60.0) == 9.0);
      CHECK(n.range_sigma_at(74.5) == 9.0);
      CHECK(n.range_sigma_at(75.0) == 3.0);
      CHECK(n.range_sigma_at(115.0) == 3.0);
    }
    THEN("bearing sigma is x3 exactly on [110, 120) s") {
      CHECK(n.bearing_sigma_at(109.5) == kSigmaBearingRad);
      CHECK(n.bearing_sigma_at(110.0) == 3.0 * kSigmaBearingRad);
      CHECK(n.bearing_sigma_at(119.5) == 3.0 * kSigmaBearingRad);
      CHECK(n.bearing_sigma_at(120.0) == kSigmaBearingRad);
      CHECK(n.bearing_sigma_at(65.0) == kSigmaBearingRad);
    }
  }

  for (const char* base : {"s1", "s2"}) {
    GIVEN("the same seed through " << base << " and " << base << "n") {
      const auto plain = make_scenario(base)->generate(7);
      const auto noisy = make_scenario(std::string(base) + "n")->generate(7);
      REQUIRE(plain.frames.size() == noisy.frames.size());
      THEN("the plots differ only inside the windows, by exactly the factor 3") {
        for (std::size_t k = 0; k < plain.frames.size(); ++k) {
          const double t = plain.frames[k].t_s;
          const double range_ratio = (t >= 60.0 && t < 75.0) ? 3.0 : 1.0;
          const double bearing_ratio = (t >= 110.0 && t < 120.0) ? 3.0 : 1.0;
          INFO("t = " << t);
          // Same unit variates, scaled: equal up to the rounding of r + s*n.
          CHECK_THAT(range_residual(noisy, k), WithinAbs(range_ratio * range_residual(plain, k), 1e-8));
          CHECK_THAT(bearing_residual(noisy, k), WithinAbs(bearing_ratio * bearing_residual(plain, k), 1e-12));
        }
      }
    }
  }
}

SCENARIO("The S1 sensor has sr = 3 m and sb = 0.30 deg", "[host_sim][scenarios][noise]") {
  GIVEN("50 seeds of S1 (15000 plots)") {
    double sum_r2 = 0.0;
    double sum_b2 = 0.0;
    double sum_r = 0.0;
    std::size_t n = 0;
    const auto s1 = make_scenario("s1");
    for (std::uint64_t seed = 0; seed < 50; ++seed) {
      const auto run = s1->generate(seed);
      for (std::size_t k = 0; k < run.frames.size(); ++k) {
        sum_r += range_residual(run, k);
        sum_r2 += range_residual(run, k) * range_residual(run, k);
        sum_b2 += bearing_residual(run, k) * bearing_residual(run, k);
        ++n;
      }
    }
    THEN("the residual standard deviations match within 5 % and the mean is ~0") {
      // Relative standard error of a sample sd is 1/sqrt(2n) = 0.6 %: 5 % is
      // about eight of them, while a wrong unit (deg vs rad) is off by 57x.
      CHECK_THAT(std::sqrt(sum_r2 / static_cast<double>(n)), WithinRel(3.0, 0.05));
      CHECK_THAT(std::sqrt(sum_b2 / static_cast<double>(n)), WithinRel(kSigmaBearingRad, 0.05));
      // Standard error of the mean: 3 / sqrt(15000) = 0.025 m.
      CHECK_THAT(sum_r / static_cast<double>(n), WithinAbs(0.0, 0.15));
    }
  }
}
