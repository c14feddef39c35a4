// SPDX-License-Identifier: Apache-2.0
// The board loop must not allocate (docs/architecture.md; the allocation
// guard of tests/support): a whole S1 run through hal::Runner - feed decode, adapter,
// Tracker::step, sink publish - inside an AllocationGuard, and a raid run
// with the multi-target GNN tracker. The stream is
// built and the sink sized before the guard, as a board sizes its buffers
// at start-up. An IMM run also records each report's mode probabilities
// inside the loop, within storage sized in the constructor.
#include <catch2/catch.hpp>
#include <cmath>
#include <memory>

#include "filters/ekf_ca.hpp"
#include "filters/imm_filters.hpp"
#include "kestrel/association/global_nearest_neighbour.hpp"
#include "kestrel/host/board.hpp"
#include "montecarlo/multi_run.hpp"
#include "pipeline/stream_run.hpp"
#include "scenarios/registry.hpp"
#include "stream/stream_writer.hpp"
#include "support/alloc_guard.hpp"

namespace {
template <class Scalar>
void check_run_allocates_nothing() {
  using Tracker = kestrel::host::BoardRadarTracker<kestrel::EkfCa<Scalar>>;
  auto bytes = kestrel::sim::encode_stream(kestrel::sim::make_scenario("s1")->generate(0).frames);
  auto tracker = std::make_unique<Tracker>(
      kestrel::make_radar_tracker<Scalar, kestrel::host::kMaxTracks, kestrel::host::kMaxPlots>(
          kestrel::sim::radar_tracker_params({})));
  kestrel::sim::StreamRun<Tracker> run(*tracker, std::move(bytes), 1'000'000);

  std::size_t allocations = 0;
  {
    kestrel::test::AllocationGuard guard;
    run.run_to_end();
    allocations = guard.allocations();
  }
  REQUIRE(run.stats().frames == 300);
  REQUIRE(run.stats().steps == 300);
  CHECK(run.stats().by_status[static_cast<std::size_t>(kestrel::Status::kOk)] == 300);
  CHECK(allocations == 0);
}
}  // namespace

SCENARIO("A whole S1 run through the Runner allocates nothing", "[host_sim][alloc]") {
  GIVEN("EKF-CA in double") {
    THEN("300 frames, 300 steps, zero allocations") { check_run_allocates_nothing<double>(); }
  }
  GIVEN("EKF-CA in float") {
    THEN("300 frames, 300 steps, zero allocations") { check_run_allocates_nothing<float>(); }
  }
}

SCENARIO("A raid run with the multi-target GNN tracker allocates nothing", "[host_sim][alloc][multitarget]") {
  GIVEN("the raid's 80 frames and the 64-track EKF-CA tracker with GNN, sized before the guard") {
    using Tracker = kestrel::sim::MultiTargetTracker<kestrel::EkfCa<double>, kestrel::GlobalNearestNeighbour>;
    auto bytes = kestrel::sim::encode_stream(kestrel::sim::make_scenario("raid")->generate(100002).frames);
    kestrel::sim::MultiRunParams config;
    config.options.radar = {{"confirm_m", 5.0}, {"confirm_n", 6.0}, {"max_speed_mps", 400.0}};
    auto tracker = kestrel::sim::make_multi_target_tracker<kestrel::EkfCa<double>, kestrel::GlobalNearestNeighbour>(config);
    kestrel::sim::StreamRun<Tracker> run(*tracker, std::move(bytes), 1'000'000);
    std::size_t allocations = 0;
    {
      kestrel::test::AllocationGuard guard;
      run.run_to_end();
      allocations = guard.allocations();
    }
    THEN("every frame is stepped, most targets are confirmed at the end and nothing was allocated") {
      REQUIRE(run.stats().steps == 80);
      CHECK(run.stats().by_status[static_cast<std::size_t>(kestrel::Status::kOk)] == 80);
      const auto result = run.result();
      std::size_t confirmed = 0;
      for (const auto& row : result.frames.back().tracks) confirmed += row.confirmed ? 1 : 0;
      CHECK(confirmed >= 10);
      CHECK(allocations == 0);
    }
  }
}

SCENARIO("An IMM S1 run records mode probabilities without allocating", "[host_sim][alloc][imm]") {
  using Tracker = kestrel::sim::SimRadarTracker<kestrel::RadarImm<double>>;  // kestrel-sim's, with the adaptive noise
  auto bytes = kestrel::sim::encode_stream(kestrel::sim::make_scenario("s1")->generate(0).frames);
  auto tracker = std::make_unique<Tracker>(kestrel::sim::make_imm_tracker<double>(kestrel::sim::FilterOptions{}));
  kestrel::sim::StreamRun<Tracker> run(*tracker, std::move(bytes), 1'000'000);
  std::size_t allocations = 0;
  {
    kestrel::test::AllocationGuard guard;
    run.run_to_end();
    allocations = guard.allocations();
  }
  CHECK(allocations == 0);
  const kestrel::sim::StreamRunResult r = run.result();
  REQUIRE(r.frames.size() == 300);
  std::size_t reports = 0, valid = 0;
  for (const auto& f : r.frames) {
    REQUIRE(f.mode_probabilities.size() == f.tracks.size());
    for (const auto& mu : f.mode_probabilities) {
      ++reports;
      REQUIRE(mu.size() == 3);
      const double sum = mu[0] + mu[1] + mu[2];
      if (std::isfinite(sum) && std::abs(sum - 1.0) < 1e-9 && mu[0] >= 0 && mu[1] >= 0 && mu[2] >= 0) ++valid;
    }
  }
  // One confirmed track reported from the third frame on; every report's
  // probabilities found in the table and summing to 1.
  CHECK(reports >= 290);
  CHECK(valid == reports);
}
