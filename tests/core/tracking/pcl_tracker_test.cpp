// SPDX-License-Identifier: Apache-2.0
// The PCL tracker (docs/tracking.md; PCL-002 in docs/scenarios.md): nearest neighbour picks
// the target among decoys and respects the gate and the one-candidate-one-
// track rule; 5-of-6 confirms and deletes exactly when it should; no track
// starts below 2 Hz while a confirmed track may cross zero Doppler; clutter
// alone confirms nothing within N frames; per-track diagnostics; zero
// allocations per frame.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>

#include "kestrel/tracking/pcl_tracker.hpp"
#include "support/alloc_guard.hpp"

namespace {

using kestrel::Status;
using kestrel::TrackStatus;
constexpr std::size_t kTracks = kestrel::kPclMaxTracks;
constexpr std::size_t kCandidates = 32;
using PclT = kestrel::PclTracker<kestrel::PclKf<double>, kTracks, kCandidates>;
using Scan = PclT::Scan;
constexpr std::int64_t kFrameUs = 500000;

const kestrel::PclTrackerParams kParams{};
const double kLambda = kestrel::pcl_wavelength_m<double>(kParams);

PclT make_tracker(const kestrel::PclTrackerParams& p = kParams) {
  return kestrel::make_pcl_tracker<double, kTracks, kCandidates>(p);
}

/// A candidate [Rb, dRb] from bistatic range (m) and Doppler (Hz).
kestrel::Vec<double, 2> cand(double rb_m, double fd_hz) {
  return {rb_m, kestrel::range_rate_from_doppler(fd_hz, kLambda)};
}

/// Noise-free target closing at 12 m/s from 1500 m (fD = +28.06 Hz).
kestrel::Vec<double, 2> target_at(int k) { return {1500.0 - 12.0 * 0.5 * k, -12.0}; }

Scan scan_at(int k) {
  Scan s;
  s.t_us = k * kFrameUs;
  s.count = 0;
  return s;
}

void add(Scan& s, const kestrel::Vec<double, 2>& z) { s.z[s.count++] = z; }

/// Runs frames 0..n-1 with the target detected where hits[k] is true.
void run_pattern(PclT& tracker, const bool* hits, int n) {
  for (int k = 0; k < n; ++k) {
    Scan s = scan_at(k);
    if (hits[k]) add(s, target_at(k));
    REQUIRE(tracker.step(s) == Status::kOk);
  }
}

std::size_t confirmed_count(const PclT& tracker) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < kTracks; ++i) {
    n += tracker.tracks()[i].status == TrackStatus::kConfirmed ? 1u : 0u;
  }
  return n;
}

/// Confirms the target track with five clean frames (0..4) and returns the next frame index.
int confirm_target(PclT& tracker) {
  const bool hits[5] = {true, true, true, true, true};
  run_pattern(tracker, hits, 5);
  REQUIRE(tracker.reports().size() == 1);
  return 5;
}

}  // namespace

SCENARIO("5-of-6 confirmation: a track confirms on its fifth hit within six frames", "[pcl][tracker][mofn]") {
  GIVEN("the target detected in every frame") {
    auto tracker = make_tracker();
    for (int k = 0; k < 5; ++k) {
      Scan s = scan_at(k);
      add(s, target_at(k));
      REQUIRE(tracker.step(s) == Status::kOk);
      if (k < 4) {
        CHECK(tracker.reports().empty());
        CHECK(tracker.tracks().size() == 1);
      }
    }
    THEN("it is confirmed on frame 4 (the fifth hit) with id 1") {
      REQUIRE(tracker.reports().size() == 1);
      CHECK(tracker.last_step().confirmed == 1);
      CHECK(tracker.reports()[0].track_id == 1);
      CHECK(tracker.reports()[0].hits == 5);
    }
  }
  GIVEN("one missed detection in frame 1") {
    auto tracker = make_tracker();
    const bool hits[6] = {true, false, true, true, true, true};
    run_pattern(tracker, hits, 5);
    CHECK(tracker.reports().empty());
    THEN("it confirms on frame 5 (five of six)") {
      Scan s = scan_at(5);
      add(s, target_at(5));
      REQUIRE(tracker.step(s) == Status::kOk);
      REQUIRE(tracker.reports().size() == 1);
      CHECK(tracker.reports()[0].track_id == 1);
    }
  }
  GIVEN("two misses before confirmation (M can no longer be met)") {
    struct Case {
      const char* name;
      bool hits[6];
      int deleted_at;
    };
    const Case cases[] = {{"H M M", {true, false, false}, 2},
                          {"H M H M", {true, false, true, false}, 3},
                          {"H H H H M M", {true, true, true, true, false, false}, 5}};
    for (const auto& c : cases) {
      WHEN(c.name) {
        auto tracker = make_tracker();
        for (int k = 0; k <= c.deleted_at; ++k) {
          Scan s = scan_at(k);
          if (c.hits[k]) add(s, target_at(k));
          REQUIRE(tracker.step(s) == Status::kOk);
          if (k < c.deleted_at) REQUIRE(tracker.tracks().size() == 1);
        }
        THEN("the tentative track is deleted in exactly that frame, never reported") {
          CHECK(tracker.last_step().deleted == 1);
          CHECK(tracker.tracks().size() == 0);
          CHECK(tracker.reports().empty());
        }
      }
    }
  }
}

