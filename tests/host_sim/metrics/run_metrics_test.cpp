// SPDX-License-Identifier: Apache-2.0
// docs/metrics.md per-run figures on hand-made error sequences, where every
// expected value can be worked out on paper.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "metrics/run_metrics.hpp"
#include "metrics/scoring.hpp"

using kestrel::sim::compute_run_metrics;
using kestrel::sim::StepError;
using Catch::Matchers::WithinAbs;

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kT = 0.5;    // frame period, s
constexpr double kL = 300.0;  // loss threshold, m
std::vector<StepError> errors(std::initializer_list<double> e) {
  std::vector<StepError> v;
  for (const double x : e) v.push_back(StepError{x, kNaN, kNaN});
  return v;
}
}  // namespace

SCENARIO("RMSE and peak of a known sequence", "[host_sim][metrics]") {
  GIVEN("errors 3 and 4 m") {
    const auto m = compute_run_metrics(errors({3.0, 4.0}), kT, kL);
    THEN("RMSE = sqrt((9 + 16) / 2), peak = 4, nothing lost") {
      CHECK_THAT(m.rmse_m, WithinAbs(std::sqrt(12.5), 1e-12));
      CHECK(m.peak_m == 4.0);
      CHECK(m.track_loss_s == 0.0);
      CHECK(m.episodes.empty());
      CHECK(std::isnan(m.recovery_s));
    }
  }
  GIVEN("NEES and NIS on some steps only") {
    std::vector<StepError> s{{1.0, 2.0, kNaN}, {1.0, 4.0, 1.0}, {1.0, kNaN, 3.0}};
    const auto m = compute_run_metrics(s, kT, kL);
    THEN("each is averaged over the steps that have it") {
      CHECK(m.nees_pos == 3.0);
      CHECK(m.nis == 2.0);
    }
  }
}

SCENARIO("Track loss and lost episodes", "[host_sim][metrics]") {
  GIVEN("errors 100, 400, 500, 100, 300, 350 m with L = 300 m") {
    const auto m = compute_run_metrics(errors({100, 400, 500, 100, 300, 350}), kT, kL);
    THEN("three steps are over L (300 itself is not): loss = 1.5 s") {
      CHECK(m.lost_steps == 3);
      CHECK(m.track_loss_s == 1.5);
    }
    THEN("two episodes: steps 1-2 recovered at step 3, and step 5 open at the end, closed there") {
      REQUIRE(m.episodes.size() == 2);
      CHECK(m.episodes[0].first_step == 1);
      CHECK(m.episodes[0].end_step == 3);
      CHECK_FALSE(m.episodes[0].open_at_end);
      CHECK(m.episodes[1].first_step == 5);
      CHECK(m.episodes[1].end_step == 6);
      CHECK(m.episodes[1].open_at_end);
    }
    THEN("recovery = mean episode length = (1.0 + 0.5) / 2 s") {
      CHECK(m.recovery_s == 0.75);
    }
  }
  GIVEN("a run lost from its first step to its end") {
    const auto m = compute_run_metrics(errors({400, 500, 600}), kT, kL);
    THEN("one open episode as long as the run") {
      REQUIRE(m.episodes.size() == 1);
      CHECK(m.episodes[0].open_at_end);
      CHECK(m.recovery_s == 1.5);
      CHECK(m.track_loss_s == 1.5);
    }
  }
  GIVEN("steps without any confirmed track (no estimate)") {
    std::vector<StepError> s = errors({10, 20, 30, 40});
    s[1].error_m.reset();
    s[2].error_m.reset();
    const auto m = compute_run_metrics(s, kT, kL);
    THEN("they count as lost but stay out of RMSE and peak") {
      CHECK(m.missing_steps == 2);
      CHECK(m.lost_steps == 2);
      CHECK(m.track_loss_s == 1.0);
      REQUIRE(m.episodes.size() == 1);
      CHECK(m.recovery_s == 1.0);
      CHECK_THAT(m.rmse_m, WithinAbs(std::sqrt((100.0 + 1600.0) / 2.0), 1e-12));
      CHECK(m.peak_m == 40.0);
    }
  }
  GIVEN("no steps at all") {
    const auto m = compute_run_metrics({}, kT, kL);
    THEN("the error figures are NaN (no data), loss is 0") {
      CHECK(std::isnan(m.rmse_m));
      CHECK(std::isnan(m.peak_m));
      CHECK(m.track_loss_s == 0.0);
    }
  }
}

SCENARIO("Position NEES of a 2x2 covariance", "[host_sim][metrics]") {
  WHEN("P = diag(4, 9) and e = (2, 3)") {
    THEN("NEES = 4/4 + 9/9 = 2") { CHECK(kestrel::sim::position_nees(2, 3, 4, 0, 9) == 2.0); }
  }
  WHEN("P has a correlation: P = [[2, 1], [1, 2]], e = (1, 1)") {
    THEN("NEES = e^T P^-1 e = 2/3") { CHECK_THAT(kestrel::sim::position_nees(1, 1, 2, 1, 2), WithinAbs(2.0 / 3.0, 1e-15)); }
  }
  WHEN("P is not positive definite") {
    THEN("NEES is NaN, not a huge number") { CHECK(std::isnan(kestrel::sim::position_nees(1, 1, 1, 1, 1))); }
  }
}
