// SPDX-License-Identifier: Apache-2.0
// The adaptive measurement noise of the robust gate: the scale stays in
// [1, max] whatever the NIS (NaN, Inf, negative, huge), moves by a bounded
// step per plot, rises under a burst and decays after it; the filters'
// scaled update keeps P positive definite in float as in double and
// allocates nothing; inside a tracker built with AdaptiveMeasurementNoise
// it acts only with the robust gate, with a gain of 0 it gives what the
// nominal tracker gives, bit for bit, and a tracker built without it
// refuses a gain.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <type_traits>

#include "kestrel/association/adaptive_noise.hpp"
#include "kestrel/filters/imm_radar.hpp"
#include "kestrel/tracking/radar_tracker.hpp"
#include "support/alloc_guard.hpp"

using kestrel::Status;

namespace {

template <class S>
kestrel::AdaptiveNoise<S> tuned() {
  // The radar tracker's defaults with the 0.999 gate of two channels.
  return kestrel::AdaptiveNoise<S>{S(0.2), S(16), S(13.816)};
}

/// chi-square with 2 degrees of freedom: twice a unit exponential.
double chi2_2(std::mt19937& rng) { return 2.0 * std::exponential_distribution<double>(1.0)(rng); }

template <class S>
bool positive_definite(const kestrel::Mat<S, 6, 6>& P) {
  if (!P.allFinite()) return false;
  if ((P - P.transpose()).cwiseAbs().maxCoeff() > S(1e-3) * P.cwiseAbs().maxCoeff()) return false;
  return Eigen::LLT<kestrel::Mat<S, 6, 6>>(P).info() == Eigen::Success;
}

/// Plots of a target flying straight from (-15000, 8000) at (200, 50) m/s,
/// range and bearing noise `factor` x the S1/S2 sensor's.
template <class S>
kestrel::Vec<S, 2> plot_at(double t_s, double factor, std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  const double x = -15000 + 200 * t_s, y = 8000 + 50 * t_s;
  const double r = std::hypot(x, y) + factor * 3.0 * n(rng);
  const double b = std::atan2(y, x) + factor * 0.3 * 3.14159265358979323846 / 180.0 * n(rng);
  return kestrel::Vec<S, 2>(static_cast<S>(r), static_cast<S>(b));
}

}  // namespace

TEMPLATE_TEST_CASE("Scenario: the noise scale stays within its bounds whatever the NIS", "[adaptive_noise]", double,
                   float) {
  using S = TestType;
  const auto a = tuned<S>();
  REQUIRE(a.enabled());
  GIVEN("a long run of NIS values among them 0 and negative and NaN and Inf and huge ones") {
    std::mt19937 rng(11);
    std::uniform_int_distribution<int> pick(0, 9);
    S scale(1);
    bool in_bounds = true, step_bounded = true;
    // Per plot the scale grows at most by 1 + alpha (cap / m - 1) and falls
    // at most by 1 - alpha; a relative 1e-5 covers float's rounding.
    const double up = 1.0 + 0.2 * (13.816 / 2.0 - 1.0), down = 1.0 - 0.2;
    for (int k = 0; k < 20000; ++k) {
      S d2;
      switch (pick(rng)) {
        case 0: d2 = std::numeric_limits<S>::quiet_NaN(); break;
        case 1: d2 = std::numeric_limits<S>::infinity(); break;
        case 2: d2 = S(-5); break;
        case 3: d2 = S(1e30); break;
        case 4: d2 = S(0); break;
        default: d2 = static_cast<S>(chi2_2(rng) * (k % 400 < 200 ? 9.0 : 1.0)); break;
      }
      const S next = a.next(scale, d2, 2);
      in_bounds = in_bounds && next >= S(1) && next <= S(16);
      step_bounded = step_bounded && static_cast<double>(next) <= static_cast<double>(scale) * up * (1 + 1e-5) &&
                     static_cast<double>(next) >= std::max(1.0, static_cast<double>(scale) * down) * (1 - 1e-5);
      scale = next;
    }
    THEN("every scale is in [1, 16] and every step within its bound") {
      CHECK(in_bounds);
      CHECK(step_bounded);
    }
  }
  GIVEN("a scale outside the bounds or NaN") {
    THEN("it is brought back into them first") {
      CHECK(a.clamped(S(0.5)) == S(1));
      CHECK(a.clamped(S(100)) == S(16));
      CHECK(a.clamped(std::numeric_limits<S>::quiet_NaN()) == S(1));
      CHECK(a.next(S(100), S(2), 2) == S(16));
    }
  }
  GIVEN("a gain of 0 or a largest scale of 1") {
    THEN("the adaptation is off") {
      CHECK_FALSE((kestrel::AdaptiveNoise<S>{S(0), S(16), S(13.816)}.enabled()));
      CHECK_FALSE((kestrel::AdaptiveNoise<S>{S(0.2), S(1), S(13.816)}.enabled()));
      CHECK_FALSE(kestrel::AdaptiveNoise<S>{}.enabled());
    }
  }
}