SCENARIO("a confirmed PCL track coasts through misses and is deleted after max_coast_misses", "[pcl][tracker]") {
  auto params = kParams;
  params.max_rb_variance_m2 = 1e9;  // only the miss count deletes here
  auto tracker = make_tracker(params);
  int k = confirm_target(tracker);
  for (int miss = 1; miss <= params.max_coast_misses; ++miss, ++k) {
    REQUIRE(tracker.step(scan_at(k)) == Status::kOk);
    REQUIRE(tracker.reports().size() == 1);
    CHECK(tracker.reports()[0].misses == miss);
    CHECK_FALSE(tracker.reports()[0].associated);
    // Noise-free constant-rate target: the coasted prediction stays on it.
    CHECK(tracker.reports()[0].x(0) == Approx(target_at(k)(0)).margin(1e-6));
  }
  WHEN("one more frame passes without a detection") {
    REQUIRE(tracker.step(scan_at(k)) == Status::kOk);
    THEN("the track is deleted") {
      CHECK(tracker.reports().empty());
      CHECK(tracker.last_step().deleted == 1);
    }
  }
}

SCENARIO("a coasting track is deleted when its bistatic-range variance passes the limit", "[pcl][tracker]") {
  auto params = kParams;
  params.max_coast_misses = 100;
  params.max_rb_variance_m2 = 400.0;  // 20 m sigma
  auto tracker = make_tracker(params);
  int k = confirm_target(tracker);
  double last_var = 0.0;
  for (; k < 60; ++k) {
    REQUIRE(tracker.step(scan_at(k)) == Status::kOk);
    if (tracker.reports().empty()) break;
    last_var = tracker.reports()[0].P(0, 0);
  }
  THEN("it went just as var(Rb) crossed 400 m^2") {
    CHECK(tracker.reports().empty());
    CHECK(tracker.last_step().deleted == 1);
    CHECK(last_var <= 400.0);
    CHECK(k < 60);
  }
}

SCENARIO("nearest neighbour picks the target among decoys and respects the gate", "[pcl][tracker][nn]") {
  auto tracker = make_tracker();
  int k = confirm_target(tracker);
  const auto z = target_at(k);
  WHEN("the frame holds decoys in and out of the gate before the target") {
    Scan s = scan_at(k);
    add(s, z + kestrel::Vec<double, 2>(400.0, 0.0));   // far out of the gate
    add(s, z + kestrel::Vec<double, 2>(20.0, 1.0));    // in the gate, farther
    add(s, z + kestrel::Vec<double, 2>(0.0, 30.0));    // out of the gate in rate
    add(s, z + kestrel::Vec<double, 2>(2.0, 0.05));    // the target's detection
    add(s, z + kestrel::Vec<double, 2>(-18.0, -1.2));  // in the gate, farther
    REQUIRE(tracker.step(s) == Status::kOk);
    THEN("the target track takes the nearest one") {
      REQUIRE(tracker.reports().size() == 1);
      CHECK(tracker.reports()[0].measurement_index == 3);
      CHECK(tracker.reports()[0].associated);
    }
  }
  WHEN("the only candidate lies outside the confirmed gate") {
    Scan s = scan_at(k);
    add(s, z + kestrel::Vec<double, 2>(90.0, 0.0));
    REQUIRE(tracker.step(s) == Status::kOk);
    THEN("the track coasts and the candidate starts a tentative track instead") {
      REQUIRE(tracker.reports().size() == 1);
      CHECK_FALSE(tracker.reports()[0].associated);
      CHECK(tracker.last_step().associated == 0);
      CHECK(tracker.last_step().seeded == 1);
      CHECK(tracker.tracks().size() == 2);
    }
  }
}

