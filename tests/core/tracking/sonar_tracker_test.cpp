// SPDX-License-Identifier: Apache-2.0
// Sonar tracker step() (docs/scenarios.md, UW-003): initialisation by
// multilateration, convergence to the truth with c fixed and no noise, the
// per-channel gate dropping an injected outlier while keeping the good
// arrivals, predict-only and re-acquisition (after empty frames, and after
// frames that fused at most half their arrivals), bad-frame statuses that leave
// the tracker untouched, zero allocations per step; the HAL sonar adapter.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>

#include "kestrel/hal/frame.hpp"
#include "kestrel/hal/sonar_adapter.hpp"
#include "kestrel/tracking/sonar_tracker.hpp"
#include "support/alloc_guard.hpp"

namespace {

using kestrel::ArrivalPath;
using kestrel::ChannelMask;
using kestrel::Status;
using Tracker = kestrel::SonarTracker<double, 4>;
using Scan = Tracker::Scan;
using L = Tracker::Layout;

constexpr double kBeacons[4][3] = {{0, 0, 0}, {2000, 0, 0}, {0, 2000, 0}, {2000, 2000, 0}};
constexpr double kSeabed = 150;

/// Straight-line truth from UW-003's start: (500, 800, 60) m at (1.2, 1.0, -0.2) m/s.
Eigen::Vector3d truth_at(double t_s) {
  return Eigen::Vector3d(500 + 1.2 * t_s, 800 + 1.0 * t_s, 60 - 0.2 * t_s);
}

double travel_time(const Eigen::Vector3d& p, int beacon, ArrivalPath path, double c) {
  const double z = path == ArrivalPath::kDirect ? p(2) : 2 * kSeabed - p(2);
  const Eigen::Vector3d src(p(0), p(1), z);
  const Eigen::Vector3d b(kBeacons[beacon][0], kBeacons[beacon][1], kBeacons[beacon][2]);
  return (src - b).norm() / c;
}

/// A full frame (4 beacons x 2 paths) at step k (1 s apart), optional noise,
/// optionally with the target displaced by `jump_m`.
Scan frame_at(int k, double c = 1500, std::mt19937_64* rng = nullptr, double sigma_s = 0,
              const Eigen::Vector3d& jump_m = Eigen::Vector3d::Zero()) {
  Scan s;
  s.t_us = static_cast<std::int64_t>(k) * 1000000;
  s.count = 0;
  std::normal_distribution<double> noise(0.0, 1.0);
  for (int b = 0; b < 4; ++b) {
    for (const ArrivalPath path : {ArrivalPath::kDirect, ArrivalPath::kReflected}) {
      auto& a = s.arrivals[s.count++];
      a.beacon = static_cast<std::uint8_t>(b);
      a.path = path;
      a.toa_s = travel_time(truth_at(k) + jump_m, b, path, c) + (rng != nullptr ? sigma_s * noise(*rng) : 0.0);
    }
  }
  return s;
}

kestrel::SonarTrackerParams sonar_params() { return kestrel::SonarTrackerParams{}; }

/// Index of an arrival in frame_at()'s order.
constexpr std::size_t arrival_index(int beacon, ArrivalPath path) {
  return static_cast<std::size_t>(2 * beacon + static_cast<int>(path));
}

bool same_state(const Tracker& a, const Tracker& b) {
  return a.initialised() == b.initialised() && a.filter().x() == b.filter().x() && a.filter().P() == b.filter().P() &&
         a.counters().frames_ok == b.counters().frames_ok;
}

}  // namespace

