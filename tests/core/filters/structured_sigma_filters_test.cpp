// SPDX-License-Identifier: Apache-2.0
// The closed-form time update of the sigma-point filters on an affine
// (block-diagonal) motion model (filters/sigma_points.hpp) against
// the point form on the same models with their structure hidden
// (Dense<M>), the oracle: UKF, CDKF, SR-UKF and SR-CDKF, on CA-2D over an
// S1 run and on CV-2D over an MC-001-like run, both with the polar radar;
// state and covariance after every predict and every update, innovations,
// the explicit-Q overload, refused input, float, and no heap.
//
// Tolerance: 1e-9 relative in double (max_relative_*_diff of
// sigma_test_support.hpp: a state entry against its standard deviation, a
// covariance entry against sqrt(P_ii P_jj)). The two forms are equal in
// exact arithmetic; they differ by round-off of different sums (the point
// form's x +- c L then f then differences cancels most of the digits of
// x, which is ~1e4 here against sqrt(P_ii) ~ 1..100).
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#include "core/filters/sigma_test_support.hpp"
#include "kestrel/filters/sigma_point_filter.hpp"
#include "kestrel/filters/sr_sigma_point_filter.hpp"
#include "kestrel/filters/structure.hpp"
#include "kestrel/math/prng.hpp"
#include "kestrel/models/measurement/polar_radar.hpp"
#include "kestrel/models/motion/constant_acceleration_2d.hpp"
#include "kestrel/models/motion/constant_velocity_2d.hpp"
#include "support/alloc_guard.hpp"

namespace {

using kestrel::Dense;
using kestrel::Status;
using kestrel::test::max_relative_cov_diff;
using kestrel::test::max_relative_state_diff;

constexpr double kTol = 1e-9;

// The filter templates as types, for TEMPLATE_TEST_CASE.
struct UkfT {
  template <class M, class H>
  using F = kestrel::Ukf<M, H>;
};
struct CdkfT {
  template <class M, class H>
  using F = kestrel::Cdkf<M, H>;
};
struct SrUkfT {
  template <class M, class H>
  using F = kestrel::SrUkf<M, H>;
};
struct SrCdkfT {
  template <class M, class H>
  using F = kestrel::SrCdkf<M, H>;
};

/// One measurement frame: time step and polar plot.
struct Frame {
  double dt;
  Eigen::Vector2d z;
};

/// S1 (docs/scenarios.md): zig-zag target, T = 0.5 s, sr 3 m, sb 0.3 deg, seeded.
std::vector<Frame> s1_frames(int n) {
  using kestrel::test::S1Truth;
  kestrel::NormalGenerator<double> noise(23);
  std::vector<Frame> out;
  for (int k = 1; k <= n; ++k) {
    double x, y, vx, vy;
    S1Truth::at(0.5 * k, x, y, vx, vy);
    out.push_back(Frame{0.5, kestrel::test::polar_measurement(x, y, 3.0, 0.3 * kestrel::test::kPi / 180.0, noise)});
  }
  return out;
}

/// MC-001-like (docs/scenarios.md): CV-2D truth with white acceleration 0.1 m/s^2,
/// T = 1 s, sr 1 m, sb 0.002 rad (the CV cases of the campaign).
std::vector<Frame> mc001_frames(int n) {
  kestrel::NormalGenerator<double> noise(41);
  const auto xs = kestrel::test::mc001_truth(n, 0.1, noise);
  std::vector<Frame> out;
  for (int k = 1; k <= n; ++k) {
    out.push_back(Frame{1.0, kestrel::test::polar_measurement(xs[static_cast<std::size_t>(k)](0),
                                                              xs[static_cast<std::size_t>(k)](2), 1.0, 0.002, noise)});
  }
  return out;
}

/// CA-2D (qj 16) or CV-2D (sa 0.1) with the polar radar of its run.
template <class F>
F make_filter() {
  using S = typename F::Scalar;
  typename F::MotionModel m{};
  typename F::MeasurementModel r{};
  if constexpr (F::kStateDim == 6) {
    m.qj = S(16);
    r.sigma_range_m = S(3);
    r.sigma_bearing_rad = static_cast<S>(0.3 * kestrel::test::kPi / 180.0);
  } else {
    m.sa = S(0.1);
    r.sigma_range_m = S(1);
    r.sigma_bearing_rad = S(0.002);
  }
  return F(m, r);
}

/// A start away from the truth, with a diagonal P.
template <class F>
void start(F& f) {
  using S = typename F::Scalar;
  typename F::State x;
  typename F::Cov P = F::Cov::Zero();
  if constexpr (F::kStateDim == 6) {
    x << S(-14940), S(185), S(0), S(7960), S(135), S(0);
    P.diagonal() << S(1e4), S(900), S(100), S(1e4), S(900), S(100);
  } else {
    x << S(1010), S(8), S(995), S(6);
    P.diagonal() << S(100), S(25), S(100), S(25);
  }
  REQUIRE(f.reset(x, P) == Status::kOk);
}

struct Worst {
  double x = 0.0;
  double P = 0.0;
  double innov = 0.0;
  void state(const auto& a, const auto& b) {
    x = std::max(x, max_relative_state_diff(a.x(), b.x(), b.P()));
    P = std::max(P, max_relative_cov_diff(a.P(), b.P()));
  }
};

/// Structured and dense forms of Filter on Motion + polar radar, run side by
/// side over `frames`; the worst differences after every predict and update.
template <class Tag, class Motion>
Worst compare_forms(const std::vector<Frame>& frames) {
  using Radar = kestrel::PolarRadar<Motion>;
  using Structured = typename Tag::template F<Motion, Radar>;
  using DenseF = typename Tag::template F<Dense<Motion>, Dense<Radar>>;
  STATIC_REQUIRE(Structured::kAffinePredict);
  STATIC_REQUIRE_FALSE(DenseF::kAffinePredict);
  auto s = make_filter<Structured>();
  auto d = make_filter<DenseF>();
  start(s);
  start(d);
  Worst w;
  for (const Frame& f : frames) {
    REQUIRE(s.predict(f.dt) == Status::kOk);
    REQUIRE(d.predict(f.dt) == Status::kOk);
    w.state(s, d);
    const auto is = s.innovation(f.z);
    const auto id = d.innovation(f.z);
    REQUIRE(is.status == Status::kOk);
    REQUIRE(id.status == Status::kOk);
    w.innov = std::max(w.innov, std::abs(is.d2 - id.d2) / std::max(1.0, id.d2));
    w.innov = std::max(w.innov, max_relative_cov_diff(is.S, id.S));
    REQUIRE(s.update(f.z) == Status::kOk);
    REQUIRE(d.update(f.z) == Status::kOk);
    w.state(s, d);
  }
  return w;
}

}  // namespace

