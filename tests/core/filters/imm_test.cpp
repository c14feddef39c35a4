// SPDX-License-Identifier: Apache-2.0
// IMM: one mode equals that mode's EKF; mode probabilities sum to 1 and
// follow a synthetic manoeuvre to the right model; refused input (NaN, a
// covariance that is not positive definite, a mode that refuses its
// update) leaves it bit-identical; no allocation; float follows double;
// the switching matrix over dt is the configured one at its period, keeps
// p_ii^2 over two periods, and stays stochastic from 1 ms to 100 s.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <type_traits>
#include <vector>

#include "kestrel/filters/ekf.hpp"
#include "kestrel/filters/imm.hpp"
#include "kestrel/filters/imm_radar.hpp"
#include "kestrel/math/positive_definite.hpp"
#include "kestrel/tracking/tracker.hpp"
#include "support/alloc_guard.hpp"

namespace {

using kestrel::Status;
template <class S>
using Ca = kestrel::ConstantAcceleration2D<S>;
template <class S>
using CaRadar = kestrel::PolarRadar<Ca<S>>;

constexpr double kSigmaRange = 3.0;
constexpr double kSigmaBearing = 0.3 * 3.14159265358979323846 / 180.0;

template <class S>
CaRadar<S> ca_radar() {
  CaRadar<S> h;
  h.sigma_range_m = S(kSigmaRange);
  h.sigma_bearing_rad = S(kSigmaBearing);
  return h;
}

/// A plot of the target at (px, py) with seeded noise.
struct Plot {
  double t_s;
  double range_m;
  double bearing_rad;
  double x_m;  ///< truth
  double y_m;  ///< truth
};

/// Straight at 200 m/s heading +x for 30 s, a left turn at 0.1 rad/s
/// (radius 2 km) for 30 s, straight again for 30 s; T = 0.5 s; radar at
/// the origin, plots from 10-17 km.
std::vector<Plot> manoeuvre_plots(unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n01(0.0, 1.0);
  std::vector<Plot> plots;
  double x = -10000.0, y = 10000.0, vx = 200.0, vy = 0.0;
  const double dt = 0.5;
  for (int k = 1; k <= 180; ++k) {
    const double t = k * dt;
    const double w = (t > 30.0 && t <= 60.0) ? 0.1 : 0.0;
    if (w > 0.0) {
      const double a = w * dt;
      const double nx = x + (std::sin(a) * vx - (1 - std::cos(a)) * vy) / w;
      const double ny = y + ((1 - std::cos(a)) * vx + std::sin(a) * vy) / w;
      const double nvx = std::cos(a) * vx - std::sin(a) * vy;
      const double nvy = std::sin(a) * vx + std::cos(a) * vy;
      x = nx, y = ny, vx = nvx, vy = nvy;
    } else {
      x += vx * dt;
      y += vy * dt;
    }
    plots.push_back({t, std::hypot(x, y) + kSigmaRange * n01(rng), std::atan2(y, x) + kSigmaBearing * n01(rng), x, y});
  }
  return plots;
}

template <class S>
typename Ca<S>::Cov initial_cov() {
  return kestrel::Vec<S, 6>(S(400), S(900), S(100), S(400), S(900), S(100)).asDiagonal();
}

template <class S>
typename Ca<S>::State initial_state() {
  typename Ca<S>::State x;
  x << S(-10000), S(200), S(0), S(10000), S(0), S(0);
  return x;
}

/// Mode filter that refuses its update while g_refuse is set (a mode that
/// rejects a plot: non-PD P in float, say).
bool g_refuse = false;
struct RefusingCaMode : kestrel::ImmCaMode<double> {
  using Base = kestrel::ImmCaMode<double>;
  using Base::Base;
  [[nodiscard]] Status update(const MeasVec& z) {
    if (g_refuse) return Status::kNotPositiveDefinite;
    return Base::update(z);
  }
};

template <class F>
bool same_bits(const F& a, const F& b) {
  const auto eq = [](const auto& m1, const auto& m2) {
    return std::memcmp(m1.data(), m2.data(), sizeof(typename std::decay_t<decltype(m1)>::Scalar) *
                                                 static_cast<std::size_t>(m1.size())) == 0;
  };
  return eq(a.x(), b.x()) && eq(a.P(), b.P()) && eq(a.common_x(), b.common_x()) && eq(a.common_P(), b.common_P()) &&
         eq(a.mode_probabilities(), b.mode_probabilities()) &&
         eq(a.mixing_probabilities(), b.mixing_probabilities());
}

/// Mean mode probabilities over t in (t0, t1].
struct ModeMeans {
  double cv = 0, ca = 0, ct = 0;
};

template <class S>
struct ImmRun {
  std::vector<double> t;
  std::vector<kestrel::Vec<double, 3>> mu;
  std::vector<double> err_m;
  bool always_valid = true;
  ModeMeans mean(double t0, double t1) const {
    ModeMeans m;
    int n = 0;
    for (std::size_t k = 0; k < t.size(); ++k) {
      if (t[k] > t0 && t[k] <= t1) {
        m.cv += mu[k](0), m.ca += mu[k](1), m.ct += mu[k](2);
        ++n;
      }
    }
    m.cv /= n, m.ca /= n, m.ct /= n;
    return m;
  }
};

template <class S>
ImmRun<S> run_imm(const std::vector<Plot>& plots) {
  kestrel::RadarImmParams p;
  auto imm = kestrel::make_radar_imm<S>(p);
  REQUIRE(imm.reset(initial_state<S>(), initial_cov<S>()) == Status::kOk);
  ImmRun<S> out;
  for (const Plot& pl : plots) {
    REQUIRE(imm.predict(S(0.5)) == Status::kOk);
    const typename decltype(imm)::MeasVec z(S(pl.range_m), S(pl.bearing_rad));
    REQUIRE(imm.update(z) == Status::kOk);
    const auto& mu = imm.mode_probabilities();
    out.t.push_back(pl.t_s);
    out.mu.push_back(mu.template cast<double>());
    out.err_m.push_back(std::hypot(double(imm.x()(0)) - pl.x_m, double(imm.x()(3)) - pl.y_m));
    // Probabilities sum to 1 (to float round-off), every one >= the floor,
    // and the combined covariance is positive definite.
    if (std::abs(double(mu.sum()) - 1.0) > 1e-5) out.always_valid = false;
    if (double(mu.minCoeff()) < 0.99 * p.min_probability) out.always_valid = false;
    if (!kestrel::is_positive_definite(imm.P()) || !kestrel::is_positive_definite(imm.common_P())) {
      out.always_valid = false;
    }
    for (int j = 0; j < 3; ++j) {
      if (std::abs(double(imm.mixing_probabilities().col(j).sum()) - 1.0) > 1e-5) out.always_valid = false;
    }
  }
  return out;
}

}  // namespace