SCENARIO("with c fixed and no noise the filter converges to the truth", "[sonar][tracker]") {
  GIVEN("noise-free frames of a constant-velocity target with c = 1500 m/s, and a filter told c barely moves") {
    auto p = sonar_params();
    p.sound_speed_sigma_mps_per_sqrt_s = 1e-4;
    p.accel_sigma_mps2 = 1e-3;
    Tracker tr = kestrel::make_sonar_tracker<double, 4>(p);
    WHEN("it runs 50 frames") {
      double first_error = 0;
      for (int k = 0; k < 50; ++k) {
        REQUIRE(tr.step(frame_at(k)) == Status::kOk);
        if (k == 0) {
          CHECK(tr.last_step().initialised);
          CHECK(tr.last_step().fused == 8);
          first_error = (tr.filter().x().head<3>() - truth_at(0)).norm();
        } else {
          CHECK_FALSE(tr.last_step().initialised);
          CHECK(tr.last_step().gated_out == 0);
        }
      }
      const auto& x = tr.filter().x();
      THEN("position, velocity and sound speed end at the truth") {
        // The fix of a noise-free frame is already within millimetres; the
        // filter must keep it there and learn the velocity from the
        // sequence. Tolerances: 5 cm, 5 mm/s, 0.05 m/s (the R of 3 ms lets
        // the estimate settle only as fast as the information accumulates).
        CHECK(first_error < 0.05);
        CHECK((x.head<3>() - truth_at(49)).norm() < 0.05);
        CHECK((x.segment<3>(L::kVx) - Eigen::Vector3d(1.2, 1.0, -0.2)).norm() < 5e-3);
        CHECK(std::abs(x(L::kC) - 1500) < 0.05);
        CHECK(tr.counters().frames_ok == 50);
        CHECK(tr.counters().initialisations == 1);
      }
    }
  }
  GIVEN("the same with 3 ms TOA noise and c = 1501.5 m/s (seeded)") {
    Tracker tr = kestrel::make_sonar_tracker<double, 4>(sonar_params());
    std::mt19937_64 rng(3);
    double sum_e2 = 0;
    for (int k = 0; k < 50; ++k) {
      REQUIRE(tr.step(frame_at(k, 1501.5, &rng, 3e-3)) == Status::kOk);
      if (k >= 1) sum_e2 += (tr.filter().x().head<3>() - truth_at(k)).squaredNorm();
    }
    THEN("the track stays within the UW-003 error scale and c is learnt") {
      // UW-003 scale: 3D RMSE about 6 m over 200 runs; one seeded run of a
      // straight track stays well inside 15 m, and c inside 1 m/s.
      CHECK(std::sqrt(sum_e2 / 49) < 15.0);
      CHECK(std::abs(tr.filter().x()(L::kC) - 1501.5) < 1.0);
    }
  }
}