SCENARIO("one candidate feeds at most one track, and two targets keep two tracks", "[pcl][tracker][nn]") {
  auto tracker = make_tracker();
  // Two targets 40 m apart in Rb with the same rate.
  auto second = [](int k) { return kestrel::Vec<double, 2>(target_at(k)(0) + 40.0, -12.0); };
  for (int k = 0; k < 8; ++k) {
    Scan s = scan_at(k);
    add(s, target_at(k));
    add(s, second(k));
    REQUIRE(tracker.step(s) == Status::kOk);
  }
  REQUIRE(tracker.reports().size() == 2);
  CHECK(tracker.reports()[0].measurement_index != tracker.reports()[1].measurement_index);
  WHEN("a frame holds one candidate between them") {
    Scan s = scan_at(8);
    add(s, kestrel::Vec<double, 2>(target_at(8)(0) + 20.0, -12.0));
    REQUIRE(tracker.step(s) == Status::kOk);
    THEN("exactly one track takes it; the other coasts") {
      REQUIRE(tracker.reports().size() == 2);
      CHECK(tracker.last_step().associated == 1);
      CHECK(tracker.reports()[0].associated != tracker.reports()[1].associated);
      CHECK(tracker.last_step().seeded == 0);
    }
  }
  WHEN("a frame holds both detections, listed in the other order") {
    Scan s = scan_at(8);
    add(s, second(8));
    add(s, target_at(8));
    REQUIRE(tracker.step(s) == Status::kOk);
    THEN("each track takes its own") {
      REQUIRE(tracker.reports().size() == 2);
      const auto& a = tracker.reports()[0];
      const auto& b = tracker.reports()[1];
      CHECK(a.associated);
      CHECK(b.associated);
      const auto& first = a.x(0) < b.x(0) ? a : b;
      const auto& other = a.x(0) < b.x(0) ? b : a;
      CHECK(first.measurement_index == 1);
      CHECK(other.measurement_index == 0);
    }
  }
}

SCENARIO("no track starts below 2 Hz, but a confirmed track crosses zero Doppler", "[pcl][tracker][ridge]") {
  GIVEN("a steady zero-Doppler ridge candidate (|fD| = 1 Hz) at a fixed range for 20 frames") {
    auto tracker = make_tracker();
    std::uint32_t refused = 0;
    for (int k = 0; k < 20; ++k) {
      Scan s = scan_at(k);
      add(s, cand(2200.0, k % 2 == 0 ? 1.0 : -1.0));
      add(s, cand(900.0, 0.0));
      REQUIRE(tracker.step(s) == Status::kOk);
      refused += tracker.last_step().refused;
    }
    THEN("nothing starts; each candidate is counted as refused, and no id was used") {
      CHECK(tracker.tracks().size() == 0);
      CHECK(refused == 40);
      Scan s = scan_at(20);
      add(s, target_at(20));
      REQUIRE(tracker.step(s) == Status::kOk);
      REQUIRE(tracker.tracks().size() == 1);
      for (std::size_t i = 0; i < kTracks; ++i) {
        if (tracker.tracks().active(i)) CHECK(tracker.tracks()[i].id == 1);
      }
    }
  }
  GIVEN("a confirmed target whose range rate goes from -6 to +6 m/s at 1 m/s^2") {
    auto tracker = make_tracker();
    int associated_near_zero = 0;
    for (int k = 0; k < 25; ++k) {
      const double t = 0.5 * k;
      const double rate = -6.0 + 1.0 * t;
      Scan s = scan_at(k);
      add(s, kestrel::Vec<double, 2>(1500.0 - 6.0 * t + 0.5 * t * t, rate));
      REQUIRE(tracker.step(s) == Status::kOk);
      if (k >= 5) {
        REQUIRE(tracker.reports().size() == 1);
        CHECK(tracker.reports()[0].associated);
        if (std::abs(rate) < 2.0 * kLambda) ++associated_near_zero;
      }
    }
    THEN("it kept its detections through |fD| < 2 Hz") { CHECK(associated_near_zero >= 3); }
  }
}

