// SPDX-License-Identifier: Apache-2.0
// Tracker step(): initiation, confirmation, coasting and deletion, gating,
// bad-frame statuses that leave the table untouched, zero allocations.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "fuzz/same_tracks.hpp"
#include "kestrel/tracking/radar_tracker.hpp"
#include "support/alloc_guard.hpp"

namespace {

using kestrel::Status;
using kestrel::TrackStatus;
constexpr double kPi = 3.14159265358979323846;

template <class S>
using TestTracker = kestrel::RadarTracker<kestrel::EkfCa<S>, 4, 8>;

template <class S>
TestTracker<S> make_tracker() {
  kestrel::RadarTrackerParams p;
  p.qj = 16.0;
  return kestrel::make_radar_tracker<S, 4, 8>(p);
}

/// Straight-line target from (-15000, 8000) at (200, 50) m/s; plot at time t.
template <class S>
kestrel::Vec<S, 2> plot_at(double t_s, double dx = 0, double dy = 0) {
  const double x = -15000 + 200 * t_s + dx;
  const double y = 8000 + 50 * t_s + dy;
  return kestrel::Vec<S, 2>(static_cast<S>(std::hypot(x, y)), static_cast<S>(std::atan2(y, x)));
}

template <class Tracker>
typename Tracker::Scan scan_at(std::int64_t t_us) {
  typename Tracker::Scan s;
  s.t_us = t_us;
  s.count = 0;
  return s;
}

}  // namespace

TEMPLATE_TEST_CASE("Scenario: a single target is initiated by two points, confirmed and held", "[tracker]",
                   double, float) {
  using S = TestType;
  auto tracker = make_tracker<S>();
  using T = decltype(tracker);
  for (int k = 0; k < 40; ++k) {
    auto scan = scan_at<T>(k * 500000LL);
    scan.z[0] = plot_at<S>(0.5 * k);
    scan.count = 1;
    REQUIRE(tracker.step(scan) == Status::kOk);
    if (k == 0) {
      // Frame 0: one seed, nothing reported yet.
      CHECK(tracker.last_step().seeded == 1);
      CHECK(tracker.reports().empty());
    } else {
      // From frame 1 (two-point initiation with 2-of-3) one confirmed track.
      REQUIRE(tracker.reports().size() == 1);
      const auto& r = tracker.reports()[0];
      CHECK(r.track_id == 1);
      CHECK(r.status == TrackStatus::kConfirmed);
      CHECK(r.associated);
      const double t = 0.5 * k;
      // Noise-free plots of a constant-velocity target: the estimate is the
      // truth up to float round-off of 20 km ranges (float: 1e-3 relative).
      CHECK(static_cast<double>(r.x(0)) == Approx(-15000 + 200 * t).margin(2.0));
      CHECK(static_cast<double>(r.x(3)) == Approx(8000 + 50 * t).margin(2.0));
      CHECK(static_cast<double>(r.x(1)) == Approx(200).margin(1.0));
      CHECK(static_cast<double>(r.x(4)) == Approx(50).margin(1.0));
    }
  }
}

SCENARIO("a confirmed track coasts through misses and is deleted after max_coast_misses", "[tracker]") {
  auto tracker = make_tracker<double>();
  using T = decltype(tracker);
  std::int64_t t = 0;
  for (int k = 0; k < 5; ++k, t += 500000) {
    auto scan = scan_at<T>(t);
    scan.z[0] = plot_at<double>(t * 1e-6);
    scan.count = 1;
    REQUIRE(tracker.step(scan) == Status::kOk);
  }
  REQUIRE(tracker.reports().size() == 1);
  const std::uint16_t max_misses = tracker.config().max_coast_misses;
  for (int miss = 1; miss <= max_misses; ++miss, t += 500000) {
    REQUIRE(tracker.step(scan_at<T>(t)) == Status::kOk);
    REQUIRE(tracker.reports().size() == 1);
    CHECK(tracker.reports()[0].misses == miss);
    CHECK_FALSE(tracker.reports()[0].associated);
  }
  WHEN("one more frame passes without a plot") {
    REQUIRE(tracker.step(scan_at<T>(t)) == Status::kOk);
    THEN("the track is deleted") {
      CHECK(tracker.reports().empty());
      CHECK(tracker.last_step().deleted == 1);
      CHECK(tracker.tracks().size() == 0);
    }
  }
}

