// SPDX-License-Identifier: Apache-2.0
// TwoPointHypothesesInitiator: a range outlier among a target's first plots
// no longer leaves it without a confirmed track at the third frame; without
// its rules it is TwoPointInitiator, report for report.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <algorithm>
#include <limits>

#include "kestrel/tracking/radar_tracker.hpp"

namespace {

using kestrel::Status;
using kestrel::TrackStatus;

template <class S>
using Plain = kestrel::Tracker<kestrel::EkfCa<S>,
                               kestrel::TwoPointInitiator<kestrel::CaMotion<S>, kestrel::CaPolarRadar<S>>, 8, 8>;
template <class S>
using Hypotheses =
    kestrel::Tracker<kestrel::EkfCa<S>,
                     kestrel::TwoPointHypothesesInitiator<kestrel::CaMotion<S>, kestrel::CaPolarRadar<S>>, 8, 8>;

/// The board's radar tracker settings (chi-square gate on confirmed tracks,
/// 2-of-3, 1000 m/s) with `extra` and `from_pairs` when Tracker keeps them.
template <class Tracker>
Tracker make(std::uint8_t extra = 1, bool from_pairs = true) {
  using S = typename Tracker::Scalar;
  kestrel::RadarTrackerParams p;
  p.qj = 16.0;
  const auto s = kestrel::radar_tracker_config<S>(p);
  kestrel::CaMotion<S> motion;
  motion.qj = s.qj;
  kestrel::CaPolarRadar<S> radar;
  radar.sigma_range_m = s.sigma_range_m;
  radar.sigma_bearing_rad = s.sigma_bearing_rad;
  typename Tracker::InitiatorT init{};
  init.measurement = radar;
  init.max_speed_mps = s.max_speed_mps;
  init.accel_sigma_mps2 = s.init_accel_sigma_mps2;
  if constexpr (requires { Tracker::InitiatorT::kKeepsHypotheses; }) {
    init.seed_extra_frames = extra;
    init.seed_from_pairs = from_pairs;
  }
  return Tracker(kestrel::EkfCa<S>(motion, radar), init, kestrel::tracker_config_of<S>(p, s));
}

/// Straight-line target from (-15000, 8000) at (200, 50) m/s, seen at
/// frame k (0.5 s apart), its range off by range_offset_m.
double truth_x(int k) { return -15000.0 + 200.0 * 0.5 * k; }
double truth_y(int k) { return 8000.0 + 50.0 * 0.5 * k; }

template <class Tracker>
typename Tracker::Scan frame(int k, double range_offset_m = 0.0) {
  using S = typename Tracker::Scalar;
  typename Tracker::Scan scan;
  scan.t_us = k * 500000LL;
  scan.count = 1;
  scan.z[0] = kestrel::Vec<S, 2>(static_cast<S>(std::hypot(truth_x(k), truth_y(k)) + range_offset_m),
                                 static_cast<S>(std::atan2(truth_y(k), truth_x(k))));
  return scan;
}

/// Distance of the nearest confirmed report from the truth at frame k
/// (infinity without one).
template <class Tracker>
double nearest_confirmed_m(const Tracker& tracker, int k) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& r : tracker.reports()) {
    if (r.status != TrackStatus::kConfirmed) continue;
    const double dx = static_cast<double>(r.x(0)) - truth_x(k);
    const double dy = static_cast<double>(r.x(3)) - truth_y(k);
    best = std::min(best, std::hypot(dx, dy));
  }
  return best;
}

/// Runs frames 0..3 with the given range offsets: the larger of the
/// nearest confirmed report's distances at frames 2 and 3 (a track started
/// from an outlier is off by then, even if its position was a good plot).
template <class Tracker>
double worst_at_frames_2_3(Tracker tracker, const double (&offsets)[4]) {
  double d = 0.0;
  for (int k = 0; k < 4; ++k) {
    REQUIRE(tracker.step(frame<Tracker>(k, offsets[k])) == Status::kOk);
    if (k >= 2) d = std::max(d, nearest_confirmed_m(tracker, k));
  }
  return d;
}

}  // namespace

TEMPLATE_TEST_CASE("a range outlier among the first plots: the second hypotheses confirm the target at frame 2",
                   "[tracker][initiation]", double, float) {
  using S = TestType;
  // Noise-free plots put a track from two good plots within metres of the
  // truth. The target closes at about 153 m/s (76 m a frame), and pairs
  // faster than 1000 m/s are refused.
  SECTION("the second plot 480 m off pairs with the first (about 810 m/s) but not with the third") {
    const double offsets[4] = {0.0, 480.0, 0.0, 0.0};
    CHECK(worst_at_frames_2_3(make<Plain<S>>(), offsets) > 300.0);
    CHECK(worst_at_frames_2_3(make<Hypotheses<S>>(), offsets) < 2.0);
    // The first plot's seed, kept after its pair, is what starts the target.
    CHECK(worst_at_frames_2_3(make<Hypotheses<S>>(0, true), offsets) > 300.0);
  }
  SECTION("the first plot 400 m off pairs with the second (about 950 m/s)") {
    const double offsets[4] = {400.0, 0.0, 0.0, 0.0};
    CHECK(worst_at_frames_2_3(make<Plain<S>>(), offsets) > 300.0);
    CHECK(worst_at_frames_2_3(make<Hypotheses<S>>(), offsets) < 2.0);
    // The second plot's own seed is what starts the target; the kept seed
    // pairs the outlier again, over two frames.
    CHECK(worst_at_frames_2_3(make<Hypotheses<S>>(1, false), offsets) > 50.0);
  }
  SECTION("the second plot 700 m off is too fast to pair (about 1250 m/s)") {
    const double offsets[4] = {0.0, 700.0, 0.0, 0.0};
    CHECK(worst_at_frames_2_3(make<Plain<S>>(), offsets) > 300.0);
    // The first plot's seed waits a frame and pairs with the third.
    CHECK(worst_at_frames_2_3(make<Hypotheses<S>>(), offsets) < 2.0);
  }
}