SCENARIO("the per-channel gate drops an injected outlier and keeps good arrivals", "[sonar][tracker][gate]") {
  GIVEN("a tracker that has followed 10 noise-free frames") {
    Tracker tr = kestrel::make_sonar_tracker<double, 4>(sonar_params());
    for (int k = 0; k < 10; ++k) REQUIRE(tr.step(frame_at(k)) == Status::kOk);
    WHEN("frame 10 has beacon 3's reflected arrival 25 ms late") {
      Scan s = frame_at(10);
      s.arrivals[arrival_index(3, ArrivalPath::kReflected)].toa_s += 25e-3;
      REQUIRE(tr.step(s) == Status::kOk);
      const int bad = Tracker::Toa::channel(3, ArrivalPath::kReflected);
      THEN("that channel alone is gated out and the seven others are fused") {
        CHECK(tr.last_step().gated_mask == (ChannelMask{1} << bad));
        CHECK(tr.last_step().gated_out == 1);
        CHECK(tr.last_step().fused == 7);
        CHECK(tr.counters().gated_out == 1);
        CHECK(tr.filter().diagnostics().test_ratio(bad) > 1.0);
        CHECK(tr.reports().size() == 1);
        CHECK(tr.reports()[0].fusion.rejected == (ChannelMask{1} << bad));
        CHECK(tr.reports()[0].fusion.fused_channels == (tr.last_step().present & ~(ChannelMask{1} << bad)));
        CHECK(tr.reports()[0].associated);
      }
      THEN("the estimate is exactly that of a twin fed the frame without the outlier") {
        // With the gate-truncation covariance off the gated channel is simply
        // removed; with it (the default) x is the same and P gains the term
        // of the next THEN.
        auto p = sonar_params();
        p.gate_truncation_covariance = false;
        Tracker plain = kestrel::make_sonar_tracker<double, 4>(p);
        Tracker twin = kestrel::make_sonar_tracker<double, 4>(p);
        for (int k = 0; k < 10; ++k) {
          REQUIRE(plain.step(frame_at(k)) == Status::kOk);
          REQUIRE(twin.step(frame_at(k)) == Status::kOk);
        }
        Scan s10 = frame_at(10);
        s10.arrivals[arrival_index(3, ArrivalPath::kReflected)].toa_s += 25e-3;
        REQUIRE(plain.step(s10) == Status::kOk);
        Scan clean = frame_at(10);
        clean.arrivals[arrival_index(3, ArrivalPath::kReflected)] = clean.arrivals[clean.count - 1];
        clean.count -= 1;  // beacon 3 reflected is the last arrival: drop it
        REQUIRE(twin.step(clean) == Status::kOk);
        REQUIRE(twin.last_step().fused == 7);
        // Removed, not zeroed: same arithmetic up to the padding of S (1e-12).
        CHECK((plain.filter().x() - twin.filter().x()).cwiseAbs().maxCoeff() < 1e-9);
        CHECK((plain.filter().P() - twin.filter().P()).cwiseAbs().maxCoeff() < 1e-9);
        CHECK((tr.filter().x() - twin.filter().x()).cwiseAbs().maxCoeff() < 1e-9);
      }
      THEN("P gains the spread of a good arrival beyond the gate along that channel's direction") {
        // Without outliers so far (1 gated of 88 arrivals) a gated arrival is
        // taken as good: weight 1, excess E[u^2 | |u| > 2] - 1 = 2 k phi(k) / erfc(k / sqrt 2).
        auto p = sonar_params();
        p.gate_truncation_covariance = false;
        Tracker plain = kestrel::make_sonar_tracker<double, 4>(p);
        Tracker dflt = kestrel::make_sonar_tracker<double, 4>(sonar_params());
        for (int k = 0; k < 10; ++k) {
          REQUIRE(plain.step(frame_at(k)) == Status::kOk);
          REQUIRE(dflt.step(frame_at(k)) == Status::kOk);
        }
        CHECK(plain.filter().P() == dflt.filter().P());  // nothing gated before frame 10: identical
        const Tracker::State x_pred = plain.filter().motion().propagate(plain.filter().x(), 1.0);
        Scan s10 = frame_at(10);
        s10.arrivals[arrival_index(3, ArrivalPath::kReflected)].toa_s += 25e-3;
        REQUIRE(plain.step(s10) == Status::kOk);
        const double kk = 2.0;
        const double excess = 2.0 * kk * std::exp(-0.5 * kk * kk) / std::sqrt(2.0 * 3.14159265358979323846) / std::erfc(kk / std::sqrt(2.0));
        CHECK(excess == Approx(4.746).margin(1e-3));
        const Eigen::Matrix<double, 1, 7> h = plain.filter().measurement().jacobian(x_pred).row(bad);
        const Tracker::Cov& P = plain.filter().P();
        const Tracker::State g = P * h.transpose();
        const double s_i = h.dot(g) + 3e-3 * 3e-3;
        const Tracker::Cov expected = P + (excess / s_i) * (g * g.transpose());
        CHECK((tr.filter().P() - expected).cwiseAbs().maxCoeff() < 1e-9 * expected.cwiseAbs().maxCoeff());
        CHECK(tr.filter().P()(L::kZ, L::kZ) > P(L::kZ, L::kZ));
        CHECK(tr.filter().x() == plain.filter().x());
      }
    }
    WHEN("the gate is off and frame 10 carries the same outlier") {
      auto p = sonar_params();
      p.per_channel_gate = false;
      Tracker ungated = kestrel::make_sonar_tracker<double, 4>(p);
      for (int k = 0; k < 10; ++k) REQUIRE(ungated.step(frame_at(k)) == Status::kOk);
      Scan s = frame_at(10);
      s.arrivals[arrival_index(3, ArrivalPath::kReflected)].toa_s += 25e-3;
      REQUIRE(ungated.step(s) == Status::kOk);
      THEN("the outlier is fused and pulls the estimate off") {
        CHECK(ungated.last_step().fused == 8);
        CHECK((ungated.filter().x().head<3>() - truth_at(10)).norm() > 1.0);
      }
    }
    WHEN("every arrival of frame 10 is 60 ms late") {
      Scan s = frame_at(10);
      for (std::size_t i = 0; i < s.count; ++i) s.arrivals[i].toa_s += 60e-3;
      const Tracker::State x9 = tr.filter().x();
      REQUIRE(tr.step(s) == Status::kOk);
      THEN("the step is predict-only") {
        CHECK(tr.last_step().predict_only);
        CHECK(tr.last_step().fused == 0);
        CHECK(tr.last_step().gated_out == 8);
        // Predict-only: x is x9 moved by one second of its own velocity.
        CHECK((tr.filter().x().head<3>() - (x9.head<3>() + x9.segment<3>(L::kVx))).norm() < 1e-9);
        CHECK(tr.counters().predict_only == 1);
      }
      AND_WHEN("the next two frames show the target 150 m further east (three empty frames in a row)") {
        const Eigen::Vector3d jump(150, 0, 0);
        REQUIRE(tr.step(frame_at(11, 1500, nullptr, 0, jump)) == Status::kOk);
        CHECK(tr.last_step().predict_only);
        REQUIRE(tr.step(frame_at(12, 1500, nullptr, 0, jump)) == Status::kOk);
        THEN("the tracker re-acquires from a fix of the third frame") {
          CHECK(tr.last_step().initialised);
          CHECK(tr.counters().initialisations == 2);
          CHECK_FALSE(tr.last_step().predict_only);
          CHECK((tr.filter().x().head<3>() - (truth_at(12) + jump)).norm() < 0.05);
        }
      }
    }
    WHEN("for three frames five arrivals show the target 150 m further east and three show it where it was") {
      // Beacons 0 and 1 (both paths) and beacon 2's direct path moved; the
      // track still fuses the other three, so no frame is empty.
      const Eigen::Vector3d jump(150, 0, 0);
      auto mixed = [&](int k) {
        Scan moved = frame_at(k, 1500, nullptr, 0, jump);
        Scan s = frame_at(k);
        for (std::size_t i = 0; i < 5; ++i) s.arrivals[i] = moved.arrivals[i];
        return s;
      };
      REQUIRE(tr.step(mixed(10)) == Status::kOk);
      CHECK(tr.last_step().fused <= 4);
      CHECK_FALSE(tr.last_step().predict_only);
      REQUIRE(tr.step(mixed(11)) == Status::kOk);
      CHECK_FALSE(tr.last_step().initialised);
      REQUIRE(tr.step(mixed(12)) == Status::kOk);
      THEN("the third frame that fused at most half its arrivals re-acquires on the five that agree") {
        CHECK(tr.last_step().initialised);
        CHECK(tr.counters().initialisations == 2);
        CHECK(tr.last_step().fused == 5);
        CHECK((tr.filter().x().head<3>() - (truth_at(12) + jump)).norm() < 0.05);
      }
    }
    WHEN("for three frames four arrivals are late by different amounts (no fix explains them)") {
      auto garbled = [&](int k) {
        Scan s = frame_at(k);
        for (std::size_t i = 0; i < 4; ++i) s.arrivals[2 * i + 1].toa_s += 40e-3 * static_cast<double>(i + 1);
        return s;
      };
      for (int k = 10; k < 13; ++k) REQUIRE(tr.step(garbled(k)) == Status::kOk);
      THEN("the fix is tried but not taken: it explains no more than the track fused") {
        CHECK(tr.last_step().fused == 4);
        CHECK_FALSE(tr.last_step().initialised);
        CHECK(tr.counters().initialisations == 1);
        // Still on the target; three frames of direct paths only hold depth
        // less tightly than full frames (0.44 m here).
        CHECK((tr.filter().x().head<3>() - truth_at(12)).norm() < 1.0);
      }
    }
  }
}

