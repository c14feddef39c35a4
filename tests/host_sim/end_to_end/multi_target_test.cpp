// SPDX-License-Identifier: Apache-2.0
// Multi-target runs through the wire stream and the radar tracker: GNN is
// the default with several targets, the crossing pair ends with one
// confirmed track on each target, and the oracle associator never gives a
// track a false alarm. Seeds from 100000 on: the Monte Carlo tables of
// docs/multitarget.md use seeds 0..199.
#include <catch2/catch.hpp>
#include <cstddef>
#include <cstdint>
#include <set>
#include <stdexcept>
#include <utility>

#include "montecarlo/multi_run.hpp"
#include "scenarios/registry.hpp"

using namespace kestrel::sim;  // NOLINT(google-build-using-namespace)

SCENARIO("GNN is the default associator with more than one target", "[host_sim][multitarget]") {
  CHECK(default_multi_associator(make_scenario("raid")->info()) == MultiAssociator::kGlobalNearestNeighbour);
  CHECK(default_multi_associator(make_scenario("crossing")->info()) == MultiAssociator::kGlobalNearestNeighbour);
  CHECK(default_multi_associator(make_scenario("s1")->info()) == MultiAssociator::kNearestNeighbour);
}

SCENARIO("The crossing pair is tracked through the crossing", "[host_sim][multitarget]") {
  const auto s = make_scenario("crossing");
  MultiRunParams config;
  config.associator = default_multi_associator(s->info());
  const MultiRunDetail d = run_multi_once(*s, 100000, config);
  THEN("both targets are held at the end by two confirmed tracks and no track is false") {
    REQUIRE(d.steps.size() == s->info().steps);
    const MultiTargetStep& last = d.steps.back();
    CHECK(last.tracks.size() == 2);
    // c = 500 m: a GOSPA under 100 m means both assigned with small errors.
    CHECK(d.metrics.gospa_m.back() < 100.0);
    CHECK(d.metrics.false_tracks == 0);
    REQUIRE(d.metrics.time_to_confirm_s.size() == 2);
    CHECK(d.metrics.time_to_confirm_s[0] >= 0.0);
    CHECK(d.metrics.time_to_confirm_s[1] >= 0.0);
  }
}

SCENARIO("The oracle associator takes no false alarm", "[host_sim][multitarget]") {
  const auto s = make_scenario("raid");
  const std::uint64_t seed = 100001;
  const ScenarioRun generated = s->generate(seed);
  MultiRunParams config;
  config.associator = MultiAssociator::kOracle;
  const MultiRunDetail d = run_multi_once(*s, seed, config);
  REQUIRE(d.stream.frames.size() == generated.frames.size());
  std::size_t associated = 0;
  std::set<std::uint32_t> before;  // tracks reported in the previous frame
  for (std::size_t k = 0; k < d.stream.frames.size(); ++k) {
    std::set<std::uint32_t> now;
    for (const auto& row : d.stream.frames[k].tracks) {
      now.insert(row.track_id);
      // A track reported for the first time may have been started in this
      // frame: its plot is then the initiator's pairing plot, not an
      // association.
      if (before.count(row.track_id) == 0) continue;
      if (!row.associated || row.measurement_index < 0) continue;
      ++associated;
      const auto j = static_cast<std::size_t>(row.measurement_index);
      REQUIRE(j < generated.origins[k].size());
      CHECK(generated.origins[k][j] >= 0);
    }
    before = std::move(now);
  }
  THEN("its confirmed tracks took plots, every one a target's, and hold most targets at the end") {
    CHECK(associated > 500);
    CHECK(d.metrics.gospa_m.size() == s->info().steps);
    CHECK(d.steps.back().tracks.size() >= 10);
  }
}

SCENARIO("The IMM runs in the multi-target tracker and holds the crossing pair", "[host_sim][multitarget][imm]") {
  CHECK(multi_filter_by_name("imm") == MultiFilter::kImm);
  CHECK(multi_filter_by_name("ekf-ca") == MultiFilter::kEkfCa);
  CHECK_THROWS_AS(multi_filter_by_name("ukf"), std::invalid_argument);
  const auto s = make_scenario("crossing");
  MultiRunParams config;
  config.filter = MultiFilter::kImm;
  // The setting docs/multitarget.md reports for the IMM (chosen on these
  // tuning seeds): a stickier switching matrix than the S1/S2 default.
  config.options.imm = {"p_stay=0.98"};
  config.options.radar = {{"confirm_m", 4.0}, {"confirm_n", 5.0}, {"max_speed_mps", 400.0}};
  std::size_t swaps = 0;
  for (std::uint64_t seed = 100000; seed < 100020; ++seed) {
    const MultiRunDetail d = run_multi_once(*s, seed, config);
    REQUIRE(d.steps.size() == s->info().steps);
    CHECK(d.steps.back().tracks.size() == 2);
    CHECK(d.metrics.false_tracks == 0);
    swaps += d.metrics.swaps;
  }
  THEN("20 runs, no track swap") { CHECK(swaps == 0); }
}

SCENARIO("On the raid the IMM's GOSPA is below EKF-CA's on the same seeds", "[host_sim][multitarget][imm]") {
  const auto s = make_scenario("raid");
  MultiRunParams ekf;
  ekf.options.radar = {{"confirm_m", 5.0}, {"confirm_n", 6.0}, {"max_speed_mps", 400.0}};
  ekf.gate_tentative = kestrel::GateProbability::k99;
  MultiRunParams imm = ekf;
  imm.filter = MultiFilter::kImm;
  imm.options.imm = {"p_stay=0.98"};
  double gospa_ekf = 0.0;
  double gospa_imm = 0.0;
  for (std::uint64_t seed = 100000; seed < 100010; ++seed) {
    gospa_ekf += run_multi_once(*s, seed, ekf).metrics.mean_gospa_m;
    gospa_imm += run_multi_once(*s, seed, imm).metrics.mean_gospa_m;
  }
  // 200 report runs: 277 against 346 m (docs/multitarget.md); a tenth less
  // over 10 tuning seeds leaves room for seed-to-seed spread.
  THEN("by more than a tenth over 10 runs") { CHECK(gospa_imm < 0.9 * gospa_ekf); }
}