SCENARIO("frames of clutter alone confirm no track within N frames", "[pcl][tracker][clutter]") {
  // PCL-002 density: 21 candidates uniform over Rb [0, 3000] m and fD
  // [-125, 125] Hz, plus 3 ridge candidates; 100 independent seeds.
  std::size_t confirmed = 0;
  std::size_t started = 0;
  for (std::uint64_t seed = 1; seed <= 100; ++seed) {
    auto tracker = make_tracker();
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> rb(0.0, 3000.0), fd(-125.0, 125.0), ridge(-0.99, 0.99);
    for (int k = 0; k < kParams.confirm_n; ++k) {
      Scan s = scan_at(k);
      // Each draw in its own statement: the order of a call's arguments is
      // unspecified, so the samples would depend on the compiler.
      for (int j = 0; j < 21; ++j) {
        const double f = fd(rng);
        add(s, cand(rb(rng), f));
      }
      for (int j = 0; j < 3; ++j) {
        const double f = ridge(rng);
        add(s, cand(rb(rng), f));
      }
      REQUIRE(tracker.step(s) == Status::kOk);
      started += tracker.last_step().seeded;
      confirmed += confirmed_count(tracker);
    }
  }
  THEN("no frame of any seed holds a confirmed track, although many tentative ones started") {
    CHECK(confirmed == 0);
    CHECK(started > 100 * 21 * 5);
  }
}

SCENARIO("an associated track reports its innovation, variance and test ratio", "[pcl][tracker][diag]") {
  auto tracker = make_tracker();
  int k = confirm_target(tracker);
  auto probe = tracker;  // predicts the same way, to know S beforehand
  Scan s = scan_at(k);
  const kestrel::Vec<double, 2> z = target_at(k) + kestrel::Vec<double, 2>(6.0, -0.2);
  add(s, z);
  REQUIRE(tracker.step(s) == Status::kOk);
  REQUIRE(tracker.reports().size() == 1);
  const auto& r = tracker.reports()[0];
  REQUIRE(r.associated);
  // Recompute the innovation from a copy of the track predicted by hand.
  auto f = probe.tracks()[0].filter;
  for (std::size_t i = 0; i < kTracks; ++i) {
    if (probe.tracks()[i].id == r.track_id) f = probe.tracks()[i].filter;
  }
  REQUIRE(f.predict(0.5) == Status::kOk);
  const auto in = f.innovation(z);
  CHECK(r.fusion.innovation(0) == Approx(in.nu(0)));
  CHECK(r.fusion.innovation(1) == Approx(in.nu(1)));
  CHECK(r.fusion.innovation_variance(0) == Approx(in.S(0, 0)));
  CHECK(r.fusion.innovation_variance(1) == Approx(in.S(1, 1)));
  CHECK(r.fusion.nis == Approx(in.d2));
  CHECK(r.nis == Approx(in.d2));
  CHECK(r.fusion.fused);
  CHECK(r.fusion.fused_channels == 0b11u);
  CHECK(r.fusion.rejected == 0u);
  // Gate 0.99 for 2 dimensions: chi2 quantile 9.210.
  CHECK(r.test_ratio == Approx(in.d2 / 9.210));
  CHECK(r.test_ratio < 1.0);
}

SCENARIO("measurements outside the PCL box refuse the frame and change nothing", "[pcl][tracker][status]") {
  auto tracker = make_tracker();
  int k = confirm_target(tracker);
  const auto before = tracker.reports()[0].x;
  Scan s = scan_at(k);
  add(s, target_at(k));
  add(s, cand(1200.0, kParams.max_abs_doppler_hz * 1.01));
  CHECK(tracker.step(s) == Status::kOutOfRange);
  CHECK(tracker.reports().empty());
  s.z[1] = cand(1200.0, std::numeric_limits<double>::quiet_NaN());
  CHECK(tracker.step(s) == Status::kNonFinite);
  s.count = 1;
  REQUIRE(tracker.step(s) == Status::kOk);
  REQUIRE(tracker.reports().size() == 1);
  CHECK(tracker.reports()[0].x(0) != before(0));
  CHECK(tracker.reports()[0].associated);
}