TEMPLATE_TEST_CASE("Scenario: the noise scale follows a burst and decays after it", "[adaptive_noise]", double,
                   float) {
  using S = TestType;
  const auto a = tuned<S>();
  std::mt19937 rng(5);
  S scale(1);
  // d2 against lambda R of a plot whose noise is 9 R: (9 / lambda) chi2_2
  // (the prediction's share of S left out: the sensor-dominated limit).
  for (int k = 0; k < 30; ++k) scale = a.next(scale, static_cast<S>(9.0 / static_cast<double>(scale) * chi2_2(rng)), 2);
  const double in_burst = static_cast<double>(scale);
  for (int k = 0; k < 30; ++k) scale = a.next(scale, static_cast<S>(1.0 / static_cast<double>(scale) * chi2_2(rng)), 2);
  const double after = static_cast<double>(scale);
  INFO("scale after 30 burst plots " << in_burst << ", after 30 nominal ones " << after);
  // Bounds from the fixed point of the rule (lambda = 9 in the burst, 1
  // after it) with room for the chi-square draws of one seed.
  CHECK(in_burst > 4.0);
  CHECK(in_burst <= 16.0);
  CHECK(after < 1.6);
}

TEMPLATE_TEST_CASE("Scenario: the IMM and the EKF fuse with a scaled R and keep P positive definite",
                   "[adaptive_noise][imm]", double, float) {
  using S = TestType;
  auto imm = kestrel::make_radar_imm<S>(kestrel::RadarImmParams{});
  kestrel::RadarTrackerParams p;
  p.qj = 16.0;
  const auto s = kestrel::radar_tracker_config<S>(p);
  kestrel::CaMotion<S> motion;
  motion.qj = s.qj;
  kestrel::CaPolarRadar<S> radar;
  radar.sigma_range_m = s.sigma_range_m;
  radar.sigma_bearing_rad = s.sigma_bearing_rad;
  kestrel::EkfCa<S> ekf(motion, radar);
  typename kestrel::RadarImm<S>::State x0 = kestrel::RadarImm<S>::State::Zero();
  x0 << S(-15000), S(200), S(0), S(8000), S(50), S(0);
  typename kestrel::RadarImm<S>::Cov P0 = kestrel::RadarImm<S>::Cov::Identity();
  P0.diagonal() << S(400), S(400), S(100), S(400), S(400), S(100);
  REQUIRE(imm.reset(x0, P0) == Status::kOk);
  REQUIRE(ekf.reset(x0, P0) == Status::kOk);

  GIVEN("one prediction and the same plot fused with R and with 9 R") {
    std::mt19937 rng(3);
    REQUIRE(imm.predict(S(0.5)) == Status::kOk);
    const auto z = plot_at<S>(0.5, 3.0, rng);
    const auto plain = imm.innovation(z);
    const auto scaled = imm.innovation_scaled(z, S(9));
    auto imm_plain = imm, imm_scaled = imm;
    REQUIRE(imm_plain.update(z) == Status::kOk);
    REQUIRE(imm_scaled.update_scaled(z, S(9)) == Status::kOk);
    THEN("S grows by 8 R and the posterior keeps more of the prior's uncertainty") {
      const auto R = imm.measurement().noise();
      // S is formed in the filter's scalar: float's relative 1e-4 of its largest entry.
      const S tol = S(std::is_same_v<S, float> ? 1e-4 : 1e-9) * scaled.S.cwiseAbs().maxCoeff();
      CHECK(((scaled.S - plain.S) - S(8) * R).cwiseAbs().maxCoeff() <= tol);
      CHECK(scaled.d2 < plain.d2);
      CHECK(imm_scaled.P().trace() > imm_plain.P().trace());
      CHECK(positive_definite<S>(imm_scaled.P()));
    }
  }
  GIVEN("80 frames of a x3 noisy sensor fused with scales from 1 to 16") {
    std::mt19937 rng(9);
    bool pd = true;
    Status worst = Status::kOk;
    std::size_t allocations = 0;
    {
      kestrel::test::AllocationGuard guard;
      for (int k = 1; k <= 80; ++k) {
        const auto z = plot_at<S>(0.5 * k, 3.0, rng);
        const S scale = S(1) + S(15) * S(static_cast<float>(k % 16) / 15.0f);
        const Status a = imm.predict(S(0.5)), b = imm.update_scaled(z, scale);
        const Status c = ekf.predict(S(0.5)), d = ekf.update_scaled(z, scale);
        for (const Status st : {a, b, c, d}) {
          if (st != Status::kOk) worst = st;
        }
        pd = pd && positive_definite<S>(imm.P()) && positive_definite<S>(ekf.P());
      }
      allocations = guard.allocations();
    }
    THEN("every step succeeds with P positive definite and no allocation") {
      CHECK(worst == Status::kOk);
      CHECK(pd);
      CHECK(allocations == 0);
    }
  }
  GIVEN("a scale that is not positive or not finite") {
    REQUIRE(imm.predict(S(0.5)) == Status::kOk);
    REQUIRE(ekf.predict(S(0.5)) == Status::kOk);
    const auto imm_before = imm;
    const auto ekf_before = ekf;
    const kestrel::Vec<S, 2> z(S(17000), S(2.65));
    THEN("the update is refused and the filter is unchanged") {
      CHECK(imm.update_scaled(z, S(0)) == Status::kOutOfRange);
      CHECK(imm.update_scaled(z, std::numeric_limits<S>::quiet_NaN()) == Status::kNonFinite);
      CHECK(ekf.update_scaled(z, S(-1)) == Status::kOutOfRange);
      CHECK(ekf.update_scaled(z, std::numeric_limits<S>::infinity()) == Status::kNonFinite);
      CHECK(imm.innovation_scaled(z, S(0)).status == Status::kOutOfRange);
      CHECK(imm.x() == imm_before.x());
      CHECK(imm.P() == imm_before.P());
      CHECK(ekf.x() == ekf_before.x());
      CHECK(ekf.P() == ekf_before.P());
    }
  }
}

