// SPDX-License-Identifier: Apache-2.0
// Tracker under time and covariance faults: a far-off frame is refused and
// blocks nothing; a sensor whose clock really moved is followed after
// resync_frames consistent frames; int64 frame times at their extremes; a
// dropout longer than max_predict_us restarts the track instead of
// extrapolating it; a filter that reports a P not positive definite, or a
// negative variance, loses its track.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>

#include "kestrel/math/positive_definite.hpp"
#include "kestrel/tracking/radar_tracker.hpp"

namespace {

using kestrel::Status;
using kestrel::TrackStatus;
constexpr std::int64_t kFrameUs = 500000;

template <class S>
kestrel::Vec<S, 2> plot_at(double t_s) {
  const double x = -15000 + 200 * t_s;
  const double y = 8000 + 50 * t_s;
  return kestrel::Vec<S, 2>(static_cast<S>(std::hypot(x, y)), static_cast<S>(std::atan2(y, x)));
}

template <class Tracker>
typename Tracker::Scan plot_scan(std::int64_t t_us, double target_t_s) {
  typename Tracker::Scan s;
  s.t_us = t_us;
  s.count = 1;
  s.z[0] = plot_at<typename Tracker::Scalar>(target_t_s);
  return s;
}

template <class S>
auto confirmed_tracker(int frames = 6) {
  kestrel::RadarTrackerParams p;
  p.qj = 16.0;
  auto tracker = kestrel::make_radar_tracker<S, 4, 8>(p);
  using T = decltype(tracker);
  for (int k = 0; k < frames; ++k) REQUIRE(tracker.step(plot_scan<T>(k * kFrameUs, 0.5 * k)) == Status::kOk);
  REQUIRE(tracker.reports().size() == 1);
  return tracker;
}

template <class Tracker>
bool all_positive_definite(const Tracker& t) {
  for (const auto& r : t.reports()) {
    if (!kestrel::is_positive_definite(r.P)) return false;
  }
  return true;
}

}  // namespace

static_assert(kestrel::elapsed_us(INT64_MAX, INT64_MIN) == INT64_MAX);
static_assert(kestrel::elapsed_us(INT64_MIN, INT64_MAX) == INT64_MIN);
static_assert(kestrel::elapsed_us(5, -3) == 8);

TEMPLATE_TEST_CASE("Scenario: one far-future frame is refused and blocks nothing", "[tracker][time]", double, float) {
  auto tracker = confirmed_tracker<TestType>();
  using T = decltype(tracker);
  const auto snapshot = tracker;
  const std::uint32_t id = tracker.reports()[0].track_id;
  // 6.4 days ahead: a corrupted clock in one CRC-valid frame.
  const std::int64_t future = 6 * kFrameUs + 553'000'000'000LL;
  CHECK(tracker.step(plot_scan<T>(future, 3.0)) == Status::kTimeJumpedForward);
  CHECK(tracker.reports().empty());
  CHECK(tracker.rejected(Status::kTimeJumpedForward) == 1);
  CHECK(tracker.tracks().size() == snapshot.tracks().size());
  THEN("the next frame on the sensor's clock is tracked by the same track") {
    REQUIRE(tracker.step(plot_scan<T>(6 * kFrameUs, 3.0)) == Status::kOk);
    REQUIRE(tracker.reports().size() == 1);
    CHECK(tracker.reports()[0].track_id == id);
    CHECK(tracker.reports()[0].associated);
    CHECK(tracker.resyncs() == 0);
  }
}

