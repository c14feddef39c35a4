// SPDX-License-Identifier: Apache-2.0
// `replay --truth` of PCL and sonar streams: the truth CSV `generate` writes
// is read back exactly and tells its kind by its columns, and a replay of
// the unchanged stream scored against it gives the generating run's
// metrics bit for bit (the kind's scorer, as `pcl` and `sonar` use it).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "csv/sensor_truth_csv.hpp"
#include "csv/truth_csv.hpp"
#include "metrics/replay_scoring.hpp"
#include "montecarlo/pcl_run.hpp"
#include "montecarlo/sonar_run.hpp"
#include "stream/stream_writer.hpp"

using namespace kestrel::sim;  // NOLINT(google-build-using-namespace): test file
using kestrel::PclTrackerParams;
using kestrel::SonarTrackerParams;
using kestrel::hal::FrameKind;

namespace {

std::filesystem::path temp_path(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("kestrel_replay_scoring_" + name);
}

/// Equal, NaN equal to NaN (a metric with no data is NaN on both sides).
bool same(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

constexpr std::uint64_t kBudgetNs = 1'000'000'000;

}  // namespace

SCENARIO("PCL and sonar truth CSVs round-trip and name their kind", "[host_sim][replay_scoring]") {
  GIVEN("the truth of pcl002 seed 3 and uw003 seed 3 as generate writes it") {
    const PclScenarioRun pcl = generate_pcl(pcl002_config(), 3);
    const SonarScenarioRun sonar = generate_sonar(sonar_config_by_name("uw003"), 3);
    const auto pcl_path = temp_path("pcl.truth.csv");
    const auto sonar_path = temp_path("sonar.truth.csv");
    write_pcl_truth_csv(pcl_path, pcl);
    write_sonar_truth_csv(sonar_path, sonar);
    THEN("each file is read back bit for bit, the target detection and outliers included") {
      const std::vector<PclTruthRow> p = read_pcl_truth_csv(pcl_path);
      REQUIRE(p.size() == pcl.truth.size());
      std::size_t detections = 0;
      for (std::size_t k = 0; k < p.size(); ++k) {
        CHECK(p[k].truth.t_s == pcl.truth[k].t_s);
        CHECK(p[k].truth.rb_m == pcl.truth[k].rb_m);
        CHECK(p[k].truth.drb_mps == pcl.truth[k].drb_mps);
        CHECK(p[k].detected == pcl.frames[k].detected);
        REQUIRE(p[k].detection.has_value() == (pcl.frames[k].target_index >= 0));
        if (p[k].detection) {
          ++detections;
          const auto& want = pcl.frames[k].wire.pcl[static_cast<std::size_t>(pcl.frames[k].target_index)];
          CHECK(p[k].detection->bistatic_range_mm == want.bistatic_range_mm);
          CHECK(p[k].detection->doppler_mhz == want.doppler_mhz);
        }
      }
      CHECK(detections > 90);  // P_D 0.9 over 120 frames
      const std::vector<SonarTruthRow> u = read_sonar_truth_csv(sonar_path);
      REQUIRE(u.size() == sonar.truth.size());
      std::size_t outliers = 0;
      for (std::size_t k = 0; k < u.size(); ++k) {
        CHECK(u[k].truth.z_m == sonar.truth[k].z_m);
        CHECK(u[k].truth.c_mps == sonar.truth[k].c_mps);
        CHECK(u[k].channels == 0xFFu);  // 4 beacons x direct and reflected
        for (const SonarArrivalRecord& a : sonar.frames[k].arrivals) outliers += a.outlier ? 1 : 0;
      }
      std::size_t outlier_bits = 0;
      for (const SonarTruthRow& r : u) {
        for (std::uint32_t b = r.outlier_channels; b != 0; b &= b - 1) ++outlier_bits;
      }
      CHECK(outlier_bits == outliers);
    }
    THEN("the kind of a truth CSV is told by its columns") {
      CHECK(truth_csv_kind(pcl_path) == FrameKind::kPcl);
      CHECK(truth_csv_kind(sonar_path) == FrameKind::kSonar);
      const auto radar_path = temp_path("radar.truth.csv");
      write_truth_csv(radar_path, {TruthSample{}});
      CHECK(truth_csv_kind(radar_path) == FrameKind::kRadar);
    }
    THEN("a PCL truth is not a sonar truth: reading it as one names the missing column") {
      CHECK_THROWS_WITH(read_sonar_truth_csv(pcl_path), Catch::Contains("missing required column 'c_mps'"));
    }
  }
}

SCENARIO("A PCL replay scored against its truth gives the generating run's metrics", "[host_sim][replay_scoring][pcl]") {
  for (const char* name : {"pcl002", "pcl002-hard"}) {
    GIVEN(std::string(name) + " seed 5, run as `pcl` runs it and replayed from its stream and truth CSV") {
      const PclScenarioParams c = pcl_config_by_name(name);
      const PclScenarioRun run = generate_pcl(c, 5);
      const PclTrackerParams params = pcl_params_for(c);
      const PclTolerance tol{};
      const PclRunMetrics want = score_pcl_run(run, run_pcl(run, c, params, TrackerPolicies{}, kBudgetNs), tol);
      const auto path = temp_path(std::string(name) + ".truth.csv");
      write_pcl_truth_csv(path, run);
      const std::vector<PclTruthRow> truth = read_pcl_truth_csv(path);
      const PclRunOutput out =
          run_pcl_stream(encode_pcl_stream(run), pcl_target_locator(truth), c, params, TrackerPolicies{}, kBudgetNs);
      const PclReplayScore got = score_pcl_replay(out, truth, tol);
      THEN("every frame is matched and every figure is the run's, bit for bit") {
        CHECK(got.match.matched == run.frames.size());
        CHECK(got.match.without_truth == 0);
        CHECK(got.match.without_time == 0);
        const PclRunMetrics& m = got.metrics;
        CHECK(m.assoc_correct == want.assoc_correct);
        CHECK(m.assoc_frames == want.assoc_frames);
        CHECK(m.assoc_frames > 0);
        CHECK(same(m.association_accuracy, want.association_accuracy));
        CHECK(m.covered_frames == want.covered_frames);
        CHECK(m.coverage_frames == want.coverage_frames);
        CHECK(same(m.coverage, want.coverage));
        CHECK(m.confirmed_tracks == want.confirmed_tracks);
        CHECK(m.false_tracks == want.false_tracks);
        CHECK(same(m.rb_rmse_m, want.rb_rmse_m));
        CHECK(same(m.drb_rmse_mps, want.drb_rmse_mps));
        CHECK(same(m.time_to_confirm_s, want.time_to_confirm_s));
        CHECK(m.detections == want.detections);
        CHECK(m.cut_by_adapter == want.cut_by_adapter);
        CHECK(m.cut_by_sensor == want.cut_by_sensor);
      }
    }
  }
  GIVEN("pcl002 seed 5 with its first 10 frames dropped from the stream") {
    const PclScenarioParams c = pcl002_config();
    PclScenarioRun run = generate_pcl(c, 5);
    const auto path = temp_path("pcl_dropped.truth.csv");
    write_pcl_truth_csv(path, run);
    const std::vector<PclTruthRow> truth = read_pcl_truth_csv(path);
    run.frames.erase(run.frames.begin(), run.frames.begin() + 10);
    const PclTrackerParams params = pcl_params_for(c);
    const PclRunOutput out =
        run_pcl_stream(encode_pcl_stream(run), pcl_target_locator(truth), c, params, TrackerPolicies{}, kBudgetNs);
    const PclReplayScore got = score_pcl_replay(out, truth, PclTolerance{});
    THEN("the remaining frames meet their own truth rows and the target's detection is still found") {
      CHECK(got.match.matched == run.frames.size());
      std::size_t found = 0;
      for (std::size_t k = 0; k < out.frames.size(); ++k) {
        CHECK(out.frames[k].target_index == run.frames[k].target_index);
        found += out.frames[k].target_index >= 0 ? 1 : 0;
      }
      CHECK(found > 80);
      CHECK(got.metrics.assoc_frames > 0);
    }
  }
}

SCENARIO("A sonar replay scored against its truth gives the generating run's metrics", "[host_sim][replay_scoring][sonar]") {
  for (const char* name : {"uw003", "uw003-1ms"}) {
    GIVEN(std::string(name) + " seed 5, run as `sonar` runs it and replayed from its stream and truth CSV") {
      const SonarScenarioParams c = sonar_config_by_name(name);
      const SonarScenarioRun run = generate_sonar(c, 5);
      const SonarTrackerParams params = sonar_params_for(c);
      const SonarRunMetrics want = score_sonar_run(run, run_sonar(run, params, kBudgetNs));
      const auto path = temp_path(std::string(name) + ".truth.csv");
      write_sonar_truth_csv(path, run);
      const SonarReplayScore got =
          score_sonar_replay(run_sonar_stream(encode_sonar_stream(run), params, kBudgetNs), read_sonar_truth_csv(path));
      THEN("every frame is matched and every figure is the run's, bit for bit") {
        CHECK(got.match.matched == run.frames.size());
        const SonarRunMetrics& m = got.metrics;
        CHECK(m.init_frame == want.init_frame);
        CHECK(m.scored_frames == want.scored_frames);
        CHECK(m.scored_frames > 40);
        CHECK(same(m.rmse_3d_m, want.rmse_3d_m));
        CHECK(same(m.rmse_h_m, want.rmse_h_m));
        CHECK(same(m.rmse_depth_m, want.rmse_depth_m));
        CHECK(same(m.peak_3d_m, want.peak_3d_m));
        CHECK(same(m.nees, want.nees));
        CHECK(same(m.c_err_mean_mps, want.c_err_mean_mps));
        CHECK(same(m.c_err_std_mps, want.c_err_std_mps));
        CHECK(m.arrivals == want.arrivals);
        CHECK(m.outliers == want.outliers);
        CHECK(m.outliers_gated == want.outliers_gated);
        CHECK(m.good_gated == want.good_gated);
        CHECK(m.gated == want.gated);
      }
    }
  }
}

SCENARIO("Frame times are counted against truth times to the microsecond", "[host_sim][replay_scoring]") {
  THEN("a time within the same microsecond matches, another does not, NaN never") {
    CHECK(count_truth_times({0.0, 0.5, 1.0}, {0.5, 1.0, 1.5}) == 2);
    CHECK(count_truth_times({0.5000001}, {0.5}) == 1);  // rounds to the same wire microsecond
    CHECK(count_truth_times({0.500002}, {0.5}) == 0);
    CHECK(count_truth_times({std::nan("")}, {0.5}) == 0);
    CHECK(count_truth_times({100.0, 101.0}, {0.0, 1.0}) == 0);
  }
}