TEMPLATE_TEST_CASE("Scenario: inside the tracker the noise scale adapts only with the robust gate",
                   "[adaptive_noise][tracker]", double, float) {
  using S = TestType;
  STATIC_REQUIRE(kestrel::ScalesMeasurementNoise<kestrel::EkfCa<S>>);
  STATIC_REQUIRE(kestrel::ScalesMeasurementNoise<kestrel::RadarImm<S>>);
  // A target flying straight, its plots x3 noisier for frames 40-99.
  auto run = [](double robust_gate_factor, double gain) {
    kestrel::RadarTrackerParams p;
    p.qj = 16.0;
    p.robust_gate_factor = robust_gate_factor;
    p.robust_noise_gain = gain;
    using Adaptive = kestrel::AdaptiveRadarTracker<kestrel::EkfCa<S>, 16, 32>;
    const auto nominal = kestrel::make_radar_tracker<S, 16, 32>(p);
    Adaptive tracker(nominal.prototype_filter(), nominal.initiator(), nominal.config());
    // Without the robust gate a gain could not act: it is refused and the
    // tracker keeps R as modelled.
    const Status expected = gain > 0.0 && robust_gate_factor <= 1.0 ? Status::kOutOfRange : Status::kOk;
    REQUIRE(tracker.configure_measurement_noise(kestrel::radar_measurement_noise<S>(p)) == expected);
    std::mt19937 rng(21);
    struct Outcome {
      double largest = 1.0, last = 1.0;
      int scaled_updates = 0, frames_with_one_track = 0;
      std::size_t allocations = 0;
    } out;
    for (int k = 0; k < 140; ++k) {
      typename decltype(tracker)::Scan scan;
      scan.t_us = k * 500000LL;
      scan.count = 1;
      scan.z[0] = plot_at<S>(0.5 * k, k >= 40 && k < 100 ? 3.0 : 1.0, rng);
      Status stepped = Status::kOk;
      {
        kestrel::test::AllocationGuard guard;
        stepped = tracker.step(scan);
        out.allocations += guard.allocations();
      }
      REQUIRE(stepped == Status::kOk);
      out.scaled_updates += tracker.measurement_noise().scaled_updates();
      if (tracker.reports().size() == 1) ++out.frames_with_one_track;
      for (const std::size_t i : tracker.tracks().active_slots()) {
        const double scale = static_cast<double>(tracker.measurement_noise().scale(i));
        out.largest = std::max(out.largest, scale);
        out.last = scale;
      }
    }
    return out;
  };
  GIVEN("the robust gate at 25 with the adaptive noise on") {
    const auto on = run(25.0, 0.2);
    INFO("largest scale " << on.largest << ", last " << on.last << ", scaled updates " << on.scaled_updates);
    THEN("the burst raises the scale within its bound and it is back near 1 after it") {
      CHECK(on.largest > 3.0);
      CHECK(on.largest <= 16.0);
      CHECK(on.last < 1.6);
      CHECK(on.scaled_updates > 40);
      CHECK(on.frames_with_one_track >= 138);
      CHECK(on.allocations == 0);
    }
  }
  GIVEN("the adaptive noise off, or a gain refused without the robust gate") {
    const auto no_gain = run(25.0, 0.0);
    const auto no_robust = run(0.0, 0.2);
    THEN("every track fuses with R as modelled") {
      CHECK(no_gain.largest == 1.0);
      CHECK(no_gain.scaled_updates == 0);
      CHECK(no_robust.largest == 1.0);
      CHECK(no_robust.scaled_updates == 0);
    }
  }
}

