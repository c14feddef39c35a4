// SPDX-License-Identifier: Apache-2.0
// The EKF's sequential whitened update (the fixed-point form): in double it
// equals the batch Cholesky update; on the fixed-point scalar it follows the
// double filter, keeps the commit-on-success contract, and refuses a step
// that saturates instead of wrapping.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "kestrel/filters/ekf.hpp"
#include "kestrel/models/measurement/polar_radar.hpp"
#include "kestrel/models/motion/constant_acceleration_2d.hpp"
#include "kestrel/scalar/fixed_point_eigen.hpp"
#include "kestrel/scalar/fixed_point_io.hpp"
#include "support/alloc_guard.hpp"

namespace {

using kestrel::EkfUpdateForm;
using kestrel::Status;

template <class S>
using Motion = kestrel::ConstantAcceleration2D<S>;
template <class S>
using Radar = kestrel::PolarRadar<Motion<S>>;
template <class S, EkfUpdateForm kForm = kestrel::kDefaultEkfUpdateForm<S>>
using RadarEkf = kestrel::Ekf<Motion<S>, Radar<S>, kForm>;

/// Linear sensor with correlated noise: exercises the Cholesky whitening.
template <class S>
struct CorrelatedPosition {
  using Scalar = S;
  static constexpr int kStateDim = 6;
  static constexpr int kMeasDim = 2;
  using Measurement = kestrel::Vec<S, 2>;
  using Jacobian = kestrel::Mat<S, 2, 6>;
  using NoiseCov = kestrel::Mat<S, 2, 2>;
  Measurement predict(const typename Motion<S>::State& x) const { return Measurement(x(0) + x(3), x(3)); }
  Jacobian jacobian(const typename Motion<S>::State&) const {
    Jacobian H = Jacobian::Zero();
    H(0, 0) = 1;
    H(0, 3) = 1;
    H(1, 3) = 1;
    return H;
  }
  NoiseCov noise() const {
    NoiseCov R;
    R << S(25), S(12), S(12), S(16);
    return R;
  }
  Measurement residual(const Measurement& z, const Measurement& zh) const { return z - zh; }
};

template <class S, EkfUpdateForm kForm>
using LinearEkf = kestrel::Ekf<Motion<S>, CorrelatedPosition<S>, kForm>;

template <class Filter>
Filter make_radar_filter() {
  using S = typename Filter::Scalar;
  using T = kestrel::ScalarTraits<S>;
  Motion<S> motion;
  motion.qj = T::from_double(16.0);
  Radar<S> radar;
  radar.sigma_range_m = S(3);
  radar.sigma_bearing_rad = T::from_double(0.3 * 3.14159265358979323846 / 180);
  return Filter(motion, radar);
}

/// A random track state near S1's geometry and a random SPD covariance.
template <class State, class Cov>
void random_state(std::mt19937_64& g, State& x, Cov& P) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::Matrix<double, 6, 6> A;
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) A(i, j) = u(g);
  }
  const Eigen::Matrix<double, 6, 1> scale(200, 30, 5, 200, 30, 5);
  const Eigen::Matrix<double, 6, 6> Pd =
      scale.asDiagonal() * (A * A.transpose() + Eigen::Matrix<double, 6, 6>::Identity()) * scale.asDiagonal();
  Eigen::Matrix<double, 6, 1> xd;
  xd << -15000 + 3000 * u(g), 200 + 20 * u(g), 5 * u(g), 8000 + 3000 * u(g), 120 + 20 * u(g), 5 * u(g);
  using S = typename State::Scalar;
  for (int i = 0; i < 6; ++i) {
    x(i) = kestrel::ScalarTraits<S>::from_double(xd(i));
    for (int j = 0; j < 6; ++j) P(i, j) = kestrel::ScalarTraits<S>::from_double(Pd(i, j));
  }
}

double rel_diff(double a, double b, double scale) { return std::fabs(a - b) / scale; }

}  // namespace

