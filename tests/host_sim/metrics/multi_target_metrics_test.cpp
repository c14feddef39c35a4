// SPDX-License-Identifier: Apache-2.0
// OSPA and GOSPA on hand-computed cases (an assignment that greedy
// nearest-first gets wrong, the cut-off, empty sets) and the track figures
// on hand-made sequences: a real swap, a one-step cross assignment that is
// not one, a false track and the time to confirm.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "metrics/multi_target_metrics.hpp"

using namespace kestrel::sim;  // NOLINT(google-build-using-namespace)
using Catch::Matchers::WithinAbs;

// Every expected value below is a square root or a ratio of small
// integers, computed by hand; 1e-9 m covers the rounding of pow and sqrt.
constexpr double kTol = 1e-9;

SCENARIO("GOSPA and OSPA pick the optimal assignment", "[host_sim][metrics][multitarget]") {
  GIVEN("truths at 0 and 6 m and tracks at 5 and 12 m on a line") {
    // Nearest pair first would take (6, 5) at 1 m and leave (0, 12) at 12 m;
    // the optimum is (0, 5) and (6, 12): 5 + 6 = 11 m (p = 1), 25 + 36 = 61 m^2 (p = 2).
    const std::vector<Position2> truths{{0, 0}, {6, 0}};
    const std::vector<Position2> tracks{{5, 0}, {12, 0}};
    WHEN("p = 1 and c = 100 m") {
      const SpaParams c{100.0, 1.0};
      const Gospa g = gospa(truths, tracks, c);
      THEN("GOSPA is 11 m with truth 0 on track 0 and OSPA is 11 / 2 m") {
        CHECK_THAT(g.gospa, WithinAbs(11.0, kTol));
        CHECK(g.assignment == std::vector<int>{0, 1});
        CHECK(g.missed == 0);
        CHECK(g.false_tracks == 0);
        CHECK_THAT(ospa(truths, tracks, c), WithinAbs(5.5, kTol));
      }
    }
    WHEN("p = 2 and c = 100 m") {
      const SpaParams c{100.0, 2.0};
      THEN("GOSPA is sqrt(61) m and OSPA sqrt(61 / 2) m") {
        CHECK_THAT(gospa(truths, tracks, c).gospa, WithinAbs(std::sqrt(61.0), kTol));
        CHECK_THAT(ospa(truths, tracks, c), WithinAbs(std::sqrt(30.5), kTol));
      }
    }
  }
  GIVEN("two truths and one track 5 m from the first, c = 10 m, p = 2") {
    const std::vector<Position2> truths{{0, 0}, {100, 0}};
    const std::vector<Position2> tracks{{3, 4}};
    const SpaParams c{10.0, 2.0};
    THEN("GOSPA^2 = 25 + 100 / 2 for the missed target and OSPA^2 = (25 + 100) / 2") {
      const Gospa g = gospa(truths, tracks, c);
      CHECK_THAT(g.gospa, WithinAbs(std::sqrt(75.0), kTol));
      CHECK(g.missed == 1);
      CHECK(g.false_tracks == 0);
      CHECK(g.assignment == std::vector<int>{0, -1});
      CHECK_THAT(ospa(truths, tracks, c), WithinAbs(std::sqrt(62.5), kTol));
    }
  }
  GIVEN("a track beyond the cut-off of the only truth") {
    const std::vector<Position2> truths{{0, 0}};
    const std::vector<Position2> tracks{{20, 0}};
    const SpaParams c{10.0, 2.0};
    THEN("GOSPA counts a miss and a false track, c^2 / 2 each, and OSPA is c") {
      const Gospa g = gospa(truths, tracks, c);
      CHECK(g.missed == 1);
      CHECK(g.false_tracks == 1);
      CHECK_THAT(g.gospa, WithinAbs(10.0, kTol));
      CHECK_THAT(ospa(truths, tracks, c), WithinAbs(10.0, kTol));
    }
  }
  GIVEN("empty sets") {
    const std::vector<Position2> none;
    const std::vector<Position2> three{{0, 0}, {1, 0}, {2, 0}};
    const SpaParams c{10.0, 2.0};
    THEN("both empty is 0; three false tracks are sqrt(3 c^2 / 2) in GOSPA and c in OSPA") {
      CHECK(gospa(none, none, c).gospa == 0.0);
      CHECK(ospa(none, none, c) == 0.0);
      CHECK_THAT(gospa(none, three, c).gospa, WithinAbs(std::sqrt(150.0), kTol));
      CHECK(ospa(none, three, c) == 10.0);
      CHECK(gospa(three, none, c).missed == 3);
    }
  }
}