TEMPLATE_TEST_CASE("Scenario: structured sigma-point filters equal their dense form to 1e-9 (double)",
                   "[structured][sigma]", UkfT, CdkfT, SrUkfT, SrCdkfT) {
  GIVEN("CA-2D + polar radar over 299 S1 frames") {
    const Worst w = compare_forms<TestType, kestrel::ConstantAcceleration2D<double>>(s1_frames(299));
    THEN("x, P (after every predict and update) and the innovations agree") {
      INFO("worst relative: x " << w.x << ", P " << w.P << ", innovation " << w.innov);
      CHECK(w.x < kTol);
      CHECK(w.P < kTol);
      CHECK(w.innov < kTol);
    }
  }
  GIVEN("CV-2D + polar radar over 200 MC-001-like frames") {
    const Worst w = compare_forms<TestType, kestrel::ConstantVelocity2D<double>>(mc001_frames(200));
    THEN("x, P and the innovations agree") {
      INFO("worst relative: x " << w.x << ", P " << w.P << ", innovation " << w.innov);
      CHECK(w.x < kTol);
      CHECK(w.P < kTol);
      CHECK(w.innov < kTol);
    }
  }
}

TEMPLATE_TEST_CASE("Scenario: the explicit-Q predict takes the closed form too", "[structured][sigma]", UkfT, CdkfT,
                   SrUkfT, SrCdkfT) {
  using Motion = kestrel::ConstantAcceleration2D<double>;
  using Radar = kestrel::PolarRadar<Motion>;
  auto s = make_filter<typename TestType::template F<Motion, Radar>>();
  auto d = make_filter<typename TestType::template F<Dense<Motion>, Dense<Radar>>>();
  start(s);
  start(d);
  // A Q coupling the axes (the adaptive filters' rotated form): the closed
  // form must add it whole, not per block.
  const auto Q1 = s.motion().axis_process_noise(0.5);
  kestrel::Mat<double, 2, 2> M;
  M << 30.0, 12.0, 12.0, 5.0;
  Motion::Cov Q;
  for (int a = 0; a < 2; ++a) {
    for (int b = 0; b < 2; ++b) Q.block<3, 3>(3 * a, 3 * b) = M(a, b) * Q1;
  }
  Worst w;
  for (const Frame& f : s1_frames(60)) {
    REQUIRE(s.predict(0.5, Q) == Status::kOk);
    REQUIRE(d.predict(0.5, Q) == Status::kOk);
    w.state(s, d);
    REQUIRE(s.update(f.z) == Status::kOk);
    REQUIRE(d.update(f.z) == Status::kOk);
    w.state(s, d);
  }
  INFO("worst relative: x " << w.x << ", P " << w.P);
  CHECK(w.x < kTol);
  CHECK(w.P < kTol);
}

