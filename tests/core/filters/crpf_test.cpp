// SPDX-License-Identifier: Apache-2.0
// CRPF: tracks MC-001's middle cell within a stated bound; bit-identical
// for the same seed (and different for another); a bad measurement returns a
// status and leaves the filter exactly as it was, PRNG included; systematic
// resampling keeps the cloud on the cheap particles; zero allocations per
// step; runs on a model without noise_gain() (CA-2D) and plugs into the
// Tracker.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "core/filters/crpf_trace_hash.hpp"
#include "core/filters/sigma_test_support.hpp"
#include "kestrel/filters/crpf.hpp"
#include "kestrel/models/measurement/polar_radar.hpp"
#include "kestrel/models/motion/constant_acceleration_2d.hpp"
#include "kestrel/models/motion/constant_velocity_2d.hpp"
#include "kestrel/tracking/tracker.hpp"
#include "support/alloc_guard.hpp"

using kestrel::Status;
using Motion = kestrel::ConstantVelocity2D<double>;
using Radar = kestrel::PolarRadar<Motion>;
template <int kN>
using Crpf = kestrel::Crpf<Motion, Radar, kN>;

namespace {

constexpr double kDeg = kestrel::test::kPi / 180.0;

/// The filters of MC-001 are tuned with the middle values (docs/scenarios.md).
Radar middle_radar() {
  Radar r;
  r.sigma_range_m = 1.0;
  r.sigma_bearing_rad = 0.1 * kDeg;
  return r;
}

struct RunResult {
  double mse_m2 = 0.0;         ///< Mean over k = 1..100 of the squared position error.
  double final_error_m = 0.0;  ///< Position error at k = 100.
  std::vector<double> trace;   ///< Every estimate's coordinates, for bit comparisons.
};

/// One MC-001 run in the middle cell (sb = 0.1 deg, sr = 1 m, sa = 0.1 m/s^2)
/// with data seed `run` and filter seed `filter_seed`.
template <int kN>
RunResult mc001_middle_run(std::uint64_t run, std::uint64_t filter_seed) {
  kestrel::NormalGenerator<double> noise(1000 + run);
  const auto truth = kestrel::test::mc001_truth(100, 0.1, noise);
  Motion motion;
  motion.sa = 0.1;
  kestrel::CrpfConfig<double> params;
  params.seed = filter_seed;
  params.refuse_indefinite = false;  // MC-001 scores the estimate alone
  Crpf<kN> f(motion, middle_radar(), params);
  const Eigen::Vector4d sd(50.0, 5.0, 50.0, 5.0);
  Eigen::Vector4d x0 = truth[0];
  for (int i = 0; i < 4; ++i) x0(i) += sd(i) * noise();
  const Eigen::Matrix4d P0 = sd.array().square().matrix().asDiagonal();
  REQUIRE(f.reset(x0, P0) == Status::kOk);
  RunResult out;
  for (int k = 1; k <= 100; ++k) {
    const auto& xt = truth[static_cast<std::size_t>(k)];
    const Eigen::Vector2d z = kestrel::test::polar_measurement(xt(0), xt(2), 1.0, 0.1 * kDeg, noise);
    REQUIRE(f.predict(1.0) == Status::kOk);
    REQUIRE(f.update(z) == Status::kOk);
    const double e2 = std::pow(f.x()(0) - xt(0), 2) + std::pow(f.x()(2) - xt(2), 2);
    out.mse_m2 += e2 / 100.0;
    out.final_error_m = std::sqrt(e2);
    for (int i = 0; i < 4; ++i) out.trace.push_back(f.x()(i));
  }
  return out;
}

bool bit_identical(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

}  // namespace

SCENARIO("the CRPF tracks MC-001's middle cell", "[crpf][mc001]") {
  GIVEN("CRPF N = 100 tuned with the middle values, 40 runs of the middle cell") {
    const int runs = 40;
    double mse_sum = 0.0;
    int diverged = 0;
    double worst_final = 0.0;
    for (int r = 0; r < runs; ++r) {
      const RunResult res = mc001_middle_run<100>(static_cast<std::uint64_t>(r), static_cast<std::uint64_t>(r));
      mse_sum += res.mse_m2;
      diverged += res.final_error_m > 100.0 ? 1 : 0;
      worst_final = std::max(worst_final, res.final_error_m);
    }
    const double mse = mse_sum / runs;
    INFO("mean position MSE " << mse << " m^2, diverged " << diverged << ", worst final error " << worst_final
                              << " m");
    THEN("no run diverges (final error over 100 m) and the MSE stays within the bound") {
      // Measured: MSE 18.3 m^2, worst final error 9.7 m (docs/filters.md).
      // Bounds at about twice that; the MSE is dominated by the first steps
      // (acquiring from a 50 m / 5 m/s prior with 100 particles), the final
      // error by the 2 m/s^2 kick against a 0.1 m/s^2 target.
      CHECK(diverged == 0);
      CHECK(mse < 60.0);
      CHECK(worst_final < 20.0);
    }
  }
}

SCENARIO("the CRPF is bit-identical for the same seed", "[crpf][determinism]") {
  GIVEN("two runs of the same data with filter seed 7 and one with seed 8") {
    const RunResult a = mc001_middle_run<100>(3, 7);
    const RunResult b = mc001_middle_run<100>(3, 7);
    const RunResult c = mc001_middle_run<100>(3, 8);
    THEN("the seed-7 runs agree bit for bit at every step; seed 8 differs") {
      CHECK(bit_identical(a.trace, b.trace));
      CHECK_FALSE(bit_identical(a.trace, c.trace));
    }
  }
}

SCENARIO("the CRPF gives the recorded bits on MC-001's middle cell", "[crpf][determinism][golden]") {
  GIVEN("100-step runs: double with 100 particles and beta 2 and with 33 and beta 3 and float with 100") {
    THEN("the hash of every estimate and covariance and particle and cost and weight equals the recorded one") {
      // Recorded on the host (x86-64, glibc for the data, no FMA) when the
      // particles' bearings moved to PolarRadar::particle_residuals (a small
      // angle from the predicted mean's bearing): any change of the filter's
      // arithmetic or of its PRNG draws changes these.
      CHECK(kestrel::test::crpf_trace_hash<double, 100>(3, 7, 2) == 0x6088139043d971bbull);
      CHECK(kestrel::test::crpf_trace_hash<double, 33>(4, 11, 3) == 0xed39454b05c421edull);
      CHECK(kestrel::test::crpf_trace_hash<float, 100>(3, 7, 2) == 0x08b82c303609cc1bull);
    }
  }
}

SCENARIO("the CRPF refuses bad input and stays exactly as it was", "[crpf][status]") {
  Motion motion;
  motion.sa = 0.1;
  kestrel::CrpfConfig<double> params;
  params.seed = 99;
  Crpf<64> f(motion, middle_radar(), params);
  Crpf<64> twin(motion, middle_radar(), params);
  const Eigen::Vector4d x0(1000.0, 10.0, 1000.0, 5.0);
  const Eigen::Matrix4d P0 = Eigen::Vector4d(100.0, 1.0, 100.0, 1.0).asDiagonal();
  REQUIRE(f.reset(x0, P0) == Status::kOk);
  REQUIRE(twin.reset(x0, P0) == Status::kOk);
  REQUIRE(f.predict(1.0) == Status::kOk);
  REQUIRE(twin.predict(1.0) == Status::kOk);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Crpf<64>::MeasVec good(std::hypot(1010.0, 1005.0), std::atan2(1005.0, 1010.0));
  WHEN("updates with NaN, Inf or a zero scale are refused") {
    CHECK(f.update(Crpf<64>::MeasVec(nan, 0.7)) == Status::kNonFinite);
    CHECK(f.update(Crpf<64>::MeasVec(1400.0, std::numeric_limits<double>::infinity())) == Status::kNonFinite);
    CHECK(f.update(good, Crpf<64>::MeasCov::Zero()) == Status::kNotPositiveDefinite);
    CHECK(f.predict(nan) == Status::kNonFinite);
    CHECK(f.reset(x0, -P0) == Status::kNotPositiveDefinite);
    CHECK_FALSE(f.diagnostics().fused);
    THEN("the next good update gives the same bits as a twin that never saw them") {
      REQUIRE(f.update(good) == Status::kOk);
      REQUIRE(twin.update(good) == Status::kOk);
      CHECK(f.x() == twin.x());
      CHECK(f.P() == twin.P());
      CHECK(f.diagnostics().fused);
    }
  }
}

SCENARIO("selection concentrates the cloud on the particles of least risk", "[crpf][resampling]") {
  GIVEN("a wide cloud (no kick, so selection alone moves it) and a measurement of a point inside it") {
    Motion motion;
    motion.sa = 0.1;
    kestrel::CrpfConfig<double> params;
    params.kick_sigma = 0.0;
    params.seed = 5;
    params.refuse_indefinite = false;  // copies only: the selected cloud is singular by design
    const Radar radar = middle_radar();
    Crpf<200> f(motion, radar, params);
    const Eigen::Vector4d x0(1000.0, 0.0, 1000.0, 0.0);
    REQUIRE(f.reset(x0, Eigen::Vector4d(200.0 * 200.0, 1e-6, 200.0 * 200.0, 1e-6).asDiagonal()) == Status::kOk);
    std::vector<Eigen::Vector4d> before;
    for (int i = 0; i < 200; ++i) before.push_back(f.particle(i));
    const double tx = 1100.0, ty = 950.0;
    const Crpf<200>::MeasVec z(std::hypot(tx, ty), std::atan2(ty, tx));
    // Risk of each old particle (costs are 0 after reset): docs/filters.md's dC.
    const auto risk = [&](const Eigen::Vector4d& p) {
      const auto nu = radar.residual(z, radar.predict(p));
      return std::pow(nu(0) / radar.sigma_range_m, 2) + std::pow(nu(1) / radar.sigma_bearing_rad, 2);
    };
    int best = 0;
    double mean_risk_before = 0.0;
    for (int i = 0; i < 200; ++i) {
      mean_risk_before += risk(before[static_cast<std::size_t>(i)]) / 200.0;
      if (risk(before[static_cast<std::size_t>(i)]) < risk(before[static_cast<std::size_t>(best)])) best = i;
    }
    const double mean_before_m = std::hypot(f.x()(0) - tx, f.x()(2) - ty);
    REQUIRE(f.update(z) == Status::kOk);
    THEN("every particle is a copy of an old one, the least-risk one survives, the rest are cheap") {
      bool all_copies = true;
      bool best_survives = false;
      double mean_risk_after = 0.0;
      for (int i = 0; i < 200; ++i) {
        const Eigen::Vector4d& p = f.particle(i);
        bool found = false;
        for (const auto& q : before) found = found || p == q;
        all_copies = all_copies && found;
        best_survives = best_survives || p == before[static_cast<std::size_t>(best)];
        mean_risk_after += risk(p) / 200.0;
      }
      CHECK(all_copies);
      // Systematic resampling keeps every particle whose share N pi_i >= 1.
      CHECK(best_survives);
      // PMF (R - min R + 1)^-2: the survivors' mean risk is a small fraction
      // of the cloud's (here the cloud's mean risk is of order 1e4).
      INFO("mean risk before " << mean_risk_before << ", after " << mean_risk_after);
      CHECK(mean_risk_after < 0.01 * mean_risk_before);
      CHECK(std::hypot(f.x()(0) - tx, f.x()(2) - ty) < 0.5 * mean_before_m);
    }
  }
}

SCENARIO("a CRPF step allocates nothing", "[crpf][alloc]") {
  Motion motion;
  motion.sa = 0.1;
  Crpf<500> f(motion, middle_radar());
  const Eigen::Vector4d x0(1000.0, 10.0, 1000.0, 5.0);
  const Eigen::Matrix4d P0 = Eigen::Vector4d(2500.0, 25.0, 2500.0, 25.0).asDiagonal();
  const Crpf<500>::MeasVec z(std::hypot(1010.0, 1005.0), std::atan2(1005.0, 1010.0));
  std::size_t allocations = 0;
  Status s0, s1, s2, s3;
  {
    kestrel::test::AllocationGuard guard;
    s0 = f.reset(x0, P0);
    s1 = f.predict(1.0);
    s2 = f.innovation(z).status;
    s3 = f.update(z);
    allocations = guard.allocations();
  }
  REQUIRE(s0 == Status::kOk);
  REQUIRE(s1 == Status::kOk);
  REQUIRE(s2 == Status::kOk);
  REQUIRE(s3 == Status::kOk);
  CHECK(allocations == 0);
}

SCENARIO("the CRPF runs on a model without noise_gain() and plugs into the Tracker", "[crpf][tracker]") {
  using Ca = kestrel::ConstantAcceleration2D<float>;
  using CaRadar = kestrel::PolarRadar<Ca>;
  using F = kestrel::Crpf<Ca, CaRadar, 32>;
  STATIC_REQUIRE(!kestrel::HasNoiseGain<Ca>);
  STATIC_REQUIRE(F::kKickDim == 6);
  STATIC_REQUIRE(kestrel::TrackingFilter<F>);
  STATIC_REQUIRE(kestrel::TrackingFilter<Crpf<100>>);
  Ca ca;
  ca.qj = 1.0f;
  CaRadar radar;
  radar.sigma_range_m = 3.0f;
  radar.sigma_bearing_rad = 0.005f;
  F f(ca, radar);
  F::State x0;
  x0 << 1000.0f, 10.0f, 0.0f, 1000.0f, 5.0f, 0.0f;
  REQUIRE(f.reset(x0, F::Cov::Identity() * 25.0f) == Status::kOk);
  REQUIRE(f.predict(1.0f) == Status::kOk);
  REQUIRE(f.update(F::MeasVec(std::hypot(1010.0f, 1005.0f), std::atan2(1005.0f, 1010.0f))) == Status::kOk);
  CHECK(std::hypot(f.x()(0) - 1010.0f, f.x()(3) - 1005.0f) < 15.0f);
}

SCENARIO("a CRPF whose cloud covariance is singular refuses the step unless told not to",
         "[crpf][status][pd]") {
  GIVEN("a prior with no spread in velocity: the drawn cloud's covariance has rank 2 of 4") {
    Motion motion;
    motion.sa = 0.1;
    const Eigen::Vector4d x0(1000.0, 10.0, 1000.0, 5.0);
    const Eigen::Matrix4d P0 = Eigen::Vector4d(100.0, 0.0, 100.0, 0.0).asDiagonal();
    WHEN("positive definiteness is required (the default, what a tracker needs)") {
      kestrel::CrpfConfig<double> params;
      params.seed = 3;
      Crpf<64> f(motion, middle_radar(), params);
      const Eigen::Vector4d x_before = f.x();
      const Eigen::Matrix4d P_before = f.P();
      THEN("reset is refused and x() and P() are as before") {
        CHECK(f.reset(x0, P0) == Status::kNotPositiveDefinite);
        CHECK(f.x() == x_before);
        CHECK(f.P() == P_before);
      }
    }
    WHEN("it is not (paper 001's scoring of the estimate)") {
      kestrel::CrpfConfig<double> params;
      params.seed = 3;
      params.refuse_indefinite = false;
      Crpf<64> f(motion, middle_radar(), params);
      THEN("reset takes the cloud") {
        CHECK(f.reset(x0, P0) == Status::kOk);
        CHECK(f.x()(1) == 10.0);
      }
    }
  }
}