namespace {
// Truth 0 at (0, 0), truth 1 at (1000, 0); tracks placed on them by id.
MultiTargetStep step(double t, std::vector<std::pair<std::uint32_t, int>> on) {
  MultiTargetStep s;
  s.t_s = t;
  s.truths = {{0, 0}, {1000, 0}};
  for (const auto& [id, truth] : on) {
    s.track_ids.push_back(id);
    s.tracks.push_back(truth < 0 ? Position2{5000, 5000} : s.truths[static_cast<std::size_t>(truth)]);
  }
  return s;
}
}  // namespace

SCENARIO("Track swaps, fragmentation, false tracks and time to confirm", "[host_sim][metrics][multitarget]") {
  const SpaParams c{100.0, 2.0};
  GIVEN("two tracks that exchange their targets for good") {
    std::vector<MultiTargetStep> steps;
    for (int k = 0; k < 3; ++k) steps.push_back(step(k, {{1, 0}, {2, 1}}));
    for (int k = 3; k < 7; ++k) steps.push_back(step(k, {{1, 1}, {2, 0}}));
    const MultiTargetRunMetrics m = compute_multi_target_metrics(steps, c);
    THEN("each track swapped once and each target changed track once") {
      CHECK(m.swaps == 2);
      CHECK(m.fragmentations == 2);
      CHECK(m.false_tracks == 0);
      CHECK(m.confirmed_tracks == 2);
      CHECK(m.mean_gospa_m == 0.0);
    }
  }
  GIVEN("a one-step cross assignment between otherwise steady tracks") {
    std::vector<MultiTargetStep> steps;
    for (int k = 0; k < 3; ++k) steps.push_back(step(k, {{1, 0}, {2, 1}}));
    steps.push_back(step(3, {{1, 1}, {2, 0}}));
    for (int k = 4; k < 7; ++k) steps.push_back(step(k, {{1, 0}, {2, 1}}));
    THEN("it is no swap when a change must hold 3 steps, and 4 changes when every one counts") {
      CHECK(compute_multi_target_metrics(steps, c, 3).swaps == 0);
      CHECK(compute_multi_target_metrics(steps, c, 1).swaps == 4);
    }
  }
  GIVEN("target 1 found at t = 2 s, and a track far from both targets in 3 of its 4 steps") {
    std::vector<MultiTargetStep> steps{step(0, {{1, 0}, {9, -1}}), step(1, {{1, 0}, {9, -1}}),
                                       step(2, {{1, 0}, {9, 1}}), step(3, {{1, 0}, {9, -1}})};
    const MultiTargetRunMetrics m = compute_multi_target_metrics(steps, c);
    THEN("the far track is false, target 0 was confirmed at once and target 1 after 2 s") {
      CHECK(m.false_tracks == 1);
      CHECK(m.confirmed_tracks == 2);
      REQUIRE(m.time_to_confirm_s.size() == 2);
      CHECK(m.time_to_confirm_s[0] == 0.0);
      CHECK(m.time_to_confirm_s[1] == 2.0);
      // Steps 0, 1, 3: target 1 missed and a false track, c^2 / 2 each: GOSPA = c.
      CHECK_THAT(m.gospa_m[0], WithinAbs(100.0, kTol));
      CHECK(m.gospa_m[2] == 0.0);
      CHECK_THAT(m.mean_missed, WithinAbs(0.75, kTol));
    }
  }
}
