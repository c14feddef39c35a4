// SPDX-License-Identifier: Apache-2.0
// Range rate end to end: the rr scenarios, hal::RadarAdapter's
// three-channel conversion and its refusal of plots without range rate, and
// EKF-CA with range rate (ekf-ca-rr, double and float) over S1rr/S2rr
// through the whole host chain (scenario -> wire stream -> StreamFileFeed
// -> RadarAdapter -> tracker -> sink -> scoring).
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "filters/filter_registry.hpp"
#include "kestrel/hal/radar_adapter.hpp"
#include "montecarlo/monte_carlo.hpp"
#include "montecarlo/single_run.hpp"
#include "scenarios/radar_scenario.hpp"
#include "scenarios/registry.hpp"

using namespace kestrel::sim;  // NOLINT(google-build-using-namespace)
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {
kestrel::hal::Frame radar_frame(std::int64_t t_us) {
  kestrel::hal::Frame f{};
  f.kind = kestrel::hal::FrameKind::kRadar;
  f.t_us = t_us;
  f.count = 2;
  f.radar[0] = kestrel::hal::RadarPlot{17'000'500, 1'073'741'824, -123'456, 1500, 1, 0};  // bearing pi/2
  f.radar[1] = kestrel::hal::RadarPlot{9'000'000, -536'870'912, 250'001, 1200, 1, 0};     // bearing -pi/4
  return f;
}
}  // namespace

SCENARIO("s1rr and s2rr add a range rate to the s1 and s2 plots", "[host_sim][scenarios][range_rate]") {
  for (const char* base : {"s1", "s2"}) {
    GIVEN("seed 11 through " << base << " and " << base << "rr") {
      const auto plain = make_scenario(base)->generate(11);
      const auto rr = make_scenario(std::string(base) + "rr")->generate(11);
      REQUIRE(plain.frames.size() == rr.frames.size());
      THEN("range and bearing are the same bits, and only rr carries a range rate") {
        for (std::size_t k = 0; k < plain.frames.size(); ++k) {
          INFO("k = " << k);
          CHECK(rr.frames[k].radar[0].range_m == plain.frames[k].radar[0].range_m);
          CHECK(rr.frames[k].radar[0].bearing_rad == plain.frames[k].radar[0].bearing_rad);
          CHECK_FALSE(plain.frames[k].radar[0].range_rate_mps.has_value());
          CHECK(rr.frames[k].radar[0].range_rate_mps.has_value());
        }
      }
      THEN("the range-rate error about (x vx + y vy)/r has mean ~0 and sd kRangeRateSigmaMps") {
        double sum = 0.0;
        double sum2 = 0.0;
        const std::size_t n = rr.frames.size();
        for (std::size_t k = 0; k < n; ++k) {
          const TruthSample& s = rr.truth[k];
          const double truth = (s.x_m * s.vx_mps + s.y_m * s.vy_mps) / std::hypot(s.x_m, s.y_m);
          const double e = *rr.frames[k].radar[0].range_rate_mps - truth;
          sum += e;
          sum2 += e * e;
        }
        const double mean = sum / static_cast<double>(n);
        const double sd = std::sqrt(sum2 / static_cast<double>(n) - mean * mean);
        // 300 draws: the mean's sd is 0.5/sqrt(300) = 0.029 (4 sigma: 0.12),
        // the sd's relative sd 1/sqrt(600) = 4 % (4 sigma: 16 %). A missing
        // factor (e.g. sigma in mm/s, or r^2 in the denominator) is far off.
        CHECK(std::abs(mean) < 0.12);
        CHECK_THAT(sd, WithinRel(kRangeRateSigmaMps, 0.16));
      }
    }
  }
}

SCENARIO("RadarAdapter converts range rate for a three-channel scan", "[host_sim][hal][range_rate]") {
  GIVEN("a radar frame whose plots carry range rate") {
    const kestrel::hal::Frame frame = radar_frame(2'500'000);
    WHEN("it is converted into double and float three-channel scans") {
      kestrel::MeasurementScan<double, 3, 4> scan;
      kestrel::MeasurementScan<float, 3, 4> scan_f;
      const kestrel::hal::RadarAdapter adapter;
      const kestrel::Status s = adapter(frame, scan);
      const kestrel::Status s_f = adapter(frame, scan_f);
      THEN("range rate is range_rate_mmps / 1000 m/s, range and bearing as before") {
        REQUIRE(s == kestrel::Status::kOk);
        REQUIRE(s_f == kestrel::Status::kOk);
        CHECK(scan.t_us == 2'500'000);
        REQUIRE(scan.count == 2);
        CHECK(scan.z[0](0) == 17000.5);
        CHECK_THAT(scan.z[0](1), WithinAbs(3.14159265358979323846 / 2, 1e-15));
        CHECK(scan.z[0](2) == -123.456);  // from_ratio: the correctly rounded quotient
        CHECK(scan.z[1](2) == 250.001);
        CHECK_THAT(scan.z[1](1), WithinAbs(-3.14159265358979323846 / 4, 1e-15));
        // Float: the nearest float to the double value.
        CHECK(scan_f.z[0](2) == static_cast<float>(-123.456));
        CHECK(scan_f.z[1](2) == static_cast<float>(250.001));
      }
    }
    WHEN("it is converted into a two-channel scan") {
      kestrel::MeasurementScan<double, 2, 4> scan;
      THEN("range and bearing are those of the three-channel scan (range rate unused)") {
        kestrel::MeasurementScan<double, 3, 4> scan3;
        REQUIRE(kestrel::hal::to_scan(frame, scan) == kestrel::Status::kOk);
        REQUIRE(kestrel::hal::to_scan(frame, scan3) == kestrel::Status::kOk);
        CHECK(scan.z[1](0) == scan3.z[1](0));
        CHECK(scan.z[1](1) == scan3.z[1](1));
      }
    }
  }
  GIVEN("a frame in which one plot has no range rate") {
    kestrel::hal::Frame frame = radar_frame(3'000'000);
    frame.radar[1].has_range_rate = 0;
    frame.radar[1].range_rate_mmps = 0;
    kestrel::MeasurementScan<double, 3, 4> scan;
    scan.t_us = 42;
    scan.count = 1;
    scan.z[0] << 1.0, 2.0, 3.0;
    WHEN("it is converted into a three-channel scan") {
      const kestrel::Status s = kestrel::hal::to_scan(frame, scan);
      THEN("the frame is refused with kWrongKind and the scan is untouched (no made-up zero)") {
        CHECK(s == kestrel::Status::kWrongKind);
        CHECK(scan.t_us == 42);
        CHECK(scan.count == 1);
        CHECK(scan.z[0](2) == 3.0);
      }
    }
    WHEN("it has more plots than the scan holds and only the dropped one lacks range rate") {
      kestrel::MeasurementScan<double, 3, 1> small;
      const kestrel::Status s = kestrel::hal::to_scan(frame, small);
      THEN("the kept plot converts and the excess is reported") {
        CHECK(s == kestrel::Status::kTooManyCandidates);
        CHECK(small.count == 1);
        CHECK(small.z[0](2) == -123.456);
      }
    }
  }
  GIVEN("a sonar frame") {
    kestrel::hal::Frame frame{};
    frame.kind = kestrel::hal::FrameKind::kSonar;
    kestrel::MeasurementScan<double, 3, 4> scan;
    THEN("it is not a radar frame: kWrongKind") {
      CHECK(kestrel::hal::to_scan(frame, scan) == kestrel::Status::kWrongKind);
    }
  }
}

SCENARIO("EKF-CA with range rate refuses range-bearing-only streams", "[host_sim][e2e][range_rate]") {
  GIVEN("s1 (no range rate) run through ekf-ca-rr") {
    const auto scenario = make_scenario("s1");
    const RunDetail d = run_scenario_once(*scenario, 0, find_filter("ekf-ca-rr"), FilterOptions{}, 1'000'000,
                                          ScoringParams{});
    THEN("every frame is refused with kWrongKind, no step runs and no track is reported") {
      REQUIRE(d.stream.frames.size() == 300);
      for (const FrameOutcome& f : d.stream.frames) {
        CHECK(f.status == kestrel::Status::kWrongKind);
        CHECK_FALSE(f.stepped);
        CHECK(f.tracks.empty());
      }
      CHECK(d.stream.stats.steps == 0);
    }
  }
}

SCENARIO("EKF-CA with range rate holds the S1rr and S2rr targets", "[host_sim][e2e][range_rate]") {
  for (const char* filter_name : {"ekf-ca-rr", "ekf-ca-rr-f32"}) {
    for (const char* name : {"s1rr", "s2rr"}) {
      GIVEN(filter_name << " with qj 160 on 3 runs of " << name << " (seeds 0-2)") {
        const auto scenario = make_scenario(name);
        const FilterEntry& filter = find_filter(filter_name);
        FilterOptions options;
        options.qj = 160.0;  // the tuned EKF-CA of docs/references.md; at 1.6 the filter is inconsistent (docs/range_rate.md)
        std::vector<RunRecord> runs;
        for (std::uint64_t seed = 0; seed < 3; ++seed) {
          runs.push_back(record_of(run_scenario_once(*scenario, seed, filter, options, 1'000'000, ScoringParams{})));
        }
        THEN("every scored frame has one confirmed track, with one id, and every frame steps") {
          for (const RunRecord& r : runs) {
            INFO(name << " seed " << r.seed);
            CHECK(r.metrics.scored_steps == 298);
            CHECK(r.metrics.missing_steps == 0);
            CHECK(r.frames_not_ok == 0);
            CHECK(r.max_confirmed_tracks == 1);
            CHECK(r.track_switches == 0);
          }
        }
        THEN("RMSE is under 100 m and the 3-channel NIS is near its 3 degrees of freedom") {
          for (const RunRecord& r : runs) {
            INFO(name << " seed " << r.seed << ": RMSE " << r.metrics.rmse_m << " m, NIS " << r.metrics.nis);
            // 200-run means (docs/range_rate.md): RMSE 54 / 59 m, NIS 3.3 / 2.4
            // on s1rr / s2rr; a range rate read in mm/s or a bearing in
            // degrees sends them far past these bounds.
            CHECK(r.metrics.rmse_m < 100.0);
            CHECK(r.metrics.nis < 6.0);
          }
        }
      }
    }
  }
}