SCENARIO("The radar IMM is a tracking filter", "[imm]") {
  STATIC_REQUIRE(kestrel::TrackingFilter<kestrel::RadarImm<double>>);
  STATIC_REQUIRE(kestrel::TrackingFilter<kestrel::RadarImm<float>>);
  STATIC_REQUIRE(kestrel::PredictsMeasurement<kestrel::RadarImm<double>>);
  STATIC_REQUIRE(kestrel::RadarImm<double>::kModes == 3);
  STATIC_REQUIRE(kestrel::RadarImm<double>::kStateDim == 6);
  STATIC_REQUIRE(kestrel::RadarImm<double>::kCommonDim == 7);
  CHECK(kestrel::RadarImm<double>::Config{}.valid());
}

SCENARIO("An IMM with one mode equals that mode's EKF", "[imm]") {
  using Mode = kestrel::ImmCaMode<double>;
  using One = kestrel::Imm<Ca<double>, CaRadar<double>, Mode>;
  Ca<double> ca;
  ca.qj = 50.0;
  Mode ekf(ca, ca_radar<double>());
  One imm(ca_radar<double>(), One::Config{}, ekf);
  REQUIRE(ekf.reset(initial_state<double>(), initial_cov<double>()) == Status::kOk);
  REQUIRE(imm.reset(initial_state<double>(), initial_cov<double>()) == Status::kOk);
  const auto plots = manoeuvre_plots(7);
  double worst = 0;
  for (const Plot& pl : plots) {
    const One::MeasVec z(pl.range_m, pl.bearing_rad);
    REQUIRE(ekf.predict(0.5) == Status::kOk);
    REQUIRE(imm.predict(0.5) == Status::kOk);
    const auto gi = imm.innovation(z);
    const auto ge = ekf.innovation(z);
    CHECK(gi.d2 == Approx(ge.d2).epsilon(1e-12));
    REQUIRE(ekf.update(z) == Status::kOk);
    REQUIRE(imm.update(z) == Status::kOk);
    worst = std::max(worst, (imm.x() - ekf.x()).cwiseAbs().maxCoeff() / ekf.x().cwiseAbs().maxCoeff());
    worst = std::max(worst, (imm.P() - ekf.P()).cwiseAbs().maxCoeff() / ekf.P().cwiseAbs().maxCoeff());
    CHECK(imm.mode_probabilities()(0) == 1.0);
  }
  // The mixing and combination with one weight of 1 are exact up to the
  // symmetrisation of P, so the two agree to round-off.
  CHECK(worst < 1e-12);
}