SCENARIO("in double the sequential whitened update equals the batch update", "[ekf][sequential]") {
  std::mt19937_64 g(3);
  std::normal_distribution<double> n(0.0, 1.0);
  GIVEN("the polar radar with random states, covariances and measurements") {
    using Batch = RadarEkf<double, EkfUpdateForm::kBatch>;
    using Seq = RadarEkf<double, EkfUpdateForm::kSequentialWhitened>;
    STATIC_REQUIRE(Batch::kUpdateForm == EkfUpdateForm::kBatch);
    STATIC_REQUIRE(RadarEkf<double>::kUpdateForm == EkfUpdateForm::kBatch);
    STATIC_REQUIRE(RadarEkf<kestrel::Q31_32>::kUpdateForm == EkfUpdateForm::kSequentialWhitened);
    double worst_x = 0, worst_P = 0, worst_nis = 0, worst_d2 = 0;
    for (int trial = 0; trial < 200; ++trial) {
      Batch batch = make_radar_filter<Batch>();
      Seq seq = make_radar_filter<Seq>();
      Batch::State x;
      Batch::Cov P;
      random_state(g, x, P);
      REQUIRE(batch.reset(x, P) == Status::kOk);
      REQUIRE(seq.reset(x, P) == Status::kOk);
      const Batch::MeasVec zh = batch.measurement().predict(x);
      const double n_bearing = n(g);  // own statements: argument order is unspecified
      const double n_range = n(g);
      const Batch::MeasVec z(zh(0) + 30 * n_range, zh(1) + 0.01 * n_bearing);
      const auto in_b = batch.innovation(z);
      const auto in_s = seq.innovation(z);
      REQUIRE(batch.update(z) == Status::kOk);
      REQUIRE(seq.update(z) == Status::kOk);
      const double px = P.diagonal().cwiseSqrt().maxCoeff();
      for (int i = 0; i < 6; ++i) {
        worst_x = std::max(worst_x, rel_diff(batch.x()(i), seq.x()(i), px));
        for (int j = 0; j < 6; ++j) worst_P = std::max(worst_P, rel_diff(batch.P()(i, j), seq.P()(i, j), P.norm()));
      }
      worst_nis = std::max(worst_nis, rel_diff(batch.diagnostics().nis, seq.diagnostics().nis, 1 + batch.diagnostics().nis));
      worst_d2 = std::max(worst_d2, rel_diff(in_b.d2, in_s.d2, 1 + in_b.d2));
      CHECK(seq.diagnostics().innovation_variance.isApprox(batch.diagnostics().innovation_variance, 1e-12));
      CHECK((seq.P() - seq.P().transpose()).cwiseAbs().maxCoeff() == 0.0);
    }
    THEN("x, P, the NIS and the gate's d2 agree to round-off (1e-9 relative)") {
      // Both are exact rewrites of the same Bayes update; the residual
      // differences are double round-off amplified by the conditioning of S.
      CHECK(worst_x <= 1e-9);
      CHECK(worst_P <= 1e-9);
      CHECK(worst_nis <= 1e-9);
      CHECK(worst_d2 <= 1e-9);
    }
  }
  GIVEN("a sensor with correlated noise (non-diagonal R)") {
    using Batch = LinearEkf<double, EkfUpdateForm::kBatch>;
    using Seq = LinearEkf<double, EkfUpdateForm::kSequentialWhitened>;
    Motion<double> motion;
    motion.qj = 1.6;
    Batch batch(motion, {});
    Seq seq(motion, {});
    Batch::State x;
    Batch::Cov P;
    random_state(g, x, P);
    REQUIRE(batch.reset(x, P) == Status::kOk);
    REQUIRE(seq.reset(x, P) == Status::kOk);
    for (int k = 0; k < 20; ++k) {
      REQUIRE(batch.predict(0.5) == Status::kOk);
      REQUIRE(seq.predict(0.5) == Status::kOk);
      const double n_bearing = n(g);  // own statements: argument order is unspecified
      const double n_range = n(g);
      const Batch::MeasVec z = batch.measurement().predict(batch.x()) + Batch::MeasVec(5 * n_range, 4 * n_bearing);
      REQUIRE(batch.update(z) == Status::kOk);
      REQUIRE(seq.update(z) == Status::kOk);
    }
    THEN("the whitened sequential filter tracks the batch filter to round-off") {
      CHECK((batch.x() - seq.x()).cwiseAbs().maxCoeff() <= 1e-8 * batch.x().cwiseAbs().maxCoeff());
      CHECK((batch.P() - seq.P()).cwiseAbs().maxCoeff() <= 1e-9 * batch.P().cwiseAbs().maxCoeff());
    }
  }
}