TEMPLATE_TEST_CASE("second hypotheses on a clean target: one track, the plain tracker's reports, seeds expire",
                   "[tracker][initiation]", double, float) {
  using S = TestType;
  auto plain = make<Plain<S>>();
  auto hyp = make<Hypotheses<S>>();
  for (int k = 0; k < 12; ++k) {
    REQUIRE(plain.step(frame<Plain<S>>(k)) == Status::kOk);
    REQUIRE(hyp.step(frame<Hypotheses<S>>(k)) == Status::kOk);
    REQUIRE(plain.reports().size() == hyp.reports().size());
    for (std::size_t i = 0; i < plain.reports().size(); ++i) {
      const auto& a = plain.reports()[i];
      const auto& b = hyp.reports()[i];
      CHECK(a.track_id == b.track_id);
      CHECK(std::memcmp(a.x.data(), b.x.data(), sizeof(S) * a.x.size()) == 0);
      CHECK(std::memcmp(a.P.data(), b.P.data(), sizeof(S) * a.P.size()) == 0);
    }
    if (k >= 1) CHECK(hyp.reports().size() == 1);
    // Frame 1 keeps the first seed's copy and seeds the pairing plot; in
    // frame 2 the track takes the only plot, so neither seed meets a plot
    // to pair with, and both go.
    if (k == 1) CHECK(hyp.tracks().size() == 3);
    if (k >= 2) CHECK(hyp.tracks().size() == 1);
  }
  CHECK(plain.tracks().size() == 1);
}

TEMPLATE_TEST_CASE("a TwoPointHypothesesInitiator with its rules off is TwoPointInitiator, report for report",
                   "[tracker][initiation]", double, float) {
  using S = TestType;
  auto plain = make<Plain<S>>();
  auto hyp = make<Hypotheses<S>>(0, false);
  const double offsets[8] = {0.0, 400.0, 0.0, 0.0, 650.0, 0.0, 0.0, -500.0};
  for (int k = 0; k < 24; ++k) {
    const double off = k < 8 ? offsets[k] : 0.0;
    REQUIRE(plain.step(frame<Plain<S>>(k, off)) == Status::kOk);
    REQUIRE(hyp.step(frame<Hypotheses<S>>(k, off)) == Status::kOk);
    REQUIRE(plain.tracks().size() == hyp.tracks().size());
    REQUIRE(plain.reports().size() == hyp.reports().size());
    for (std::size_t i = 0; i < plain.reports().size(); ++i) {
      CHECK(plain.reports()[i].track_id == hyp.reports()[i].track_id);
      CHECK(std::memcmp(plain.reports()[i].x.data(), hyp.reports()[i].x.data(), sizeof(S) * 6) == 0);
    }
  }
}

TEST_CASE("a seed to keep with no free slot is counted as dropped", "[tracker][initiation]") {
  using T = kestrel::Tracker<
      kestrel::EkfCa<double>,
      kestrel::TwoPointHypothesesInitiator<kestrel::CaMotion<double>, kestrel::CaPolarRadar<double>>, 1, 8>;
  auto tracker = make<T>();
  REQUIRE(tracker.step(frame<T>(0)) == Status::kOk);
  REQUIRE(tracker.step(frame<T>(1)) == Status::kOk);
  // The pair took the only slot: neither the seed's copy nor the pairing
  // plot's seed has one.
  CHECK(tracker.last_step().initiated == 1);
  CHECK(tracker.last_step().dropped == 2);
  CHECK(tracker.last_step().seeded == 0);
  REQUIRE(tracker.reports().size() == 1);
  CHECK(tracker.reports()[0].status == TrackStatus::kConfirmed);
}

TEMPLATE_TEST_CASE("an outlier of a held target leaves a seed that goes once the track takes the next plot",
                   "[tracker][initiation]", double, float) {
  using S = TestType;
  auto hyp = make<Hypotheses<S>>();
  for (int k = 0; k < 14; ++k) {
    // Frames 10 and 12: the plot 600 m off in range, outside the
    // confirmed track's gate. Kept to frame 12, frame 10's seed would pair
    // with it (600 m in 1 s) into a confirmed false track.
    const double off = (k == 10 || k == 12) ? 600.0 : 0.0;
    REQUIRE(hyp.step(frame<Hypotheses<S>>(k, off)) == Status::kOk);
    if (k == 10 || k == 12) CHECK(hyp.tracks().size() == 2);  // the track and the outlier's seed
    if (k == 11 || k == 13) CHECK(hyp.tracks().size() == 1);  // the track took the plot: the seed met none
    if (k >= 1) {
      REQUIRE(hyp.reports().size() == 1);
      CHECK(hyp.reports()[0].track_id == 1);
    }
  }
}
