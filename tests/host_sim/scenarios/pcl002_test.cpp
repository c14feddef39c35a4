// SPDX-License-Identifier: Apache-2.0
// PCL-002 against docs/scenarios.md (the drone's box and limits, the frame
// statistics, reproducibility), the PCL metrics on a hand-made run, and an
// end-to-end check of the tracker through the board loop (the goals of docs/pcl.md
// on a few seeds; figures independent of the number of worker threads).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <vector>

#include "metrics/pcl_metrics.hpp"
#include "montecarlo/pcl_monte_carlo.hpp"
#include "scenarios/pcl002.hpp"
#include "stream/stream_writer.hpp"

using namespace kestrel::sim;  // NOLINT(google-build-using-namespace): test file
using Catch::Matchers::WithinAbs;

SCENARIO("PCL-002 drones stay in the scenario box and within the acceleration limits", "[host_sim][scenarios][pcl]") {
  const PclScenarioParams c = pcl002_config();
  double r_min = 1e9, r_max = 0.0, y_min = 1e9, z_min = 1e9, z_max = 0.0, v_max = 0.0;
  double along_max = 0.0, total_max = 0.0;
  for (std::uint64_t seed = 0; seed < 100; ++seed) {
    const PclScenarioRun run = generate_pcl(c, seed);
    REQUIRE(run.truth.size() == 120);
    REQUIRE(run.frames.size() == 120);
    for (std::size_t k = 0; k < run.truth.size(); ++k) {
      const PclTruth& t = run.truth[k];
      r_min = std::min(r_min, std::hypot(t.x_m, t.y_m));
      r_max = std::max(r_max, std::hypot(t.x_m, t.y_m));
      y_min = std::min(y_min, t.y_m);
      z_min = std::min(z_min, t.z_m);
      z_max = std::max(z_max, t.z_m);
      v_max = std::max(v_max, std::sqrt(t.vx_mps * t.vx_mps + t.vy_mps * t.vy_mps + t.vz_mps * t.vz_mps));
      if (k == 0 || k + 1 == run.truth.size()) continue;
      // Mean accelerations over [t - T, t + T]: speed change (along track)
      // and velocity change (total); the instantaneous limits bound both.
      const PclTruth& a = run.truth[k - 1];
      const PclTruth& b = run.truth[k + 1];
      const double dt = b.t_s - a.t_s;
      const double speed_a = std::hypot(a.vx_mps, a.vy_mps), speed_b = std::hypot(b.vx_mps, b.vy_mps);
      along_max = std::max(along_max, std::abs(speed_b - speed_a) / dt);
      total_max = std::max(total_max, std::hypot(b.vx_mps - a.vx_mps, b.vy_mps - a.vy_mps) / dt);
    }
  }
  CHECK(r_min >= 300.0);
  CHECK(r_max <= 900.0);
  CHECK(y_min > 0.0);
  CHECK(z_min >= 50.0);
  CHECK(z_max <= 120.0);
  CHECK(v_max <= 26.0);
  CHECK(along_max <= 2.0 + 1e-6);
  CHECK(total_max <= std::hypot(3.0, 2.0));
  THEN("the drones use the box and the Doppler span the scenario describes") {
    CHECK(r_min < 400.0);
    CHECK(r_max > 800.0);
    CHECK(v_max > 20.0);
  }
}

SCENARIO("PCL-002 truth: Rb and fD follow the geometry", "[host_sim][scenarios][pcl]") {
  const PclScenarioParams c = pcl002_config();
  const PclScenarioRun run = generate_pcl(c, 3);
  const double lambda = pcl_lambda_m(c);
  CHECK_THAT(lambda, WithinAbs(0.4277, 5e-5));
  for (const PclTruth& t : run.truth) {
    const double rb = std::hypot(t.x_m, t.y_m + 8500.0, t.z_m) + std::hypot(t.x_m, t.y_m, t.z_m) - 8500.0;
    CHECK_THAT(t.rb_m, WithinAbs(rb, 1e-9));
    CHECK_THAT(t.fd_hz, WithinAbs(-t.drb_mps / lambda, 1e-9));
    CHECK(std::abs(t.fd_hz) < 125.0);
  }
  // dRb is the derivative of Rb: mean rate over a frame vs the mean of the ends
  // (trapezoid; error ~ T^2/12 * d3Rb/dt3, well under 0.5 m/s at these accelerations).
  for (std::size_t k = 1; k < run.truth.size(); ++k) {
    const double secant = (run.truth[k].rb_m - run.truth[k - 1].rb_m) / 0.5;
    CHECK_THAT(secant, WithinAbs(0.5 * (run.truth[k].drb_mps + run.truth[k - 1].drb_mps), 0.5));
  }
}