SCENARIO("bad frames get a status and leave the tracker untouched", "[sonar][tracker][status]") {
  Tracker tr = kestrel::make_sonar_tracker<double, 4>(sonar_params());
  GIVEN("a first frame with three arrivals") {
    Scan s = frame_at(0);
    s.count = 3;
    THEN("kUnderdetermined: not initialised, no report; the next full frame initialises") {
      CHECK(tr.step(s) == Status::kUnderdetermined);
      CHECK_FALSE(tr.initialised());
      CHECK(tr.reports().empty());
      CHECK(tr.counters().rejected[static_cast<std::size_t>(Status::kUnderdetermined)] == 1);
      CHECK(tr.step(frame_at(1)) == Status::kOk);
      CHECK(tr.initialised());
    }
  }
  GIVEN("a tracker following a target") {
    for (int k = 0; k < 5; ++k) REQUIRE(tr.step(frame_at(k)) == Status::kOk);
    const Tracker before = tr;
    const auto refused = [&](const Scan& s, Status expected) {
      CHECK(tr.step(s) == expected);
      CHECK(same_state(tr, before));
      CHECK(tr.reports().empty());
      CHECK(tr.last_step().status == expected);
      CHECK(tr.counters().rejected[static_cast<std::size_t>(expected)] >= 1);
    };
    WHEN("the count is over capacity") {
      Scan s = frame_at(5);
      s.count = Scan::kMaxArrivals + 1;
      refused(s, Status::kMalformedFrame);
    }
    WHEN("two arrivals claim the same beacon and path") {
      Scan s = frame_at(5);
      s.arrivals[1] = s.arrivals[0];
      refused(s, Status::kMalformedFrame);
    }
    WHEN("a path value is neither direct nor reflected") {
      Scan s = frame_at(5);
      s.arrivals[2].path = static_cast<ArrivalPath>(7);
      refused(s, Status::kMalformedFrame);
    }
    WHEN("time goes backwards") { refused(frame_at(3), Status::kTimeWentBackwards); }
    WHEN("an arrival time is NaN") {
      Scan s = frame_at(5);
      s.arrivals[4].toa_s = std::numeric_limits<double>::quiet_NaN();
      refused(s, Status::kNonFinite);
    }
    WHEN("an arrival time is infinite") {
      Scan s = frame_at(5);
      s.arrivals[4].toa_s = std::numeric_limits<double>::infinity();
      refused(s, Status::kNonFinite);
    }
    WHEN("an arrival names beacon 9") {
      Scan s = frame_at(5);
      s.arrivals[5].beacon = 9;
      refused(s, Status::kOutOfRange);
    }
    WHEN("an arrival time is negative") {
      Scan s = frame_at(5);
      s.arrivals[5].toa_s = -0.2;
      refused(s, Status::kOutOfRange);
    }
    WHEN("an arrival time is beyond max_toa_s") {
      Scan s = frame_at(5);
      s.arrivals[5].toa_s = 11.0;
      refused(s, Status::kOutOfRange);
    }
    WHEN("then a good frame arrives") {
      Scan bad = frame_at(5);
      bad.arrivals[0].toa_s = std::numeric_limits<double>::quiet_NaN();
      REQUIRE(tr.step(bad) == Status::kNonFinite);
      THEN("it is tracked as if the bad one had never come") {
        CHECK(tr.step(frame_at(5)) == Status::kOk);
        CHECK(tr.last_step().fused == 8);
      }
    }
    WHEN("a frame carries no arrival") {
      Scan s = frame_at(5);
      s.count = 0;
      THEN("kOk, predict-only") {
        CHECK(tr.step(s) == Status::kOk);
        CHECK(tr.last_step().predict_only);
        CHECK(tr.reports().size() == 1);
      }
    }
  }
}