TEMPLATE_TEST_CASE("Scenario: a sensor reset (time goes back) is followed after resync_frames frames",
                   "[tracker][time]", double, float) {
  auto tracker = confirmed_tracker<TestType>(10);
  using T = decltype(tracker);
  const std::uint8_t n = tracker.config().resync_frames;
  REQUIRE(n == 3);
  // The sensor restarts its clock at 0 with the target where it now is.
  for (std::uint8_t k = 0; k + 1 < n; ++k) {
    CHECK(tracker.step(plot_scan<T>(k * kFrameUs, 5.0 + 0.5 * k)) == Status::kTimeWentBackwards);
    CHECK(tracker.tracks().size() == 1);
  }
  REQUIRE(tracker.step(plot_scan<T>((n - 1) * kFrameUs, 5.0 + 0.5 * (n - 1))) == Status::kOk);
  CHECK(tracker.last_step().resynced);
  CHECK(tracker.last_step().deleted == 1);
  CHECK(tracker.resyncs() == 1);
  THEN("the new clock is tracked: a new track is confirmed on it") {
    for (int k = n; k < n + 4; ++k) REQUIRE(tracker.step(plot_scan<T>(k * kFrameUs, 5.0 + 0.5 * k)) == Status::kOk);
    REQUIRE(tracker.reports().size() == 1);
    CHECK(tracker.reports()[0].status == TrackStatus::kConfirmed);
    CHECK(all_positive_definite(tracker));
  }
  THEN("frames that are not consistent with each other never resync") {
    auto t2 = confirmed_tracker<TestType>(10);
    const std::int64_t times[] = {0, 10'000'000'000LL, 1'000'000, 20'000'000'000LL, 2'000'000};
    for (const std::int64_t t : times) CHECK(t2.step(plot_scan<T>(t, 5.0)) != Status::kOk);
    CHECK(t2.resyncs() == 0);
    CHECK(t2.tracks().size() == 1);
  }
}

SCENARIO("frame times at the ends of int64 neither overflow nor wedge the tracker", "[tracker][time]") {
  kestrel::RadarTrackerParams p;
  auto tracker = kestrel::make_radar_tracker<double, 4, 8>(p);
  using T = decltype(tracker);
  const std::int64_t lo = std::numeric_limits<std::int64_t>::min();
  const std::int64_t hi = std::numeric_limits<std::int64_t>::max();
  REQUIRE(tracker.step(plot_scan<T>(lo, 0.0)) == Status::kOk);
  REQUIRE(tracker.step(plot_scan<T>(lo + kFrameUs, 0.5)) == Status::kOk);
  REQUIRE(tracker.tracks().size() == 1);
  CHECK(tracker.step(plot_scan<T>(hi, 1.0)) == Status::kTimeJumpedForward);
  CHECK(tracker.step(plot_scan<T>(hi, 1.0)) == Status::kTimeJumpedForward);
  REQUIRE(tracker.step(plot_scan<T>(hi, 1.0)) == Status::kOk);  // third consistent frame
  CHECK(tracker.last_step().resynced);
  CHECK(tracker.tracks().size() == 1);  // the new seed
  CHECK(tracker.step(plot_scan<T>(lo, 1.5)) == Status::kTimeWentBackwards);
}

TEMPLATE_TEST_CASE("Scenario: a dropout longer than max_predict_us restarts the track", "[tracker][time][pd]",
                   double, float) {
  auto tracker = confirmed_tracker<TestType>(12);
  using T = decltype(tracker);
  const std::uint32_t old_id = tracker.reports()[0].track_id;
  // 60 s without any frame, then the target again.
  const std::int64_t t0 = 11 * kFrameUs + 60'000'000;
  REQUIRE(tracker.step(plot_scan<T>(t0, 5.5 + 60.0)) == Status::kOk);
  CHECK(tracker.last_step().stale == 1);
  CHECK(tracker.last_step().deleted == 1);
  CHECK(tracker.last_step().seeded == 1);
  CHECK(tracker.reports().empty());
  for (int k = 1; k < 6; ++k) {
    REQUIRE(tracker.step(plot_scan<T>(t0 + k * kFrameUs, 65.5 + 0.5 * k)) == Status::kOk);
    CHECK(all_positive_definite(tracker));
  }
  REQUIRE(tracker.reports().size() == 1);
  CHECK(tracker.reports()[0].track_id != old_id);
  AND_WHEN("the gap is within max_predict_us, the same track coasts across it") {
    auto t2 = confirmed_tracker<TestType>(12);
    const std::int64_t t1 = 11 * kFrameUs + 5'000'000;
    REQUIRE(t2.step(plot_scan<T>(t1, 5.5 + 5.0)) == Status::kOk);
    CHECK(t2.last_step().stale == 0);
    REQUIRE(t2.reports().size() == 1);
    CHECK(t2.reports()[0].track_id == old_id);
    CHECK(all_positive_definite(t2));
  }
}

