// SPDX-License-Identifier: Apache-2.0
// The robustness variants (docs/robustness.md) generate what they claim:
// s1-outliers/s2-outliers put a 300-800 m range offset, either sign, on
// about 3 % of plots and change nothing else; s1-burst/s2-burst scale range
// and bearing noise by 3 on [50, 80) s and nowhere else. Both are compared
// with S1/S2 of the same seed, whose unit variates they share.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "scenarios/radar_scenario.hpp"
#include "scenarios/registry.hpp"

using namespace kestrel::sim;  // NOLINT(google-build-using-namespace)
using Catch::Matchers::WithinAbs;

namespace {
double range_residual(const ScenarioRun& run, std::size_t k) {
  return run.frames[k].radar[0].range_m - std::hypot(run.truth[k].x_m, run.truth[k].y_m);
}
double bearing_residual(const ScenarioRun& run, std::size_t k) {
  return run.frames[k].radar[0].bearing_rad - std::atan2(run.truth[k].y_m, run.truth[k].x_m);
}
}  // namespace

SCENARIO("The outlier variants offset a few per cent of ranges by hundreds of metres",
         "[host_sim][scenarios][robustness]") {
  for (const char* base : {"s1", "s2"}) {
    GIVEN(base << " and " << base << "-outliers over seeds 0 to 49") {
      const auto plain_scenario = make_scenario(base);
      const auto outlier_scenario = make_scenario(std::string(base) + "-outliers");
      std::size_t plots = 0;
      std::size_t outliers = 0;
      std::size_t negative = 0;
      bool bearings_equal = true;
      bool offsets_in_range = true;
      for (std::uint64_t seed = 0; seed < 50; ++seed) {
        const ScenarioRun plain = plain_scenario->generate(seed);
        const ScenarioRun noisy = outlier_scenario->generate(seed);
        REQUIRE(plain.frames.size() == noisy.frames.size());
        for (std::size_t k = 0; k < plain.frames.size(); ++k) {
          ++plots;
          bearings_equal = bearings_equal && noisy.frames[k].radar[0].bearing_rad == plain.frames[k].radar[0].bearing_rad;
          const double offset = range_residual(noisy, k) - range_residual(plain, k);
          // Not an outlier: the same bits up to the rounding of r + s n + 0.
          if (std::fabs(offset) < 1e-6) continue;
          ++outliers;
          if (offset < 0.0) ++negative;
          // 1e-6 m: the rounding of a range near 20 km.
          offsets_in_range = offsets_in_range && std::fabs(offset) >= 300.0 - 1e-6 && std::fabs(offset) < 800.0 + 1e-6;
        }
      }
      THEN("the bearings are S1/S2's and every range offset is 300-800 m") {
        CHECK(bearings_equal);
        CHECK(offsets_in_range);
      }
      THEN("about 3 % of plots are outliers, with either sign") {
        // 15000 plots: the standard error of a 3 % fraction is 0.14 %; 0.5 %
        // is over three of them, while 0 % or 6 % would fail.
        const double fraction = static_cast<double>(outliers) / static_cast<double>(plots);
        CHECK_THAT(fraction, WithinAbs(0.03, 0.005));
        // Half negative: the standard error of the share is 1/sqrt(4 x 450) = 2.4 %.
        CHECK_THAT(static_cast<double>(negative) / static_cast<double>(outliers), WithinAbs(0.5, 0.1));
      }
    }
  }
  GIVEN("one seed generated twice") {
    const auto s = make_scenario("s1-outliers");
    const ScenarioRun a = s->generate(11);
    const ScenarioRun b = s->generate(11);
    THEN("the runs are identical bit for bit") {
      bool same = true;
      for (std::size_t k = 0; k < a.frames.size(); ++k) {
        same = same && a.frames[k].radar[0].range_m == b.frames[k].radar[0].range_m &&
               a.frames[k].radar[0].bearing_rad == b.frames[k].radar[0].bearing_rad;
      }
      CHECK(same);
    }
  }
}

SCENARIO("The burst variants scale range and bearing sigma by 3 for 30 s", "[host_sim][scenarios][robustness]") {
  GIVEN("the burst noise profile") {
    const RadarNoise n = paper000_burst_radar_noise();
    const RadarNoise nominal = paper000_radar_noise();
    THEN("both sigmas are x3 exactly on [50, 80) s") {
      CHECK(n.range_sigma_at(49.5) == nominal.sigma_range_m);
      CHECK(n.range_sigma_at(50.0) == 3.0 * nominal.sigma_range_m);
      CHECK(n.range_sigma_at(79.5) == 3.0 * nominal.sigma_range_m);
      CHECK(n.range_sigma_at(80.0) == nominal.sigma_range_m);
      CHECK(n.bearing_sigma_at(49.5) == nominal.sigma_bearing_rad);
      CHECK(n.bearing_sigma_at(50.0) == 3.0 * nominal.sigma_bearing_rad);
      CHECK(n.bearing_sigma_at(79.5) == 3.0 * nominal.sigma_bearing_rad);
      CHECK(n.bearing_sigma_at(80.0) == nominal.sigma_bearing_rad);
    }
  }
  for (const char* base : {"s1", "s2"}) {
    GIVEN("the same seed through " << base << " and " << base << "-burst") {
      const auto plain = make_scenario(base)->generate(7);
      const auto noisy = make_scenario(std::string(base) + "-burst")->generate(7);
      REQUIRE(plain.frames.size() == noisy.frames.size());
      THEN("the plots differ only inside the burst, by exactly the factor 3") {
        for (std::size_t k = 0; k < plain.frames.size(); ++k) {
          const double t = plain.frames[k].t_s;
          const double ratio = (t >= 50.0 && t < 80.0) ? 3.0 : 1.0;
          INFO("t = " << t);
          CHECK_THAT(range_residual(noisy, k), WithinAbs(ratio * range_residual(plain, k), 1e-8));
          CHECK_THAT(bearing_residual(noisy, k), WithinAbs(ratio * bearing_residual(plain, k), 1e-12));
        }
      }
    }
  }
}
