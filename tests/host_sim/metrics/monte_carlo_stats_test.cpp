// SPDX-License-Identifier: Apache-2.0
// Monte Carlo aggregation (docs/metrics.md: mean with 1.96 sd / sqrt(n)),
// recovery over the runs that lost the track, and the nearest-rank
// percentiles of the timing report.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "metrics/monte_carlo_stats.hpp"
#include "montecarlo/monte_carlo.hpp"
#include "timing/step_timing.hpp"

using namespace kestrel::sim;  // NOLINT(google-build-using-namespace)
using Catch::Matchers::WithinAbs;

SCENARIO("Mean and 95 % interval over runs", "[host_sim][metrics]") {
  GIVEN("values 1, 2, 3, 4") {
    const std::vector<double> v{1, 2, 3, 4};
    const MeanCi m = mean_ci95(v);
    THEN("mean 2.5 +- 1.96 * sd / 2 with sd = sqrt(5/3)") {
      const double half = 1.96 * std::sqrt(5.0 / 3.0) / 2.0;
      CHECK(m.mean == 2.5);
      CHECK_THAT(m.ci95_low, WithinAbs(2.5 - half, 1e-12));
      CHECK_THAT(m.ci95_high, WithinAbs(2.5 + half, 1e-12));
      CHECK(m.n == 4);
    }
  }
  GIVEN("NaN among the values (a run without the figure)") {
    const std::vector<double> v{2.0, std::numeric_limits<double>::quiet_NaN(), 4.0};
    THEN("it is skipped") {
      CHECK(mean_ci95(v).mean == 3.0);
      CHECK(mean_ci95(v).n == 2);
    }
  }
  GIVEN("one value") {
    THEN("the interval has zero width") {
      const std::vector<double> v{7.0};
      CHECK(mean_ci95(v).ci95_low == 7.0);
      CHECK(mean_ci95(v).ci95_high == 7.0);
    }
  }
}

SCENARIO("Recovery time is averaged over runs that had an episode", "[host_sim][metrics]") {
  GIVEN("three runs: no loss, one 1 s episode, one 2 s episode") {
    std::vector<RunRecord> runs(3);
    runs[0].metrics.recovery_s = std::numeric_limits<double>::quiet_NaN();
    runs[1].metrics.episodes.resize(1);
    runs[1].metrics.recovery_s = 1.0;
    runs[1].metrics.track_loss_s = 1.0;
    runs[2].metrics.episodes.resize(1);
    runs[2].metrics.recovery_s = 2.0;
    runs[2].metrics.track_loss_s = 2.0;
    const MonteCarloSummary s = summarise(runs, 1000);
    THEN("recovery = 1.5 s over 2 runs, 1 run without loss, loss averaged over all 3") {
      CHECK(s.recovery_s.mean == 1.5);
      CHECK(s.recovery_s.n == 2);
      CHECK(s.runs_without_loss == 1);
      CHECK(s.track_loss_s.mean == 1.0);
      CHECK(s.track_loss_s.n == 3);
    }
  }
}

SCENARIO("Step latency percentiles use nearest rank", "[host_sim][timing]") {
  GIVEN("step times 100, 99, ..., 1 ns and a 90 ns budget") {
    std::vector<std::uint64_t> ns;
    for (std::uint64_t i = 100; i >= 1; --i) ns.push_back(i);
    const StepTiming t = summarise_step_times(ns, 90);
    THEN("min 1, median 50, p99 99, max 100, 10 overruns") {
      CHECK(t.min_ns == 1);
      CHECK(t.median_ns == 50);
      CHECK(t.p99_ns == 99);
      CHECK(t.max_ns == 100);
      CHECK(t.overruns == 10);
      CHECK(t.mean_ns == 50.5);
    }
  }
}