TEMPLATE_TEST_CASE("Scenario: a stale track frees its slot before the frame's plots start tracks", "[tracker][time]",
                   double, float) {
  // One slot: the plot after the dropout can only start a track if the
  // stale track is deleted before the unused plots are seeded.
  kestrel::RadarTrackerParams p;
  p.qj = 16.0;
  auto tracker = kestrel::make_radar_tracker<TestType, 1, 8>(p);
  using T = decltype(tracker);
  for (int k = 0; k < 6; ++k) REQUIRE(tracker.step(plot_scan<T>(k * kFrameUs, 0.5 * k)) == Status::kOk);
  REQUIRE(tracker.reports().size() == 1);
  REQUIRE(tracker.step(plot_scan<T>(5 * kFrameUs + 60'000'000, 2.5 + 60.0)) == Status::kOk);
  CHECK(tracker.last_step().stale == 1);
  CHECK(tracker.last_step().deleted == 1);
  CHECK(tracker.last_step().seeded == 1);
  CHECK(tracker.last_step().dropped == 0);
  CHECK(tracker.tracks().size() == 1);
}

namespace {

/// EKF-CA whose predict can be made to report a P that is not positive
/// definite, or whose P can be made to show a negative variance: faults a
/// sound filter never produces, to check how the tracker answers them.
/// Checked at every predict, as a filter without the once-per-frame check
/// is (VerifiesPredictionLater): the tracker then also reads P's variances.
template <class S>
struct FaultyEkf : kestrel::EkfCaCheckedEachPredict<S> {
  using Base = kestrel::EkfCaCheckedEachPredict<S>;
  using Base::Base;
  static inline bool fail_predict = false;
  static inline bool negative_variance = false;
  Status predict(S dt) { return fail_predict ? Status::kNotPositiveDefinite : Base::predict(dt); }
  typename Base::Cov P() const {
    typename Base::Cov P = Base::P();
    if (negative_variance) P(0, 0) = S(-196.75);
    return P;
  }
};

}  // namespace

static_assert(!kestrel::VerifiesPredictionLater<FaultyEkf<double>>);

SCENARIO("a track whose covariance is unhealthy is deleted, never reported", "[tracker][pd]") {
  using S = double;
  using F = FaultyEkf<S>;
  kestrel::RadarTrackerParams p;
  p.qj = 16.0;
  auto tracker = kestrel::make_radar_tracker<S, 4, 8, F>(p);
  using T = decltype(tracker);
  F::fail_predict = false;
  F::negative_variance = false;
  for (int k = 0; k < 6; ++k) REQUIRE(tracker.step(plot_scan<T>(k * kFrameUs, 0.5 * k)) == Status::kOk);
  REQUIRE(tracker.reports().size() == 1);
  WHEN("the filter refuses a predict with kNotPositiveDefinite") {
    F::fail_predict = true;
    REQUIRE(tracker.step(plot_scan<T>(6 * kFrameUs, 3.0)) == Status::kOk);
    F::fail_predict = false;
    THEN("the track is deleted at once and its plot starts a new one") {
      CHECK(tracker.last_step().unhealthy == 1);
      CHECK(tracker.last_step().deleted == 1);
      CHECK(tracker.last_step().seeded == 1);
      CHECK(tracker.reports().empty());
    }
  }
  WHEN("the track's P shows a negative variance") {
    F::negative_variance = true;
    REQUIRE(tracker.step(plot_scan<T>(6 * kFrameUs, 3.0)) == Status::kOk);
    F::negative_variance = false;
    THEN("it is deleted, not reported as confirmed") {
      CHECK(tracker.last_step().unhealthy == 1);
      CHECK(tracker.last_step().deleted == 1);
      CHECK(tracker.reports().empty());
    }
  }
}

namespace {

/// EKF-CA whose process noise can be made indefinite (a negative jerk
/// density), so that the prediction it commits unchecked is really not
/// positive definite: what the tracker's once-per-frame check must find.
template <class S>
struct IndefinitePredictionEkf : kestrel::EkfCa<S> {
  using Base = kestrel::EkfCa<S>;
  using Base::Base;
  static inline bool indefinite = false;
  Status predict_unverified(S dt) {
    if (indefinite) this->motion().qj = S(-1e6);
    return Base::predict_unverified(dt);
  }
};

}  // namespace

static_assert(kestrel::VerifiesPredictionLater<kestrel::EkfCa<double>>);
static_assert(kestrel::VerifiesPredictionLater<kestrel::EkfCa<float>>);

