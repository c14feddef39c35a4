// SPDX-License-Identifier: Apache-2.0
// End to end: S1 and S2 through the whole host chain (scenario -> wire
// stream -> StreamFileFeed -> RadarAdapter -> EKF-CA tracker -> sink ->
// scoring) with paper 000's EKF-CA, qj = 1.6.
//
// Bounds, from docs/references.md: the filter alone reaches about 130 m RMSE
// on S1 and 109 m on S2 at qj = 1.6 (this project's scenarios reproduce
// that: 129 m and 109 m over 20 runs, docs/host_sim.md). 200 m is 1.5x the
// S1 figure, well above the run-to-run spread (+-8 m), and is exceeded by
// any gross fault: a one-frame time shift alone adds 100 m along track,
// a bearing in degrees loses the target at once.
// "Track held" is what a single clean target must give: a confirmed track
// at every scored frame (k >= 2: frame 0 seeds, frame 1 initialises and
// confirms with M = 2), never two confirmed tracks, and one track id.
#include <catch2/catch.hpp>
#include <vector>

#include "filters/filter_registry.hpp"
#include "montecarlo/monte_carlo.hpp"
#include "scenarios/registry.hpp"

using namespace kestrel::sim;  // NOLINT(google-build-using-namespace)

SCENARIO("EKF-CA (qj 1.6) holds the S1 and S2 targets", "[host_sim][e2e]") {
  for (const char* name : {"s1", "s2"}) {
    GIVEN("5 runs of " << name << " (seeds 0-4)") {
      const auto scenario = make_scenario(name);
      const FilterEntry& filter = find_filter("ekf-ca");
      FilterOptions options;
      options.qj = 1.6;
      std::vector<RunRecord> runs;
      std::vector<std::size_t> scored;
      for (std::uint64_t seed = 0; seed < 5; ++seed) {
        const RunDetail d = run_scenario_once(*scenario, seed, filter, options, 1'000'000, ScoringParams{});
        runs.push_back(record_of(d));
        scored.push_back(d.steps.size());
      }
      // Sections run once per pass, so each THEN loops over the runs itself.
      THEN("every frame from k = 2 on is scored and has a confirmed track") {
        for (std::size_t i = 0; i < runs.size(); ++i) {
          INFO(name << " seed " << runs[i].seed);
          CHECK(scored[i] == 298);
          CHECK(runs[i].metrics.missing_steps == 0);
          CHECK(runs[i].frames_not_ok == 0);
        }
      }
      THEN("there is never more than one confirmed track, and it keeps its id") {
        for (const RunRecord& r : runs) {
          INFO(name << " seed " << r.seed << ": " << r.track_switches << " track switches, up to "
                    << r.max_confirmed_tracks << " confirmed tracks in a frame");
          CHECK(r.max_confirmed_tracks == 1);
          CHECK(r.track_switches == 0);
        }
      }
      THEN("RMSE is under 200 m") {
        for (const RunRecord& r : runs) {
          INFO(name << " seed " << r.seed);
          CHECK(r.metrics.rmse_m < 200.0);
        }
      }
    }
  }
}