SCENARIO("IMM mode probabilities follow a manoeuvre to the right model", "[imm]") {
  GIVEN("straight flight, a 0.1 rad/s turn from 30 s to 60 s, straight flight again") {
    const auto plots = manoeuvre_plots(3);
    const ImmRun<double> run = run_imm<double>(plots);
    THEN("the probabilities sum to 1, stay above the floor, and every covariance is positive definite") {
      CHECK(run.always_valid);
    }
    THEN("CV leads in the straight legs and CT in the turn") {
      const ModeMeans a = run.mean(15, 30), b = run.mean(40, 60), c = run.mean(75, 90);
      INFO("straight " << a.cv << " " << a.ca << " " << a.ct << "; turn " << b.cv << " " << b.ca << " " << b.ct
                       << "; straight " << c.cv << " " << c.ca << " " << c.ct);
      CHECK(a.cv > a.ca);
      CHECK(a.cv > a.ct);
      CHECK(b.ct > b.cv);
      CHECK(b.ct > b.ca);
      // With p_ii = 0.8 no mode can hold much more than 0.8 after a
      // predict, so the turn is judged against the straight legs: CT's
      // share at least doubles and CV's at least halves.
      CHECK(b.ct > 2 * a.ct);
      CHECK(b.cv < a.cv / 2);
      CHECK(c.cv > c.ct);
      CHECK(c.cv > c.ca);
    }
  }
}

SCENARIO("The IMM in float follows the IMM in double", "[imm][float]") {
  const auto plots = manoeuvre_plots(5);
  const ImmRun<double> d = run_imm<double>(plots);
  const ImmRun<float> f = run_imm<float>(plots);
  CHECK(f.always_valid);
  double worst_mu = 0, worst_err = 0, rms_d = 0;
  for (std::size_t k = 0; k < d.t.size(); ++k) {
    worst_mu = std::max(worst_mu, (f.mu[k] - d.mu[k]).cwiseAbs().maxCoeff());
    worst_err = std::max(worst_err, std::abs(f.err_m[k] - d.err_m[k]));
    rms_d += d.err_m[k] * d.err_m[k];
  }
  rms_d = std::sqrt(rms_d / static_cast<double>(d.t.size()));
  INFO("largest probability difference " << worst_mu << ", largest error difference " << worst_err
                                         << " m, double rms " << rms_d << " m");
  // Float positions at 14 km carry about 1 mm of round-off; the mode
  // likelihoods amplify it through exp, so the bounds are loose but far
  // below the filter's own error.
  CHECK(worst_mu < 0.05);
  CHECK(worst_err < 1.0);
}

SCENARIO("A refused IMM step leaves the filter bit-identical", "[imm]") {
  auto imm = kestrel::make_radar_imm<double>(kestrel::RadarImmParams{});
  REQUIRE(imm.reset(initial_state<double>(), initial_cov<double>()) == Status::kOk);
  const auto plots = manoeuvre_plots(11);
  for (int k = 0; k < 70; ++k) {
    REQUIRE(imm.predict(0.5) == Status::kOk);
    REQUIRE(imm.update({plots[static_cast<std::size_t>(k)].range_m, plots[static_cast<std::size_t>(k)].bearing_rad}) ==
            Status::kOk);
  }
  REQUIRE(imm.predict(0.5) == Status::kOk);
  const auto before = imm;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  WHEN("the plot has a NaN") {
    CHECK(imm.update({nan, 0.5}) == Status::kNonFinite);
    THEN("nothing changed and the diagnostics say so") {
      CHECK(same_bits(imm, before));
      CHECK_FALSE(imm.diagnostics().fused);
      CHECK(imm.diagnostics().status == Status::kNonFinite);
    }
  }
  WHEN("dt is NaN or infinite") {
    CHECK(imm.predict(nan) != Status::kOk);
    CHECK(imm.predict(std::numeric_limits<double>::infinity()) != Status::kOk);
    THEN("nothing changed") { CHECK(same_bits(imm, before)); }
  }
  WHEN("reset gets a covariance that is not positive definite, or a NaN state") {
    auto P = initial_cov<double>();
    P(1, 1) = -1.0;
    CHECK(imm.reset(initial_state<double>(), P) == Status::kNotPositiveDefinite);
    auto x = initial_state<double>();
    x(2) = nan;
    CHECK(imm.reset(x, initial_cov<double>()) == Status::kNonFinite);
    THEN("nothing changed") { CHECK(same_bits(imm, before)); }
  }
}