SCENARIO("PCL step allocates nothing with full frames of clutter and a target", "[pcl][tracker][alloc]") {
  auto tracker = make_tracker();
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> rb(0.0, 3000.0), fd(-125.0, 125.0);
  static Scan scans[120];
  for (int k = 0; k < 120; ++k) {
    scans[k] = scan_at(k);
    for (std::size_t j = 0; j + 1 < kCandidates; ++j) {
      const double f = fd(rng);  // own statement: argument order is unspecified
      add(scans[k], cand(rb(rng), f));
    }
    add(scans[k], target_at(k) + kestrel::Vec<double, 2>(0.0, 0.0));
  }
  bool all_ok = true;
  std::size_t allocations = 0;
  std::size_t target_reports = 0;
  {
    kestrel::test::AllocationGuard guard;
    for (const auto& s : scans) {
      all_ok = all_ok && tracker.step(s) == Status::kOk;
    }
    allocations = guard.allocations();
  }
  for (const auto& r : tracker.reports()) {
    if (std::abs(r.x(0) - target_at(119)(0)) < 10.0) ++target_reports;
  }
  THEN("no heap allocation, and the target is still tracked at the end") {
    CHECK(all_ok);
    CHECK(allocations == 0);
    CHECK(target_reports >= 1);
  }
}

SCENARIO("the track score starts a single-point track below T_d, confirms it on evidence and deletes a tentative "
         "one T_d below its peak",
         "[pcl][tracker][llr]") {
  using ScoredT = kestrel::PclTracker<kestrel::PclKf<double>, kTracks, kCandidates, kestrel::NearestNeighbour,
                                      kestrel::SequentialLlr>;
  // PCL-002's clutter density and a rare new target: the prior odds of a
  // lone plot, ln(beta_NT / beta_FA) = -4.2, lie below T_d = -3.0.
  const kestrel::SequentialLlrParams llr = kestrel::pcl_score_params(kParams);
  const double td = std::log(llr.missed_track_probability / (1 - llr.false_track_probability));
  REQUIRE(std::log(llr.new_target_density / llr.clutter_density) < td);
  GIVEN("the target detected in every frame") {
    auto tracker = kestrel::make_pcl_tracker<double, kTracks, kCandidates, kestrel::NearestNeighbour,
                                             kestrel::SequentialLlr>(kParams);
    int confirmed_at = -1;
    for (int k = 0; k < 8 && confirmed_at < 0; ++k) {
      ScoredT::Scan s = scan_at(k);
      add(s, target_at(k));
      REQUIRE(tracker.step(s) == Status::kOk);
      if (!tracker.reports().empty()) confirmed_at = k;
    }
    THEN("the track is confirmed within a few frames") {
      CHECK(confirmed_at >= 1);
      CHECK(confirmed_at <= 4);
    }
  }
  GIVEN("one plot, then nothing") {
    auto tracker = kestrel::make_pcl_tracker<double, kTracks, kCandidates, kestrel::NearestNeighbour,
                                             kestrel::SequentialLlr>(kParams);
    ScoredT::Scan s = scan_at(0);
    add(s, target_at(0));
    REQUIRE(tracker.step(s) == Status::kOk);
    REQUIRE(tracker.tracks().size() == 1);
    // Each miss of a tentative track adds ln(1 - P_D P_G), P_G of the
    // tentative gate (0.95).
    const double per_miss = -std::log(1 - llr.detection_probability * 0.95);
    const int expected = static_cast<int>(std::ceil(-td / per_miss));
    int deleted_after = 0;
    for (int miss = 1; miss <= 10 && deleted_after == 0; ++miss) {
      REQUIRE(tracker.step(scan_at(miss)) == Status::kOk);
      if (tracker.tracks().size() == 0) deleted_after = miss;
    }
    THEN("it lives until the misses take it T_d below its peak") { CHECK(deleted_after == expected); }
  }
}