SCENARIO("a far-future frame is refused, and a clock that really moved is followed", "[sonar][tracker][time]") {
  Tracker tr = kestrel::make_sonar_tracker<double, 4>(sonar_params());
  for (int k = 0; k < 5; ++k) REQUIRE(tr.step(frame_at(k)) == Status::kOk);
  const Tracker before = tr;
  const auto shifted = [](int k, std::int64_t by_us) {
    Scan s = frame_at(k);
    s.t_us += by_us;
    return s;
  };
  WHEN("one frame is a day ahead") {
    CHECK(tr.step(shifted(5, 86'400'000'000)) == Status::kTimeJumpedForward);
    CHECK(same_state(tr, before));
    CHECK(tr.reports().empty());
    THEN("the next frame on the old clock is tracked, not re-initialised") {
      CHECK(tr.step(frame_at(5)) == Status::kOk);
      CHECK_FALSE(tr.last_step().initialised);
      CHECK(tr.last_step().fused == 8);
      CHECK(tr.counters().resyncs == 0);
    }
  }
  for (const std::int64_t by_us : {std::int64_t{-100'000'000}, std::int64_t{3'600'000'000}}) {
    WHEN("the sensor clock moves by " << by_us / 1000000 << " s and stays there") {
      CHECK(tr.step(shifted(5, by_us)) == (by_us < 0 ? Status::kTimeWentBackwards : Status::kTimeJumpedForward));
      CHECK(same_state(tr, before));
      CHECK(tr.step(shifted(6, by_us)) == (by_us < 0 ? Status::kTimeWentBackwards : Status::kTimeJumpedForward));
      CHECK(same_state(tr, before));
      THEN("the third consistent frame restarts the track from a fix on the new clock") {
        CHECK(tr.step(shifted(7, by_us)) == Status::kOk);
        CHECK(tr.last_step().resynced);
        CHECK(tr.last_step().initialised);
        CHECK(tr.counters().resyncs == 1);
        REQUIRE(tr.reports().size() == 1);
        CHECK(tr.reports()[0].t_us == shifted(7, by_us).t_us);
        CHECK(tr.step(shifted(8, by_us)) == Status::kOk);
        CHECK_FALSE(tr.last_step().resynced);
        CHECK((tr.filter().x().segment<3>(L::kPos) - truth_at(8)).norm() < 5.0);
      }
    }
  }
  WHEN("refused frames disagree with each other (each earlier than the one before)") {
    for (int i = 1; i <= 6; ++i) CHECK(tr.step(shifted(5, -100'000'000 * i)) == Status::kTimeWentBackwards);
    THEN("the clock never moves") {
      CHECK(tr.counters().resyncs == 0);
      CHECK(same_state(tr, before));
      CHECK(tr.step(frame_at(5)) == Status::kOk);
    }
  }
}

SCENARIO("a tracker step allocates nothing", "[sonar][tracker][alloc]") {
  GIVEN("a tracker and 50 noisy frames with an outlier every seventh frame") {
    Tracker tr = kestrel::make_sonar_tracker<double, 4>(sonar_params());
    std::mt19937_64 rng(11);
    Scan frames[50];
    for (int k = 0; k < 50; ++k) {
      frames[k] = frame_at(k, 1500, &rng, 3e-3);
      if (k % 7 == 3) frames[k].arrivals[static_cast<std::size_t>(k % 8)].toa_s += 30e-3;
    }
    THEN("initialisation and every tracked step make zero heap allocations") {
      std::size_t allocations = 0;
      int ok = 0;
      {
        kestrel::test::AllocationGuard guard;
        for (const Scan& s : frames) ok += tr.step(s) == Status::kOk ? 1 : 0;
        allocations = guard.allocations();
      }
      CHECK(ok == 50);
      CHECK(allocations == 0);
    }
  }
  GIVEN("the float build") {
    kestrel::SonarTracker<float, 4> tf = kestrel::make_sonar_tracker<float, 4>(sonar_params());
    Tracker td = kestrel::make_sonar_tracker<double, 4>(sonar_params());
    THEN("it follows the double build within centimetres") {
      for (int k = 0; k < 20; ++k) {
        const Scan sd = frame_at(k);
        REQUIRE(td.step(sd) == Status::kOk);
        kestrel::SonarTracker<float, 4>::Scan s;
        s.t_us = sd.t_us;
        s.count = sd.count;
        for (std::size_t i = 0; i < sd.count; ++i) {
          s.arrivals[i].toa_s = static_cast<float>(sd.arrivals[i].toa_s);
          s.arrivals[i].beacon = sd.arrivals[i].beacon;
          s.arrivals[i].path = sd.arrivals[i].path;
        }
        REQUIRE(tf.step(s) == Status::kOk);
      }
      // float times of ~1 s carry 6e-8 s (0.1 mm) of rounding, and the
      // covariance arithmetic a few 1e-7 relative: 2 cm is ample.
      const Eigen::Vector3f p = tf.filter().x().head<3>();
      CHECK((p.cast<double>() - td.filter().x().head<3>()).norm() < 0.02);
      CHECK(std::abs(static_cast<double>(tf.filter().x()(L::kC)) - td.filter().x()(L::kC)) < 0.01);
    }
  }
}

SCENARIO("the sonar adapter turns wire frames into TOA scans", "[sonar][hal]") {
  using kestrel::hal::Frame;
  using kestrel::hal::FrameKind;
  using kestrel::hal::ToaPath;
  Frame f{};
  f.kind = FrameKind::kSonar;
  f.t_us = 7000000;
  f.count = 3;
  f.sonar[0] = {1234567890u, 2, ToaPath::kReflected};
  f.sonar[1] = {1u, 0, ToaPath::kDirect};
  f.sonar[2] = {987654321u, 3, ToaPath::kDirect};
  GIVEN("a sonar frame") {
    Scan s;
    THEN("nanoseconds become seconds, labels are kept") {
      REQUIRE(kestrel::hal::to_scan(f, s) == Status::kOk);
      CHECK(s.t_us == 7000000);
      CHECK(s.count == 3);
      CHECK(s.arrivals[0].toa_s == 1.23456789);
      CHECK(s.arrivals[0].beacon == 2);
      CHECK(s.arrivals[0].path == ArrivalPath::kReflected);
      CHECK(s.arrivals[1].toa_s == 1e-9);
      CHECK(s.arrivals[2].path == ArrivalPath::kDirect);
      CHECK(kestrel::hal::SonarAdapter{}(f, s) == Status::kOk);
    }
  }
  GIVEN("a radar frame") {
    Frame r{};
    r.kind = FrameKind::kRadar;
    Scan s;
    s.count = 5;
    THEN("kWrongKind and the scan is untouched") {
      CHECK(kestrel::hal::to_scan(r, s) == Status::kWrongKind);
      CHECK(s.count == 5);
    }
  }
  GIVEN("an unknown path value") {
    Frame bad = f;
    bad.sonar[1].path = static_cast<ToaPath>(4);
    Scan s;
    s.count = 5;
    THEN("kMalformedFrame and the scan is untouched") {
      CHECK(kestrel::hal::to_scan(bad, s) == Status::kMalformedFrame);
      CHECK(s.count == 5);
    }
  }
  GIVEN("more arrivals than the scan holds") {
    Frame many{};
    many.kind = FrameKind::kSonar;
    many.count = 12;
    for (std::size_t i = 0; i < 12; ++i) {
      many.sonar[i] = {static_cast<std::uint32_t>(1000000 + i), static_cast<std::uint8_t>(i / 2),
                       (i % 2) != 0 ? ToaPath::kReflected : ToaPath::kDirect};
    }
    Scan s;
    THEN("the first eight are kept with kTooManyCandidates") {
      CHECK(kestrel::hal::to_scan(many, s) == Status::kTooManyCandidates);
      CHECK(s.count == 8);
      CHECK(s.arrivals[7].beacon == 3);
    }
  }
  GIVEN("an installation config in millimetres") {
    kestrel::hal::SonarAdapterParams cfg;
    cfg.seabed_depth_mm = 100000;
    cfg.sigma_toa_ns = 1000000;
    const auto p = kestrel::hal::sonar_tracker_params(cfg);
    THEN("the tracker parameters carry it in metres and seconds") {
      CHECK(p.seabed_depth_m == 100.0);
      CHECK(p.sigma_toa_s == Approx(1e-3));
      CHECK(p.beacon_count == 4);
      CHECK(p.beacons_m[3][0] == 2000.0);
      CHECK(p.beacons_m[3][1] == 2000.0);
    }
  }
  GIVEN("wire frames of a noise-free track fed through the adapter") {
    Tracker tr = kestrel::make_sonar_tracker<double, 4>(sonar_params());
    Tracker direct = kestrel::make_sonar_tracker<double, 4>(sonar_params());
    THEN("the tracker follows it as it follows the unquantised scans") {
      for (int k = 0; k < 5; ++k) {
        const Scan truth = frame_at(k);
        REQUIRE(direct.step(truth) == Status::kOk);
        Frame w{};
        w.kind = FrameKind::kSonar;
        w.t_us = truth.t_us;
        w.count = static_cast<std::uint16_t>(truth.count);
        for (std::size_t i = 0; i < truth.count; ++i) {
          w.sonar[i].time_of_flight_ns = static_cast<std::uint32_t>(std::llround(truth.arrivals[i].toa_s * 1e9));
          w.sonar[i].beacon_id = truth.arrivals[i].beacon;
          w.sonar[i].path = truth.arrivals[i].path == ArrivalPath::kDirect ? ToaPath::kDirect : ToaPath::kReflected;
        }
        Scan s;
        REQUIRE(kestrel::hal::to_scan(w, s) == Status::kOk);
        REQUIRE(tr.step(s) == Status::kOk);
      }
      // 1 ns quantisation is 1.5 um of range.
      CHECK((tr.filter().x().head<3>() - direct.filter().x().head<3>()).norm() < 1e-3);
    }
  }
}

SCENARIO("the composed sonar tracker checks only the channels a frame carries", "[sonar][tracker][status]") {
  // SonarTracker is Tracker<ChannelGatedEkf, MultilaterationInitiator,
  // 1, 1, LabelledAssociation, ReacquireWhenLost> over one ChannelScan entry.
  using Core = Tracker::Core;
  Tracker tr = kestrel::make_sonar_tracker<double, 4>(sonar_params());
  Core core = tr.core();
  const Scan full = frame_at(0);
  Core::Scan s;
  s.t_us = full.t_us;
  s.count = 1;
  s.z[0].setConstant(std::numeric_limits<double>::quiet_NaN());  // absent channels are never read
  for (std::size_t i = 0; i < full.count; ++i) {
    const auto& a = full.arrivals[i];
    if (a.path != ArrivalPath::kDirect) continue;
    const int ch = Tracker::Toa::channel(a.beacon, a.path);
    s.z[0](ch) = a.toa_s;
    s.present[0] |= ChannelMask{1} << ch;
  }
  WHEN("the four direct arrivals are present and the rest NaN") {
    REQUIRE(core.step(s) == Status::kOk);
    THEN("a track starts from their fix, confirmed, fusing exactly them") {
      REQUIRE(core.reports().size() == 1);
      CHECK(core.reports()[0].fusion.fused_channels == s.present[0]);
      CHECK(core.last_step().seeded == 1);
    }
  }
  WHEN("a present channel is NaN") {
    s.z[0](Tracker::Toa::channel(2, ArrivalPath::kDirect)) = std::numeric_limits<double>::quiet_NaN();
    CHECK(core.step(s) == Status::kNonFinite);
    CHECK(core.tracks().size() == 0);
  }
  WHEN("the mask names a channel the model does not have") {
    s.present[0] |= ChannelMask{1} << 8;
    CHECK(core.step(s) == Status::kMalformedFrame);
    CHECK(core.tracks().size() == 0);
  }
  WHEN("three arrivals cannot fix the position") {
    s.present[0] &= ~(ChannelMask{1} << Tracker::Toa::channel(3, ArrivalPath::kDirect));
    REQUIRE(core.step(s) == Status::kOk);
    THEN("the frame is taken, no track starts and the step says why") {
      CHECK(core.reports().empty());
      CHECK(core.last_step().failure == Status::kUnderdetermined);
      CHECK(core.initiator().last_fix().status == Status::kUnderdetermined);
    }
  }
}