TEMPLATE_TEST_CASE("Scenario: the fixed-point EKF follows the double EKF", "[ekf][fixed_point]", kestrel::Q31_32,
                   kestrel::Q23_40) {
  using Q = TestType;
  using QEkf = RadarEkf<Q>;
  using DEkf = RadarEkf<double>;
  std::mt19937_64 g(17);
  std::normal_distribution<double> n(0.0, 1.0);
  kestrel::reset_fixed_point_overflow_count();
  GIVEN("a target flying a straight line measured 200 times") {
    QEkf q = make_radar_filter<QEkf>();
    DEkf d = make_radar_filter<DEkf>();
    DEkf::State x0;
    x0 << -15000, 200, 0, 8000, 125, 0;
    DEkf::Cov P0 = DEkf::Cov::Identity() * 100;
    typename QEkf::State qx0;
    typename QEkf::Cov qP0;
    for (int i = 0; i < 6; ++i) {
      qx0(i) = Q::from_double(x0(i));
      for (int j = 0; j < 6; ++j) qP0(i, j) = Q::from_double(P0(i, j));
    }
    REQUIRE(q.reset(qx0, qP0) == Status::kOk);
    REQUIRE(d.reset(x0, P0) == Status::kOk);
    double worst = 0;
    std::size_t allocations = 0;
    for (int k = 1; k <= 200; ++k) {
      const double t = 0.5 * k;
      const double px = -15000 + 200 * t, py = 8000 + 125 * t;
      // Measurements enter as integers (mm, binary angle), as at the HAL.
      const auto range_mm = static_cast<std::int64_t>(std::llround((std::hypot(px, py) + 3 * n(g)) * 1000));
      const auto bam = static_cast<std::int64_t>(
          std::llround((std::atan2(py, px) + 0.005 * n(g)) / 3.14159265358979323846 * 2147483648.0));
      using TQ = kestrel::ScalarTraits<Q>;
      const typename QEkf::MeasVec zq(TQ::from_ratio(range_mm, 1000), TQ::from_ratio(bam, 2147483648LL) * TQ::pi());
      const DEkf::MeasVec zd(static_cast<double>(range_mm) / 1000,
                             static_cast<double>(bam) / 2147483648.0 * 3.14159265358979323846);
      {
        kestrel::test::AllocationGuard guard;
        REQUIRE(q.predict(Q(0.5)) == Status::kOk);
        REQUIRE(q.update(zq) == Status::kOk);
        allocations += guard.allocations();
      }
      REQUIRE(d.predict(0.5) == Status::kOk);
      REQUIRE(d.update(zd) == Status::kOk);
      worst = std::max(worst, std::hypot(static_cast<double>(q.x()(0)) - d.x()(0), static_cast<double>(q.x()(3)) - d.x()(3)));
    }
    THEN("the position stays within 1 mm of the double filter, with no overflow and no allocation") {
      INFO("largest position deviation: " << worst << " m");
      CHECK(worst <= 1e-3);
      CHECK(kestrel::fixed_point_overflow_count() == 0);
      CHECK(allocations == 0);
      AND_THEN("P is exactly symmetric and positive definite") {
        const auto Pd = q.P().template cast<double>().eval();
        CHECK(q.P() == q.P().transpose());
        CHECK(Eigen::LLT<Eigen::Matrix<double, 6, 6>>(Pd).info() == Eigen::Success);
      }
    }
  }
}

TEMPLATE_TEST_CASE("Scenario: the fixed-point EKF refuses bad steps and keeps its state", "[ekf][fixed_point][status]",
                   kestrel::Q31_32, kestrel::Q23_40) {
  using Q = TestType;
  using QEkf = RadarEkf<Q>;
  QEkf ekf = make_radar_filter<QEkf>();
  typename QEkf::State x0;
  x0 << Q(-1500), Q(20), Q(0), Q(800), Q(12), Q(0);
  REQUIRE(ekf.reset(x0, QEkf::Cov::Identity() * Q(100)) == Status::kOk);
  const auto x_before = ekf.x();
  const auto P_before = ekf.P();
  GIVEN("a target on the radar itself (r = 0)") {
    REQUIRE(ekf.reset(QEkf::State::Zero(), QEkf::Cov::Identity()) == Status::kOk);
    THEN("the Jacobian saturates and update refuses with kNonFinite") {
      CHECK(ekf.update(typename QEkf::MeasVec(Q(10), Q(0))) == Status::kNonFinite);
      CHECK(ekf.x() == QEkf::State::Zero());
      CHECK_FALSE(ekf.diagnostics().fused);
    }
  }
  GIVEN("a measurement noise that is not positive definite") {
    typename QEkf::MeasCov R = QEkf::MeasCov::Zero();
    R(0, 0) = Q(-4);
    R(1, 1) = Q(1);
    THEN("update and innovation return kNotPositiveDefinite and x, P are unchanged") {
      CHECK(ekf.update(typename QEkf::MeasVec(Q(1700), Q(2.6)), R) == Status::kNotPositiveDefinite);
      CHECK(ekf.innovation(typename QEkf::MeasVec(Q(1700), Q(2.6)), R).status == Status::kNotPositiveDefinite);
      CHECK(ekf.x() == x_before);
      CHECK(ekf.P() == P_before);
    }
  }
  GIVEN("a saturated measurement") {
    const Q inf = Q::from_raw(INT64_MAX);
    THEN("update refuses with kNonFinite") {
      CHECK(ekf.update(typename QEkf::MeasVec(inf, Q(0))) == Status::kNonFinite);
      CHECK(ekf.x() == x_before);
    }
  }
  GIVEN("a track coasting with no measurement (Q31.32 holds P to about 2e9)") {
    kestrel::reset_fixed_point_overflow_count();
    int steps = 0;
    Status last = Status::kOk;
    typename QEkf::State x_last = ekf.x();
    typename QEkf::Cov P_last = ekf.P();
    for (; steps < 4000; ++steps) {
      x_last = ekf.x();
      P_last = ekf.P();
      last = ekf.predict(Q(1));
      if (last != Status::kOk) break;
    }
    THEN("predict is eventually refused with kNonFinite, never wraps, and keeps the last finite state") {
      INFO("coasting steps of 1 s before the refusal: " << steps);
      CHECK(last == Status::kNonFinite);
      CHECK(kestrel::fixed_point_overflow_count() > 0);
      CHECK(ekf.x() == x_last);
      CHECK(ekf.P() == P_last);
      CHECK(kestrel::all_finite(ekf.P()));
      CHECK(ekf.P()(0, 0) > Q(0));
    }
  }
}