SCENARIO("PCL-002 frames: detection, noise, clutter and ridge as docs/scenarios.md describes", "[host_sim][scenarios][pcl]") {
  const PclScenarioParams c = pcl002_config();
  std::size_t frames = 0, detections = 0, candidates = 0, ridge = 0;
  double se_rb = 0.0, se_fd = 0.0;
  for (std::uint64_t seed = 0; seed < 40; ++seed) {
    const PclScenarioRun run = generate_pcl(c, seed);
    for (std::size_t k = 0; k < run.frames.size(); ++k) {
      const PclFrameRecord& f = run.frames[k];
      ++frames;
      REQUIRE(f.wire.kind == kestrel::hal::FrameKind::kPcl);
      REQUIRE(f.wire.count <= kestrel::hal::kMaxPclCandidates);
      CHECK(f.wire.t_us == static_cast<std::int64_t>(k) * 500000);
      candidates += f.wire.count;
      for (std::size_t i = 0; i < f.wire.count; ++i) {
        const double rb = f.wire.pcl[i].bistatic_range_mm * 1e-3;
        const double fd = f.wire.pcl[i].doppler_mhz * 1e-3;
        if (static_cast<int>(i) == f.target_index) {
          se_rb += (rb - run.truth[k].rb_m) * (rb - run.truth[k].rb_m);
          se_fd += (fd - run.truth[k].fd_hz) * (fd - run.truth[k].fd_hz);
          continue;
        }
        CHECK(rb <= 3000.0);
        CHECK(std::abs(fd) <= 125.0);
        CHECK(f.wire.pcl[i].snr_cdb >= 1200);
        CHECK(f.wire.pcl[i].snr_cdb <= 2000);
        if (std::abs(fd) < 1.0) ++ridge;
      }
      if (f.target_index >= 0) ++detections;
      CHECK(f.detected == (f.target_index >= 0));  // no 64-cut at this density
    }
  }
  const double n = static_cast<double>(frames);
  // 4800 frames: binomial sd of Pd is 0.0043; Poisson sd of the mean count 0.07.
  CHECK_THAT(detections / n, WithinAbs(0.9, 0.015));
  CHECK_THAT(candidates / n, WithinAbs(0.9 + 21.0 + 1.5, 0.3));
  // Ridge: 1.5 per frame plus the clutter that falls below 1 Hz (21 * 2 / 250).
  CHECK_THAT(ridge / n, WithinAbs(1.5 + 21.0 * 2.0 / 250.0, 0.08));
  CHECK_THAT(std::sqrt(se_rb / static_cast<double>(detections)), WithinAbs(10.0, 0.4));
  CHECK_THAT(std::sqrt(se_fd / static_cast<double>(detections)), WithinAbs(0.5, 0.02));
}

SCENARIO("PCL-002 is reproducible bit for bit, and the hard variant is cut to the wire's 64",
         "[host_sim][scenarios][pcl]") {
  const PclScenarioRun a = generate_pcl(pcl002_config(), 17);
  const PclScenarioRun b = generate_pcl(pcl002_config(), 17);
  const PclScenarioRun other = generate_pcl(pcl002_config(), 18);
  // The frames are compared as wire bytes: a candidate's padding is
  // indeterminate, so the objects themselves need not match.
  bool same = a.frames.size() == b.frames.size();
  bool differs = false;
  for (std::size_t k = 0; same && k < a.frames.size(); ++k) {
    std::vector<std::uint8_t> a_bytes, b_bytes;
    kestrel::sim::append_encoded(a.frames[k].wire, a_bytes);
    kestrel::sim::append_encoded(b.frames[k].wire, b_bytes);
    same = a_bytes == b_bytes && a.frames[k].target_index == b.frames[k].target_index && a.truth[k].rb_m == b.truth[k].rb_m;
    differs = differs || a.truth[k].rb_m != other.truth[k].rb_m;
  }
  CHECK(same);
  CHECK(differs);

  const PclScenarioParams hard = pcl002_hard_config();
  std::size_t over = 0, cut_detections = 0, detected = 0;
  for (std::uint64_t seed = 0; seed < 10; ++seed) {
    const PclScenarioRun run = generate_pcl(hard, seed);
    for (const PclFrameRecord& f : run.frames) {
      CHECK(f.wire.count <= 64);
      if (f.generated > 64) ++over;
      if (f.detected) ++detected;
      if (f.detected && f.target_index < 0) ++cut_detections;
    }
  }
  CHECK(over > 200);  // Poisson(63) + ridge + target exceeds 64 in about half the frames
  CHECK(cut_detections > 0);
  CHECK_THAT(detected / 1200.0, WithinAbs(0.7, 0.05));
}