TEMPLATE_TEST_CASE("Scenario: a structured predict refuses bad input and keeps its state", "[structured][sigma]",
                   UkfT, CdkfT, SrUkfT, SrCdkfT) {
  using Motion = kestrel::ConstantAcceleration2D<double>;
  auto s = make_filter<typename TestType::template F<Motion, kestrel::PolarRadar<Motion>>>();
  start(s);
  const auto x0 = s.x();
  const auto P0 = s.P();
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(s.predict(inf) == Status::kNonFinite);
  Motion::Cov Q = Motion::Cov::Zero();
  Q(2, 2) = std::numeric_limits<double>::quiet_NaN();
  CHECK(s.predict(0.5, Q) == Status::kNonFinite);
  CHECK(s.x() == x0);
  CHECK(s.P() == P0);
}

namespace {

struct FloatErrors {
  double structured = 0.0;  ///< Structured float against dense double.
  double dense = 0.0;       ///< Dense float against dense double.
  double between = 0.0;     ///< Structured float against dense float.
};

/// Structured float, dense float and dense double (the reference) of
/// Filter on Motion<.> + polar radar over `frames` (measurements rounded to
/// float for all three); worst relative state differences.
template <class Tag, template <class> class Motion>
FloatErrors compare_float(const std::vector<Frame>& frames) {
  using MF = Motion<float>;
  using MD = Motion<double>;
  auto sf = make_filter<typename Tag::template F<MF, kestrel::PolarRadar<MF>>>();
  auto df = make_filter<typename Tag::template F<Dense<MF>, Dense<kestrel::PolarRadar<MF>>>>();
  auto ref = make_filter<typename Tag::template F<Dense<MD>, Dense<kestrel::PolarRadar<MD>>>>();
  start(sf);
  start(df);
  start(ref);
  FloatErrors e;
  for (const Frame& f : frames) {
    const kestrel::Vec<float, 2> zf(static_cast<float>(f.z(0)), static_cast<float>(f.z(1)));
    const auto dtf = static_cast<float>(f.dt);
    REQUIRE(sf.predict(dtf) == Status::kOk);
    REQUIRE(df.predict(dtf) == Status::kOk);
    REQUIRE(ref.predict(double(dtf)) == Status::kOk);
    REQUIRE(sf.update(zf) == Status::kOk);
    REQUIRE(df.update(zf) == Status::kOk);
    REQUIRE(ref.update(kestrel::Vec<double, 2>(double(zf(0)), double(zf(1)))) == Status::kOk);
    e.structured = std::max(e.structured, max_relative_state_diff(sf.x(), ref.x(), ref.P()));
    e.dense = std::max(e.dense, max_relative_state_diff(df.x(), ref.x(), ref.P()));
    e.between = std::max(e.between, max_relative_state_diff(sf.x(), df.x(), df.P()));
  }
  return e;
}

// Both float forms are float round-off of the same filter: the structured
// form must not be worse than the point form by more than round-off noise,
// and the two stay within 1e-3 relative of each other (a thousandth of a
// standard deviation where an entry is near zero).
void check_float(const FloatErrors& e) {
  INFO("float structured " << e.structured << ", float dense " << e.dense << " (relative to double); structured vs "
                           << "dense " << e.between);
  CHECK(e.structured <= 2.0 * e.dense + 1e-4);
  CHECK(e.between < 1e-3);
}

}  // namespace

TEMPLATE_TEST_CASE("Scenario: structured float is no worse than dense float against double",
                   "[structured][sigma][float]", UkfT, CdkfT, SrUkfT, SrCdkfT) {
  GIVEN("CV-2D + polar radar over 200 MC-001-like frames") {
    check_float(compare_float<TestType, kestrel::ConstantVelocity2D>(mc001_frames(200)));
  }
  // CA-2D on S1 in float: the plain forms only. Both square-root forms,
  // dense and structured alike, refuse an early update of this run in float
  // (the rank-1 downdate of Sx reports kNotPositiveDefinite): a limit of the
  // square-root forms in float, not of the closed-form predict.
  if constexpr (std::is_same_v<TestType, UkfT> || std::is_same_v<TestType, CdkfT>) {
    GIVEN("CA-2D + polar radar over 299 S1 frames") {
      check_float(compare_float<TestType, kestrel::ConstantAcceleration2D>(s1_frames(299)));
    }
  }
}

TEMPLATE_TEST_CASE("Scenario: a structured sigma-point step allocates nothing", "[structured][sigma][alloc]", UkfT,
                   CdkfT, SrUkfT, SrCdkfT) {
  using Motion = kestrel::ConstantAcceleration2D<double>;
  auto s = make_filter<typename TestType::template F<Motion, kestrel::PolarRadar<Motion>>>();
  start(s);
  const std::vector<Frame> frames = s1_frames(20);
  std::size_t allocations = 1;
  bool ok = true;
  {
    kestrel::test::AllocationGuard guard;
    for (const Frame& f : frames) {
      ok = ok && s.predict(f.dt) == Status::kOk;
      ok = ok && s.innovation(f.z).status == Status::kOk;
      ok = ok && s.update(f.z) == Status::kOk;
    }
    allocations = guard.allocations();
  }
  CHECK(ok);
  CHECK(allocations == 0);
}