SCENARIO("the gate keeps a far plot away from a confirmed track", "[tracker][gate]") {
  auto tracker = make_tracker<double>();
  using T = decltype(tracker);
  for (int k = 0; k < 10; ++k) {
    auto scan = scan_at<T>(k * 500000LL);
    scan.z[0] = plot_at<double>(0.5 * k);
    scan.count = 1;
    REQUIRE(tracker.step(scan) == Status::kOk);
  }
  const auto x_before = tracker.reports()[0].x;
  WHEN("the next frame holds only a plot 2 km off the prediction") {
    auto scan = scan_at<T>(10 * 500000LL);
    scan.z[0] = plot_at<double>(5.0, 2000, 0);
    scan.count = 1;
    REQUIRE(tracker.step(scan) == Status::kOk);
    THEN("the track coasts (not updated) and the plot starts a seed instead") {
      REQUIRE(tracker.reports().size() == 1);
      CHECK_FALSE(tracker.reports()[0].associated);
      CHECK(tracker.last_step().associated == 0);
      CHECK(tracker.last_step().seeded == 1);
      // Coasted: x is the pure prediction of the previous estimate.
      CHECK(tracker.reports()[0].x(0) == Approx(x_before(0) + 0.5 * x_before(1) + 0.125 * x_before(2)));
    }
  }
  WHEN("the frame holds the true plot and a decoy 300 m away") {
    auto scan = scan_at<T>(10 * 500000LL);
    scan.z[0] = plot_at<double>(5.0, 300, 0);
    scan.z[1] = plot_at<double>(5.0);
    scan.count = 2;
    REQUIRE(tracker.step(scan) == Status::kOk);
    THEN("nearest neighbour picks the true plot") {
      REQUIRE(tracker.reports().size() == 1);
      CHECK(tracker.reports()[0].measurement_index == 1);
    }
  }
}

SCENARIO("bad frames get their status and leave the track table untouched", "[tracker][status]") {
  auto tracker = make_tracker<double>();
  using T = decltype(tracker);
  for (int k = 0; k < 6; ++k) {
    auto scan = scan_at<T>(k * 500000LL);
    scan.z[0] = plot_at<double>(0.5 * k);
    scan.count = 1;
    REQUIRE(tracker.step(scan) == Status::kOk);
  }
  const auto snapshot = tracker;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto good = scan_at<T>(6 * 500000LL);
  good.z[0] = plot_at<double>(3.0);
  good.count = 1;

  struct Case {
    const char* name;
    T::Scan scan;
    Status expected;
  };
  Case cases[] = {{"count over capacity", good, Status::kMalformedFrame},
                  {"NaN range", good, Status::kNonFinite},
                  {"Inf bearing", good, Status::kNonFinite},
                  {"negative range", good, Status::kOutOfRange},
                  {"bearing beyond pi", good, Status::kOutOfRange},
                  {"time went backwards", good, Status::kTimeWentBackwards}};
  cases[0].scan.count = T::Scan::kMaxMeasurements + 1;
  cases[1].scan.z[0](0) = nan;
  cases[2].scan.z[0](1) = std::numeric_limits<double>::infinity();
  cases[3].scan.z[0](0) = -5.0;
  cases[4].scan.z[0](1) = 4.0;
  cases[5].scan.t_us = 2 * 500000LL;

  for (const auto& c : cases) {
    GIVEN("a frame with " << c.name) {
      THEN("step returns its status, reports nothing and changes nothing") {
        CHECK(tracker.step(c.scan) == c.expected);
        CHECK(tracker.reports().empty());
        CHECK(kestrel::test::same_tracks(tracker, snapshot));
        CHECK(tracker.rejected(c.expected) == 1);
        AND_THEN("the next good frame is tracked as if the bad one never came") {
          auto ref = snapshot;
          REQUIRE(ref.step(good) == Status::kOk);
          REQUIRE(tracker.step(good) == Status::kOk);
          REQUIRE(tracker.reports().size() == 1);
          CHECK(tracker.reports()[0].x == ref.reports()[0].x);
          CHECK(tracker.reports()[0].associated);
        }
      }
    }
  }
}