SCENARIO("PCL metrics on a hand-made run", "[host_sim][metrics][pcl]") {
  // Ten frames, truth Rb = 1000 - 5k, dRb = -10. Track 7 is confirmed from
  // frame 4 on the target (it takes the detection, index 0, except in frame
  // 6 where it takes clutter index 1 and in frame 8 where it misses);
  // track 9 is a false track in frames 5..7; frame 7 has no detection.
  PclScenarioRun run;
  PclRunOutput out;
  for (int k = 0; k < 10; ++k) {
    PclTruth t;
    t.t_s = 0.5 * k;
    t.rb_m = 1000.0 - 5.0 * k;
    t.drb_mps = -10.0;
    run.truth.push_back(t);
    PclFrameRecord f;
    f.wire.kind = kestrel::hal::FrameKind::kPcl;
    f.wire.count = 2;
    f.target_index = k == 7 ? -1 : 0;
    f.detected = k != 7;
    run.frames.push_back(f);
    PclFrameOutcome o;
    o.stepped = true;
    o.target_in_scan = f.target_index >= 0;
    if (k >= 4) {
      PclTrackRow r;
      r.id = 7;
      r.rb_m = t.rb_m + 3.0;
      r.drb_mps = -10.0 + (k == 9 ? 6.0 : 0.0);  // off target in frame 9 (dRb 6 m/s off)
      r.associated = k != 8;
      r.frame_index = k == 6 ? 1 : (k == 8 ? -1 : 0);
      o.tracks.push_back(r);
    }
    if (k >= 5 && k <= 7) {
      PclTrackRow r;
      r.id = 9;
      r.rb_m = 2000.0;
      r.drb_mps = 20.0;
      o.tracks.push_back(r);
    }
    out.frames.push_back(o);
  }
  const PclRunMetrics m = score_pcl_run(run, out, PclTolerance{});
  THEN("each figure counts what docs/metrics.md says") {
    CHECK(m.confirmed_tracks == 2);
    CHECK(m.target_tracks == 1);
    CHECK(m.false_tracks == 1);
    // Target track in frames 4..9; detections there except frame 7: 4,5,6,8,9;
    // correct in 4, 5, 9 (6 took clutter, 8 missed).
    CHECK(m.assoc_frames == 5);
    CHECK(m.assoc_correct == 3);
    CHECK_THAT(m.association_accuracy, WithinAbs(0.6, 1e-12));
    // Frames after the first confirmation (4): 5..9; on target in 5..8.
    CHECK(m.coverage_frames == 5);
    CHECK(m.covered_frames == 4);
    CHECK_THAT(m.time_to_confirm_s, WithinAbs(2.0, 1e-12));
    CHECK(m.rmse_frames == 6);
    CHECK_THAT(m.rb_rmse_m, WithinAbs(3.0, 1e-12));
    CHECK_THAT(m.drb_rmse_mps, WithinAbs(std::sqrt(36.0 / 6.0), 1e-12));
    CHECK(m.detections == 9);
  }
}

SCENARIO("the PCL tracker meets its accuracy goals on pcl002 through the board loop", "[host_sim][end_to_end][pcl]") {
  const PclScenarioParams sc = pcl002_config();
  PclMonteCarloParams c;
  c.runs = 12;
  c.base_seed = 100;
  c.jobs = 1;
  const PclMonteCarloResult one = run_pcl_monte_carlo(sc, pcl_params_for(sc), c);
  c.jobs = 3;
  const PclMonteCarloResult three = run_pcl_monte_carlo(sc, pcl_params_for(sc), c);
  const PclSummary s = summarise_pcl(one.runs, c.budget_ns);
  THEN("accuracy and coverage over 0.95, false tracks rare, Rb error near sigma_Rb / 3") {
    CHECK(s.association_accuracy.mean >= 0.95);
    CHECK(s.coverage.mean >= 0.95);
    CHECK(s.false_tracks.mean <= 0.25);
    CHECK(s.rb_rmse_m.mean < 5.0);
    CHECK(s.runs_never_confirmed == 0);
    CHECK(s.frames_refused == 0);
  }
  THEN("the figures do not depend on the number of worker threads") {
    for (std::size_t i = 0; i < c.runs; ++i) {
      CHECK(one.runs[i].assoc_correct == three.runs[i].assoc_correct);
      CHECK(one.runs[i].covered_frames == three.runs[i].covered_frames);
      CHECK(one.runs[i].false_tracks == three.runs[i].false_tracks);
      CHECK(one.runs[i].rb_rmse_m == three.runs[i].rb_rmse_m);
    }
  }
}

SCENARIO("on pcl002-hard, PDA with the track score holds the drone and confirms almost no clutter",
         "[host_sim][end_to_end][pcl][policies]") {
  const PclScenarioParams sc = pcl002_hard_config();
  PclMonteCarloParams c;
  c.runs = 40;
  c.base_seed = 100;
  c.jobs = 2;
  c.policies = {AssociatorChoice::kPda, ManagerChoice::kScore};
  const PclSummary s = summarise_pcl(run_pcl_monte_carlo(sc, pcl_params_for(sc), c).runs, c.budget_ns);
  c.policies = {};
  const PclSummary nn = summarise_pcl(run_pcl_monte_carlo(sc, pcl_params_for(sc), c).runs, c.budget_ns);
  THEN("association and coverage of at least 0.95 and at most 0.1 false confirmed tracks per run") {
    CHECK(s.association_accuracy.mean >= 0.95);
    CHECK(s.coverage.mean >= 0.95);
    CHECK(s.false_tracks.mean <= 0.1);
    CHECK(s.runs_never_confirmed == 0);
  }
  THEN("where nearest neighbour with 5-of-6 falls short of both") {
    CHECK(nn.association_accuracy.mean < 0.95);
    CHECK(nn.false_tracks.mean > 0.5);
  }
}