TEMPLATE_TEST_CASE("Scenario: a prediction committed unchecked that is not positive definite deletes its track",
                   "[tracker][pd]", double, float) {
  using S = TestType;
  using F = IndefinitePredictionEkf<S>;
  kestrel::RadarTrackerParams p;
  p.qj = 16.0;
  auto tracker = kestrel::make_radar_tracker<S, 4, 8, F>(p);
  using T = decltype(tracker);
  F::indefinite = false;
  for (int k = 0; k < 6; ++k) REQUIRE(tracker.step(plot_scan<T>(k * kFrameUs, 0.5 * k)) == Status::kOk);
  REQUIRE(tracker.reports().size() == 1);
  REQUIRE(tracker.reports()[0].status == TrackStatus::kConfirmed);

  WHEN("the track takes its plot in that frame") {
    F::indefinite = true;
    REQUIRE(tracker.step(plot_scan<T>(6 * kFrameUs, 3.0)) == Status::kOk);
    F::indefinite = false;
    THEN("the track is deleted and never reported; its plot starts a new one") {
      CHECK(tracker.last_step().unhealthy == 1);
      CHECK(tracker.last_step().deleted == 1);
      CHECK(tracker.last_step().associated == 0);
      CHECK(tracker.last_step().seeded == 1);
      CHECK(tracker.reports().empty());
      CHECK(all_positive_definite(tracker));
    }
  }
  WHEN("the frame has no plot") {
    F::indefinite = true;
    typename T::Scan empty;
    empty.t_us = 6 * kFrameUs;
    empty.count = 0;
    REQUIRE(tracker.step(empty) == Status::kOk);
    F::indefinite = false;
    THEN("the end-of-frame check finds it: the track is deleted and never reported") {
      CHECK(tracker.last_step().unhealthy == 1);
      CHECK(tracker.last_step().deleted == 1);
      CHECK(tracker.last_step().failure == Status::kNotPositiveDefinite);
      CHECK(tracker.reports().empty());
      CHECK(tracker.tracks().size() == 0);
    }
  }
  WHEN("the prediction stays sound") {
    typename T::Scan empty;
    empty.t_us = 6 * kFrameUs;
    empty.count = 0;
    REQUIRE(tracker.step(empty) == Status::kOk);
    THEN("a coasting track is checked and kept") {
      CHECK(tracker.last_step().unhealthy == 0);
      CHECK(tracker.last_step().deleted == 0);
      REQUIRE(tracker.reports().size() == 1);
      CHECK(all_positive_definite(tracker));
    }
  }
}

static_assert(!kestrel::VerifiesPredictionLater<kestrel::EkfCaCheckedEachPredict<float>>);

TEMPLATE_TEST_CASE("Scenario: checking P once per frame or at every predict gives the same tracks, bit for bit",
                   "[tracker][pd]", double, float) {
  using S = TestType;
  kestrel::RadarTrackerParams p;
  p.qj = 16.0;
  auto once = kestrel::make_radar_tracker<S, 4, 8>(p);
  auto each = kestrel::make_radar_tracker<S, 4, 8, kestrel::EkfCaCheckedEachPredict<S>>(p);
  using T = decltype(once);
  std::size_t reported = 0;
  for (int k = 0; k < 60; ++k) {
    auto scan = plot_scan<T>(k * kFrameUs, 0.5 * k);
    if (k % 4 == 3) scan.count = 0;  // coasting frames: P checked at the end of the frame
    typename decltype(each)::Scan scan_each;
    scan_each.t_us = scan.t_us;
    scan_each.count = scan.count;
    scan_each.z[0] = scan.z[0];
    REQUIRE(once.step(scan) == Status::kOk);
    REQUIRE(each.step(scan_each) == Status::kOk);
    REQUIRE(once.reports().size() == each.reports().size());
    for (std::size_t i = 0; i < once.reports().size(); ++i) {
      CHECK(once.reports()[i].track_id == each.reports()[i].track_id);
      CHECK(once.reports()[i].nis == each.reports()[i].nis);
      CHECK(once.reports()[i].x == each.reports()[i].x);
      CHECK(once.reports()[i].P == each.reports()[i].P);
    }
    reported += once.reports().size();
  }
  CHECK(reported > 50);
}