SCENARIO("step allocates nothing, with clutter and table overflow", "[tracker][alloc]") {
  auto tracker = make_tracker<double>();
  using T = decltype(tracker);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> range(1000, 30000), bearing(-kPi, kPi);
  T::Scan scans[60];
  for (int k = 0; k < 60; ++k) {
    scans[k] = scan_at<T>(k * 500000LL);
    scans[k].z[0] = plot_at<double>(0.5 * k);
    for (std::size_t j = 1; j < T::Scan::kMaxMeasurements; ++j) {
      const double b = bearing(rng);  // own statement: argument order is unspecified
      scans[k].z[j] = kestrel::Vec<double, 2>(range(rng), b);
    }
    scans[k].count = T::Scan::kMaxMeasurements;
  }
  // Catch's own bookkeeping allocates, so only step() runs under the guard.
  std::uint32_t dropped = 0;
  std::size_t allocations = 0;
  bool all_ok = true;
  {
    kestrel::test::AllocationGuard guard;
    for (const auto& s : scans) {
      all_ok = all_ok && tracker.step(s) == Status::kOk;
      dropped += tracker.last_step().dropped;
    }
    allocations = guard.allocations();
  }
  THEN("no heap allocation happened and the full table dropped plots with a count") {
    CHECK(all_ok);
    CHECK(allocations == 0);
    CHECK(dropped > 0);
    CHECK(tracker.tracks().size() <= T::Table::kMaxTracks);
  }
}

SCENARIO("two separated targets get two tracks", "[tracker]") {
  auto tracker = make_tracker<double>();
  using T = decltype(tracker);
  for (int k = 0; k < 12; ++k) {
    auto scan = scan_at<T>(k * 500000LL);
    scan.z[0] = plot_at<double>(0.5 * k);
    scan.z[1] = plot_at<double>(0.5 * k, 3000, -2000);
    scan.count = 2;
    REQUIRE(tracker.step(scan) == Status::kOk);
  }
  REQUIRE(tracker.reports().size() == 2);
  CHECK(tracker.reports()[0].track_id != tracker.reports()[1].track_id);
  CHECK(tracker.reports()[0].measurement_index != tracker.reports()[1].measurement_index);
  CHECK(tracker.reports()[0].associated);
  CHECK(tracker.reports()[1].associated);
}

SCENARIO("an explicit confirmed-gate threshold replaces the chi-square quantile", "[tracker][gate]") {
  kestrel::RadarTrackerParams p;
  p.qj = 16.0;
  auto config = kestrel::tracker_config_of<double>(p);
  config.gate_confirmed_threshold = 1e12;  // effectively ungated
  kestrel::CaMotion<double> motion;
  motion.qj = p.qj;
  kestrel::CaPolarRadar<double> radar;
  radar.sigma_range_m = p.sigma_range_m;
  radar.sigma_bearing_rad = p.sigma_bearing_rad;
  TestTracker<double> tracker(kestrel::EkfCa<double>(motion, radar),
                              {radar, p.max_speed_mps, p.init_accel_sigma_mps2}, config);
  using T = decltype(tracker);
  for (int k = 0; k < 10; ++k) {
    auto scan = scan_at<T>(k * 500000LL);
    scan.z[0] = plot_at<double>(0.5 * k);
    scan.count = 1;
    REQUIRE(tracker.step(scan) == Status::kOk);
  }
  WHEN("a plot 2 km off the prediction arrives") {
    auto scan = scan_at<T>(10 * 500000LL);
    scan.z[0] = plot_at<double>(5.0, 2000, 0);
    scan.count = 1;
    REQUIRE(tracker.step(scan) == Status::kOk);
    THEN("the confirmed track takes it (the default gate refuses it, see above)") {
      REQUIRE(tracker.reports().size() == 1);
      CHECK(tracker.reports()[0].associated);
      CHECK(tracker.last_step().seeded == 0);
    }
  }
}