SCENARIO("An IMM whose mode refuses the update refuses it whole", "[imm]") {
  using Imm = kestrel::Imm<Ca<double>, CaRadar<double>, kestrel::ImmCvMode<double>, RefusingCaMode>;
  kestrel::ConstantVelocity2D<double> cv;
  cv.sa = 1.0;
  kestrel::PolarRadar<kestrel::ConstantVelocity2D<double>> h_cv;
  h_cv.sigma_range_m = kSigmaRange;
  h_cv.sigma_bearing_rad = kSigmaBearing;
  Ca<double> ca;
  ca.qj = 50.0;
  Imm imm(ca_radar<double>(), Imm::Config{}, kestrel::ImmCvMode<double>(cv, h_cv),
          RefusingCaMode(ca, ca_radar<double>()));
  REQUIRE(imm.reset(initial_state<double>(), initial_cov<double>()) == Status::kOk);
  const auto plots = manoeuvre_plots(13);
  REQUIRE(imm.predict(0.5) == Status::kOk);
  REQUIRE(imm.update({plots[0].range_m, plots[0].bearing_rad}) == Status::kOk);
  REQUIRE(imm.predict(0.5) == Status::kOk);
  const auto before = imm;
  g_refuse = true;
  const Status s = imm.update({plots[1].range_m, plots[1].bearing_rad});
  g_refuse = false;
  CHECK(s == Status::kNotPositiveDefinite);
  CHECK(same_bits(imm, before));
  CHECK(imm.update({plots[1].range_m, plots[1].bearing_rad}) == Status::kOk);
}

TEMPLATE_TEST_CASE("Scenario: an IMM predict and update allocate nothing", "[imm][alloc]", double, float) {
  using S = TestType;
  auto imm = kestrel::make_radar_imm<S>(kestrel::RadarImmParams{});
  REQUIRE(imm.reset(initial_state<S>(), initial_cov<S>()) == Status::kOk);
  const auto plots = manoeuvre_plots(17);
  std::size_t allocations = 0;
  Status predicted = Status::kOk, updated = Status::kOk;
  kestrel::Innovation<S, 2> inn;
  {
    kestrel::test::AllocationGuard guard;
    for (int k = 0; k < 20 && predicted == Status::kOk && updated == Status::kOk; ++k) {
      const typename kestrel::RadarImm<S>::MeasVec z(S(plots[static_cast<std::size_t>(k)].range_m),
                                                     S(plots[static_cast<std::size_t>(k)].bearing_rad));
      predicted = imm.predict(S(0.5));
      inn = imm.innovation(z);
      updated = imm.update(z);
    }
    allocations = guard.allocations();
  }
  REQUIRE(predicted == Status::kOk);
  REQUIRE(updated == Status::kOk);
  CHECK(inn.status == Status::kOk);
  CHECK(allocations == 0);
}

namespace {

/// A switching matrix with unequal rows and off-diagonal proportions, so a
/// wrong share of the leaving probability shows.
template <class S>
typename kestrel::ImmConfig<S, 3>::Matrix uneven_switching() {
  typename kestrel::ImmConfig<S, 3>::Matrix m;
  m << S(0.8), S(0.15), S(0.05), S(0.1), S(0.85), S(0.05), S(0.2), S(0.1), S(0.7);
  return m;
}

/// Round-off allowed per entry: a few ulp of the log, exp and share.
template <class S>
double entry_tolerance() {
  return std::is_same_v<S, float> ? 1e-6 : 1e-13;
}

}  // namespace

