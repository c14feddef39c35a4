// SPDX-License-Identifier: Apache-2.0
// The multi-target scenarios: registered, reproducible per seed, every
// plot labelled with its origin, detections at about Pd, false alarms
// inside the surveillance region, frames within the wire capacity, and
// the crossing targets really meeting.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>

#include "kestrel/hal/frame.hpp"
#include "scenarios/multi_target.hpp"
#include "scenarios/registry.hpp"

using namespace kestrel::sim;  // NOLINT(google-build-using-namespace)

SCENARIO("The raid scenario labels every plot and keeps to its sensor", "[host_sim][scenarios][multitarget]") {
  const auto s = make_scenario("raid");
  REQUIRE(s->info().targets == 12);
  GIVEN("one seed generated twice and another seed") {
    const ScenarioRun a = s->generate(7);
    const ScenarioRun b = s->generate(7);
    const ScenarioRun other = s->generate(8);
    THEN("the same seed gives the same plots and another seed other plots") {
      REQUIRE(a.frames.size() == s->info().steps);
      REQUIRE(a.origins.size() == a.frames.size());
      CHECK(a.frames[10].radar.size() == b.frames[10].radar.size());
      CHECK(a.frames[10].radar[0].range_m == b.frames[10].radar[0].range_m);
      CHECK(a.frames[10].radar[0].range_m != other.frames[10].radar[0].range_m);
    }
    THEN("target plots come at about Pd = 0.9 and clutter at about 10 per frame in the region") {
      std::size_t target_plots = 0, clutter = 0;
      for (std::size_t k = 0; k < a.frames.size(); ++k) {
        const auto& f = a.frames[k];
        REQUIRE(f.radar.size() == a.origins[k].size());
        CHECK(f.radar.size() <= kestrel::hal::kMaxRadarPlots);
        for (std::size_t p = 0; p < f.radar.size(); ++p) {
          if (p > 0) CHECK(f.radar[p - 1].bearing_rad <= f.radar[p].bearing_rad);  // bearing order
          const int o = a.origins[k][p];
          REQUIRE(o >= -1);
          REQUIRE(o < 12);
          if (o < 0) {
            ++clutter;
            CHECK(f.radar[p].range_m >= 5000.0);
            CHECK(f.radar[p].range_m <= 40000.0);
          } else {
            ++target_plots;
            // Within 5 sigma of the true range of its own target.
            const TruthSample& t = a.targets[static_cast<std::size_t>(o)][k];
            CHECK(std::abs(f.radar[p].range_m - std::hypot(t.x_m, t.y_m)) < 15.0);
          }
        }
      }
      // 960 target chances: Pd 0.9 gives 864 +- 9.3 (1 sd); 800 clutter +- 28.
      CHECK(target_plots > 820);
      CHECK(target_plots < 910);
      CHECK(clutter > 680);
      CHECK(clutter < 920);
    }
  }
}

SCENARIO("The crossing targets meet at the crossing time", "[host_sim][scenarios][multitarget]") {
  const auto s = make_scenario("crossing");
  REQUIRE(s->info().targets == 2);
  const ScenarioRun r = s->generate(1);
  THEN("they are within a metre at t = 30 s and kilometres apart at the ends, one plot each per frame") {
    const TruthSample& a = r.targets[0][30];
    const TruthSample& b = r.targets[1][30];
    CHECK(a.t_s == 30.0);
    CHECK(std::hypot(a.x_m - b.x_m, a.y_m - b.y_m) < 1.0);
    CHECK(std::hypot(r.targets[0][0].x_m - r.targets[1][0].x_m, r.targets[0][0].y_m - r.targets[1][0].y_m) > 2000.0);
    // Mirror images about the y axis: equal true ranges in every frame.
    CHECK(std::abs(std::hypot(r.targets[0][45].x_m, r.targets[0][45].y_m) -
                   std::hypot(r.targets[1][45].x_m, r.targets[1][45].y_m)) < 1e-6);
    for (const auto& f : r.frames) CHECK(f.radar.size() == 2);
  }
}

SCENARIO("The formation splits after 40 s", "[host_sim][scenarios][multitarget]") {
  const auto s = make_scenario("formation-split");
  REQUIRE(s->info().targets == 3);
  const ScenarioRun r = s->generate(1);
  THEN("the outer targets are 400 m from the middle one before and over 1 km after") {
    const auto gap = [&](std::size_t i, std::size_t k) {
      return std::hypot(r.targets[i][k].x_m - r.targets[1][k].x_m, r.targets[i][k].y_m - r.targets[1][k].y_m);
    };
    CHECK(std::abs(gap(0, 39) - 400.0) < 1.0);
    CHECK(std::abs(gap(2, 39) - 400.0) < 1.0);
    CHECK(gap(0, 89) > 1000.0);
    CHECK(gap(2, 89) > 1000.0);
  }
}
