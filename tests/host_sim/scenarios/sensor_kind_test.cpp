// SPDX-License-Identifier: Apache-2.0
// Sensor kinds of scenario names, filter names and decoded streams: what
// `run` and `replay` dispatch on (docs/host_sim.md), and what a PCL or sonar
// stream replay runs: the same tracks as the scenario run it was generated from.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "montecarlo/pcl_run.hpp"
#include "montecarlo/sonar_run.hpp"
#include "scenarios/pcl002.hpp"
#include "scenarios/sensor_kind.hpp"
#include "scenarios/uw003.hpp"
#include "stream/stream_writer.hpp"

using namespace kestrel::sim;  // NOLINT(google-build-using-namespace): test file
using kestrel::PclTrackerParams;
using kestrel::SonarTrackerParams;
using kestrel::hal::FrameKind;

SCENARIO("Scenario and filter names map to their sensor kind", "[host_sim][sensor_kind]") {
  THEN("each registry gives its kind, case-insensitively, and an unknown name none") {
    CHECK(scenario_kind("s1") == FrameKind::kRadar);
    CHECK(scenario_kind("raid") == FrameKind::kRadar);
    CHECK(scenario_kind("PCL002-hard") == FrameKind::kPcl);
    CHECK(scenario_kind("uw003-1ms") == FrameKind::kSonar);
    CHECK_FALSE(scenario_kind("s9").has_value());
  }
  THEN("the filters that fit a kind are its own only") {
    CHECK(filters_for_kind(FrameKind::kPcl) == std::vector<std::string>{"pcl-kf"});
    CHECK(filters_for_kind(FrameKind::kSonar) == std::vector<std::string>{"sonar-ekf"});
    const std::vector<std::string> radar = filters_for_kind(FrameKind::kRadar);
    CHECK(std::find(radar.begin(), radar.end(), "ekf-ca") != radar.end());
    CHECK(std::find(radar.begin(), radar.end(), "pcl-kf") == radar.end());
    CHECK(filter_kind("ekf-ca") == FrameKind::kRadar);
    CHECK(filter_kind("SONAR-EKF") == FrameKind::kSonar);
    CHECK_FALSE(filter_kind("nope").has_value());
  }
}

SCENARIO("A decoded stream's frames are counted by kind", "[host_sim][sensor_kind]") {
  GIVEN("a PCL stream followed by a sonar stream") {
    const PclScenarioRun pcl = generate_pcl(pcl002_config(), 3);
    const SonarScenarioRun sonar_run = generate_sonar(sonar_config_by_name("uw003"), 3);
    std::vector<std::uint8_t> bytes = encode_pcl_stream(pcl);
    const std::vector<std::uint8_t> sonar = encode_sonar_stream(sonar_run);
    bytes.insert(bytes.end(), sonar.begin(), sonar.end());
    std::size_t skipped = 0;
    std::vector<MeasurementFrame> frames = decode_stream(bytes, skipped);
    REQUIRE(skipped == 0);
    THEN("both kinds are counted and named") {
      const FrameKindCounts c = count_frame_kinds(frames);
      CHECK(c.pcl == pcl.frames.size());
      CHECK(c.sonar == sonar_run.frames.size());
      CHECK(c.radar == 0);
      CHECK(c.kinds() == 2);
      CHECK(c.describe() ==
            std::to_string(pcl.frames.size()) + " PCL, " + std::to_string(sonar_run.frames.size()) + " sonar");
    }
    THEN("a frame that did not decode counts as undecoded, not as radar") {
      frames.push_back(MeasurementFrame{});
      frames.back().t_s = std::nan("");
      const FrameKindCounts c = count_frame_kinds(frames);
      CHECK(c.radar == 0);
      CHECK(c.undecoded == 1);
    }
  }
}

SCENARIO("A PCL stream replayed without its reference gives the scenario run's tracks", "[host_sim][sensor_kind][pcl]") {
  GIVEN("pcl002 seed 3, run as `pcl` runs it and as `replay --stream` runs its stream") {
    const PclScenarioParams c = pcl002_config();
    const PclScenarioRun run = generate_pcl(c, 3);
    const PclTrackerParams params = pcl_params_for(c);
    const PclRunOutput scenario_run = run_pcl(run, c, params, TrackerPolicies{}, 1'000'000'000);
    const PclRunOutput replay = run_pcl_stream(encode_pcl_stream(run), std::vector<PclFrameRecord>{}, c, params, TrackerPolicies{}, 1'000'000'000);
    THEN("every frame has the same confirmed tracks and the frame's wire time") {
      REQUIRE(replay.frames.size() == run.frames.size());
      std::size_t rows = 0;
      for (std::size_t k = 0; k < run.frames.size(); ++k) {
        const auto& a = scenario_run.frames[k].tracks;
        const auto& b = replay.frames[k].tracks;
        REQUIRE(a.size() == b.size());
        for (std::size_t i = 0; i < a.size(); ++i) {
          CHECK(a[i].id == b[i].id);
          CHECK(a[i].rb_m == b[i].rb_m);  // same bytes, same tracker: bit-identical
        }
        rows += b.size();
        // The wire carries whole microseconds.
        CHECK_THAT(replay.frames[k].t_s, Catch::Matchers::WithinAbs(run.truth[k].t_s, 0.5e-6));
        // Without a reference the target's candidate is unknown.
        CHECK(replay.frames[k].target_index == -1);
      }
      CHECK(rows > 0);
    }
  }
}

SCENARIO("A sonar stream replayed gives the scenario run's estimates with their frame times", "[host_sim][sensor_kind][sonar]") {
  GIVEN("uw003 seed 3") {
    const SonarScenarioParams c = sonar_config_by_name("uw003");
    const SonarScenarioRun run = generate_sonar(c, 3);
    const SonarTrackerParams params = sonar_params_for(c);
    const SonarRunOutput a = run_sonar(run, params, 1'000'000'000);
    const SonarRunOutput b = run_sonar_stream(encode_sonar_stream(run), params, 1'000'000'000);
    THEN("the estimates agree bit for bit and t_s is the wire time") {
      REQUIRE(b.frames.size() == run.frames.size());
      std::size_t reported = 0;
      for (std::size_t k = 0; k < run.frames.size(); ++k) {
        CHECK(a.frames[k].reported == b.frames[k].reported);
        CHECK(a.frames[k].x == b.frames[k].x);
        CHECK_THAT(b.frames[k].t_s, Catch::Matchers::WithinAbs(run.truth[k].t_s, 0.5e-6));
        reported += b.frames[k].reported ? 1 : 0;
      }
      CHECK(reported > 0);
    }
  }
}