TEMPLATE_TEST_CASE("Scenario: a tracker without the adaptive noise refuses a gain and with a gain of 0 the adaptive one is the nominal one",
                   "[adaptive_noise][tracker]", double, float) {
  using S = TestType;
  using Nominal = kestrel::RadarTracker<kestrel::EkfCa<S>, 16, 32>;
  using Adaptive = kestrel::AdaptiveRadarTracker<kestrel::EkfCa<S>, 16, 32>;
  STATIC_REQUIRE(!Nominal::MeasurementNoiseT::kAdapts);
  STATIC_REQUIRE(Adaptive::MeasurementNoiseT::kAdapts);
  // The nominal policy has no state: the tracker is the size it was without it.
  STATIC_REQUIRE(std::is_empty_v<typename Nominal::MeasurementNoiseT>);
  kestrel::RadarTrackerParams p;
  p.robust_gate_factor = 25.0;
  GIVEN("a tracker built without the adaptive noise (make_radar_tracker, every board's)") {
    auto tracker = kestrel::make_radar_tracker<S, 16, 32>(p);
    THEN("a gain is refused with kOutOfRange, a gain of 0 is accepted") {
      p.robust_noise_gain = 0.2;
      CHECK(tracker.configure_measurement_noise(kestrel::radar_measurement_noise<S>(p)) == Status::kOutOfRange);
      p.robust_noise_gain = 0.0;
      CHECK(tracker.configure_measurement_noise(kestrel::radar_measurement_noise<S>(p)) == Status::kOk);
    }
  }
  GIVEN("a tracker built with it") {
    const auto nominal = kestrel::make_radar_tracker<S, 16, 32>(p);
    Adaptive tracker(nominal.prototype_filter(), nominal.initiator(), nominal.config());
    THEN("a gain outside [0, 1], a max scale below 1 or a NaN is refused") {
      CHECK(tracker.configure_measurement_noise({S(1.5), S(16)}) == Status::kOutOfRange);
      CHECK(tracker.configure_measurement_noise({S(-0.1), S(16)}) == Status::kOutOfRange);
      CHECK(tracker.configure_measurement_noise({S(0.2), S(0.5)}) == Status::kOutOfRange);
      CHECK(tracker.configure_measurement_noise({std::numeric_limits<S>::quiet_NaN(), S(16)}) == Status::kNonFinite);
      CHECK(tracker.configure_measurement_noise({S(0.2), S(16)}) == Status::kOk);
    }
  }
  GIVEN("a tracker built with it but without the robust gate") {
    p.robust_gate_factor = 0.0;
    const auto nominal = kestrel::make_radar_tracker<S, 16, 32>(p);
    Adaptive tracker(nominal.prototype_filter(), nominal.initiator(), nominal.config());
    THEN("a gain, which could not act, is refused; a gain of 0 is accepted") {
      CHECK(tracker.configure_measurement_noise({S(0.2), S(16)}) == Status::kOutOfRange);
      CHECK(tracker.configure_measurement_noise({S(0), S(16)}) == Status::kOk);
    }
  }
  GIVEN("a burst, tracked by the nominal tracker and by the adaptive one with a gain of 0") {
    auto nominal = kestrel::make_radar_tracker<S, 16, 32>(p);
    Adaptive adaptive(nominal.prototype_filter(), nominal.initiator(), nominal.config());
    REQUIRE(adaptive.configure_measurement_noise(kestrel::radar_measurement_noise<S>(p)) == Status::kOk);
    THEN("every report is the same, bit for bit") {
      std::mt19937 rng(7);
      int reports = 0;
      for (int k = 0; k < 140; ++k) {
        typename Nominal::Scan scan;
        scan.t_us = k * 500000LL;
        scan.count = 1;
        scan.z[0] = plot_at<S>(0.5 * k, k >= 40 && k < 100 ? 3.0 : 1.0, rng);
        REQUIRE(nominal.step(scan) == Status::kOk);
        REQUIRE(adaptive.step(scan) == Status::kOk);
        REQUIRE(nominal.reports().size() == adaptive.reports().size());
        for (std::size_t i = 0; i < nominal.reports().size(); ++i) {
          CHECK(nominal.reports()[i].x == adaptive.reports()[i].x);
          CHECK(nominal.reports()[i].P == adaptive.reports()[i].P);
          CHECK(nominal.reports()[i].test_ratio == adaptive.reports()[i].test_ratio);
          ++reports;
        }
        CHECK(nominal.last_step().clipped == adaptive.last_step().clipped);
        CHECK(adaptive.measurement_noise().scaled_updates() == 0);
      }
      CHECK(reports > 100);
    }
  }
}