TEMPLATE_TEST_CASE("Scenario: the switching matrix follows dt by mean sojourn times", "[imm][switching]", double,
                   float) {
  using S = TestType;
  using Config = kestrel::ImmConfig<S, 3>;
  Config params;
  params.switching = uneven_switching<S>();
  params.switching_period_s = S(0.5);
  REQUIRE(params.valid());
  const double tol = entry_tolerance<S>();

  GIVEN("dt equal to the period the matrix is given for") {
    const auto m = params.switching_over(S(0.5));
    THEN("it is the configured matrix bit for bit") {
      CHECK(std::memcmp(m.data(), params.switching.data(), sizeof(S) * 9) == 0);
    }
  }
  GIVEN("dt twice that period") {
    const auto m = params.switching_over(S(1.0));
    THEN("staying is staying twice, p_ii(2 T0) = p_ii(T0)^2, and leaving keeps its proportions") {
      for (int i = 0; i < 3; ++i) {
        const double p = double(params.switching(i, i));
        CHECK(double(m(i, i)) == Approx(p * p).margin(tol));
        for (int j = 0; j < 3; ++j) {
          if (j == i) continue;
          // (1 - p^2) / (1 - p) = 1 + p times the configured entry.
          CHECK(double(m(i, j)) == Approx(double(params.switching(i, j)) * (1.0 + p)).margin(tol));
        }
      }
    }
    THEN("a mode is left more often than over one period, unlike a matrix applied once per predict") {
      for (int i = 0; i < 3; ++i) CHECK(double(m(i, i)) < double(params.switching(i, i)) - 0.1);
    }
  }
  GIVEN("a period of 0") {
    params.switching_period_s = S(0);
    THEN("the matrix applies once per predict whatever dt") {
      const auto m = params.switching_over(S(3.0));
      CHECK(std::memcmp(m.data(), params.switching.data(), sizeof(S) * 9) == 0);
    }
  }
}

TEMPLATE_TEST_CASE("Scenario: the scaled switching matrix stays stochastic from 1 ms to 100 s", "[imm][switching]",
                   double, float) {
  using S = TestType;
  using Config = kestrel::ImmConfig<S, 3>;
  Config params;
  params.switching = uneven_switching<S>();
  params.switching_period_s = S(0.5);
  const double tol = 4 * entry_tolerance<S>();
  double previous_stay[3] = {2, 2, 2};
  int checked = 0;
  // 1e-3 s to 100 s in 101 log-spaced steps, and 0.5 s itself.
  for (int k = 0; k <= 100; ++k) {
    const S dt = S(std::pow(10.0, -3.0 + 5.0 * k / 100.0));
    const auto m = params.switching_over(dt);
    for (int i = 0; i < 3; ++i) {
      double row = 0;
      for (int j = 0; j < 3; ++j) {
        INFO("dt " << double(dt) << " s, entry " << i << j << " = " << double(m(i, j)));
        CHECK(std::isfinite(double(m(i, j))));
        CHECK(double(m(i, j)) >= 0.0);
        CHECK(double(m(i, j)) <= 1.0);
        row += double(m(i, j));
      }
      INFO("dt " << double(dt) << " s, row " << i << " sums to " << row);
      CHECK(row == Approx(1.0).margin(tol));
      // Staying is less likely the longer the step.
      CHECK(double(m(i, i)) <= previous_stay[i]);
      previous_stay[i] = double(m(i, i));
    }
    ++checked;
  }
  CHECK(checked == 101);
  const auto short_step = params.switching_over(S(1e-3));
  const auto long_step = params.switching_over(S(100));
  for (int i = 0; i < 3; ++i) {
    CHECK(double(short_step(i, i)) > 0.999);  // 1 ms: almost surely no switch
    CHECK(double(long_step(i, i)) < 1e-6);    // 100 s = 200 periods: almost surely left
  }
}

TEMPLATE_TEST_CASE("Scenario: an IMM predict over two periods mixes with the matrix over two periods", "[imm][switching]",
                   double, float) {
  using S = TestType;
  kestrel::RadarImmParams p;
  p.switching[0][0] = 0.8, p.switching[0][1] = 0.15, p.switching[0][2] = 0.05;
  p.switching[1][0] = 0.1, p.switching[1][1] = 0.85, p.switching[1][2] = 0.05;
  p.switching[2][0] = 0.2, p.switching[2][1] = 0.1, p.switching[2][2] = 0.7;
  p.initial_probabilities[0] = 0.6, p.initial_probabilities[1] = 0.3, p.initial_probabilities[2] = 0.1;
  auto imm = kestrel::make_radar_imm<S>(p);
  REQUIRE(imm.reset(initial_state<S>(), initial_cov<S>()) == Status::kOk);
  const auto mu0 = imm.mode_probabilities();
  REQUIRE(imm.predict(S(1.0)) == Status::kOk);
  // Without an update the mode probabilities are the predicted c = P(dt)^T mu.
  const auto expected = (imm.params().switching_over(S(1.0)).transpose() * mu0).eval();
  const auto once = (imm.params().switching.transpose() * mu0).eval();
  for (int j = 0; j < 3; ++j) {
    CHECK(double(imm.mode_probabilities()(j)) == Approx(double(expected(j))).margin(1e-6));
  }
  // And that is not what one application of the 0.5 s matrix gives.
  CHECK(std::abs(double(imm.mode_probabilities()(0)) - double(once(0))) > 0.02);
}
