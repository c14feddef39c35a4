// SPDX-License-Identifier: Apache-2.0
// EKF: equals a textbook linear KF on a linear model; refuses bad input and
// leaves its state unchanged; allocation-free.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include <Eigen/LU>

#include "kestrel/filters/ekf.hpp"
#include "kestrel/models/measurement/polar_radar.hpp"
#include "kestrel/models/motion/constant_acceleration_2d.hpp"
#include "support/alloc_guard.hpp"

namespace {

/// Linear test model: measures x and y of a CA-2D state directly.
template <class S>
struct LinearPosition {
  using Scalar = S;
  using Motion = kestrel::ConstantAcceleration2D<S>;
  static constexpr int kStateDim = 6;
  static constexpr int kMeasDim = 2;
  using Measurement = kestrel::Vec<S, 2>;
  using Jacobian = kestrel::Mat<S, 2, 6>;
  using NoiseCov = kestrel::Mat<S, 2, 2>;
  S sigma{};
  Measurement predict(const typename Motion::State& x) const { return Measurement(x(0), x(3)); }
  Jacobian jacobian(const typename Motion::State&) const {
    Jacobian H = Jacobian::Zero();
    H(0, 0) = 1;
    H(1, 3) = 1;
    return H;
  }
  NoiseCov noise() const { return NoiseCov::Identity() * (sigma * sigma); }
  Measurement residual(const Measurement& z, const Measurement& zh) const { return z - zh; }
};

template <class S>
using LinearEkf = kestrel::Ekf<kestrel::ConstantAcceleration2D<S>, LinearPosition<S>>;

}  // namespace

TEMPLATE_TEST_CASE("Scenario: on a linear model the EKF is the textbook Kalman filter", "[ekf]", double, float) {
  using S = TestType;
  kestrel::ConstantAcceleration2D<S> motion;
  motion.qj = S(1.6);
  LinearPosition<S> meas;
  meas.sigma = S(5);
  LinearEkf<S> ekf(motion, meas);
  typename LinearEkf<S>::State x0;
  x0 << S(100), S(10), S(0), S(-50), S(5), S(1);
  typename LinearEkf<S>::Cov P0 = LinearEkf<S>::Cov::Identity() * S(100);
  P0(0, 1) = P0(1, 0) = S(10);
  REQUIRE(ekf.reset(x0, P0) == kestrel::Status::kOk);

  // Reference: the same recursion written out in double with dynamic Eigen,
  // standard (non-Joseph) covariance form P = (I - K H) P, which equals the
  // Joseph form for the optimal gain.
  Eigen::MatrixXd x = x0.template cast<double>();
  Eigen::MatrixXd P = P0.template cast<double>();
  const double T = 0.5;
  const double zs[][2] = {{106.0, -47.0}, {109.5, -44.0}, {116.0, -43.5}, {119.0, -40.0}};
  for (const auto& zv : zs) {
    REQUIRE(ekf.predict(S(T)) == kestrel::Status::kOk);
    REQUIRE(ekf.update(typename LinearEkf<S>::MeasVec(S(zv[0]), S(zv[1]))) == kestrel::Status::kOk);

    const Eigen::MatrixXd F = motion.transition(S(T)).template cast<double>();
    const Eigen::MatrixXd Q = motion.process_noise(S(T)).template cast<double>();
    Eigen::MatrixXd H = Eigen::MatrixXd::Zero(2, 6);
    H(0, 0) = 1;
    H(1, 3) = 1;
    const Eigen::MatrixXd R = Eigen::MatrixXd::Identity(2, 2) * 25.0;
    x = F * x;
    P = F * P * F.transpose() + Q;
    Eigen::Vector2d z(zv[0], zv[1]);
    const Eigen::MatrixXd S_ = H * P * H.transpose() + R;
    const Eigen::MatrixXd K = P * H.transpose() * S_.inverse();
    x = x + K * (z - H * x);
    P = (Eigen::MatrixXd::Identity(6, 6) - K * H) * P;
  }
  // double: round-off of a few products only; float: 24-bit mantissa over
  // four steps with entries up to ~1e2, so 1e-4 relative.
  const double tol = std::is_same_v<S, double> ? 1e-10 : 1e-4;
  for (int i = 0; i < 6; ++i) {
    CHECK(static_cast<double>(ekf.x()(i)) == Approx(x(i)).epsilon(tol).margin(tol));
    for (int j = 0; j < 6; ++j) {
      CHECK(static_cast<double>(ekf.P()(i, j)) == Approx(P(i, j)).epsilon(tol).margin(tol * 10));
    }
  }
  CHECK(ekf.diagnostics().fused);
}

SCENARIO("the EKF refuses bad input and keeps its state", "[ekf][status]") {
  using Motion = kestrel::ConstantAcceleration2D<double>;
  using Radar = kestrel::PolarRadar<Motion>;
  using Filter = kestrel::Ekf<Motion, Radar>;
  Motion motion;
  motion.qj = 1.6;
  Radar radar;
  radar.sigma_range_m = 3;
  radar.sigma_bearing_rad = 0.005;
  Filter ekf(motion, radar);
  Filter::State x0;
  x0 << -15000, 200, 0, 8000, 125, 0;
  REQUIRE(ekf.reset(x0, Filter::Cov::Identity() * 100) == kestrel::Status::kOk);
  const Filter::State x_before = ekf.x();
  const Filter::Cov P_before = ekf.P();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();

  GIVEN("a measurement with NaN") {
    THEN("update returns kNonFinite and x, P are unchanged") {
      CHECK(ekf.update(Filter::MeasVec(nan, 0.5)) == kestrel::Status::kNonFinite);
      CHECK(ekf.x() == x_before);
      CHECK(ekf.P() == P_before);
      CHECK_FALSE(ekf.diagnostics().fused);
    }
  }
  GIVEN("a measurement with Inf") {
    THEN("update returns kNonFinite") {
      CHECK(ekf.update(Filter::MeasVec(17000, inf)) == kestrel::Status::kNonFinite);
      CHECK(ekf.x() == x_before);
    }
  }
  GIVEN("a measurement noise that makes S indefinite") {
    Filter::MeasCov R = Filter::MeasCov::Zero();
    R(0, 0) = -1e9;
    R(1, 1) = 1e-6;
    THEN("update returns kNotPositiveDefinite and x, P are unchanged") {
      CHECK(ekf.update(Filter::MeasVec(17000, 2.6), R) == kestrel::Status::kNotPositiveDefinite);
      CHECK(ekf.x() == x_before);
      CHECK(ekf.P() == P_before);
    }
  }
  GIVEN("a NaN time step") {
    THEN("predict returns kNonFinite and the state is unchanged") {
      CHECK(ekf.predict(nan) == kestrel::Status::kNonFinite);
      CHECK(ekf.x() == x_before);
    }
  }
  GIVEN("a target on the radar itself (r = 0)") {
    Filter::State x_origin = Filter::State::Zero();
    REQUIRE(ekf.reset(x_origin, Filter::Cov::Identity()) == kestrel::Status::kOk);
    THEN("the Jacobian is undefined and update refuses with kNonFinite") {
      CHECK(ekf.update(Filter::MeasVec(10, 0.1)) == kestrel::Status::kNonFinite);
      CHECK(ekf.x() == x_origin);
    }
  }
  GIVEN("a reset with NaN") {
    Filter::State xb = x0;
    xb(2) = nan;
    THEN("reset returns kNonFinite and keeps the old state") {
      CHECK(ekf.reset(xb, Filter::Cov::Identity()) == kestrel::Status::kNonFinite);
      CHECK(ekf.x() == x_before);
    }
  }
  GIVEN("a good measurement") {
    THEN("update keeps P symmetric and allocates nothing") {
      std::size_t allocations = 0;
      kestrel::Status predicted, updated;
      {
        kestrel::test::AllocationGuard guard;
        predicted = ekf.predict(0.5);
        updated = ekf.update(Filter::MeasVec(std::hypot(-14900.0, 8062.5), std::atan2(8062.5, -14900.0)));
        allocations = guard.allocations();
      }
      REQUIRE(predicted == kestrel::Status::kOk);
      REQUIRE(updated == kestrel::Status::kOk);
      CHECK(allocations == 0);
      CHECK((ekf.P() - ekf.P().transpose()).cwiseAbs().maxCoeff() == 0.0);
      CHECK(ekf.diagnostics().fused);
    }
  }
}

namespace {

template <class S>
using CaEkf = kestrel::Ekf<kestrel::ConstantAcceleration2D<S>, kestrel::PolarRadar<kestrel::ConstantAcceleration2D<S>>>;

/// EKF-CA (qj 16, 3 m, 5 mrad) started at an S1-like state with P = 100 I.
template <class S>
CaEkf<S> started_ca_ekf() {
  kestrel::ConstantAcceleration2D<S> motion;
  motion.qj = S(16);
  kestrel::PolarRadar<kestrel::ConstantAcceleration2D<S>> radar;
  radar.sigma_range_m = S(3);
  radar.sigma_bearing_rad = S(0.005);
  CaEkf<S> ekf(motion, radar);
  typename CaEkf<S>::State x0;
  x0 << S(-15000), S(200), S(0), S(8000), S(125), S(0);
  REQUIRE(ekf.reset(x0, CaEkf<S>::Cov::Identity() * S(100)) == kestrel::Status::kOk);
  return ekf;
}

}  // namespace

TEMPLATE_TEST_CASE("Scenario: a prediction committed unchecked is checked by the update or by verify_prediction",
                   "[ekf][status][pd]", double, float) {
  using S = TestType;
  using Filter = CaEkf<S>;
  Filter ekf = started_ca_ekf<S>();
  const typename Filter::MeasVec z(S(std::hypot(-14900.0, 8062.5)), S(std::atan2(8062.5, -14900.0)));

  GIVEN("a sound prediction") {
    Filter checked = ekf;
    REQUIRE(checked.predict(S(0.5)) == kestrel::Status::kOk);
    REQUIRE(ekf.predict_unverified(S(0.5)) == kestrel::Status::kOk);
    THEN("it is predict()'s, bit for bit, and passes the check") {
      CHECK(ekf.x() == checked.x());
      CHECK(ekf.P() == checked.P());
      CHECK(ekf.verify_prediction() == kestrel::Status::kOk);
    }
  }
  GIVEN("a process noise that makes only the acceleration block indefinite") {
    // Q's acceleration variance dt qj is -500 on each axis against P's 100;
    // its position entries (dt^5 / 20 qj = -1.6) stay far below P's, so S is
    // still positive definite and only the update's own check can find it.
    ekf.motion().qj = S(-1000);
    Filter refused = ekf;
    CHECK(refused.predict(S(0.5)) == kestrel::Status::kNotPositiveDefinite);
    CHECK(refused.x() == ekf.x());
    REQUIRE(ekf.predict_unverified(S(0.5)) == kestrel::Status::kOk);
    REQUIRE_FALSE(kestrel::is_positive_definite(ekf.P()));
    const typename Filter::Cov P_pred = ekf.P();
    THEN("verify_prediction() reports it") {
      CHECK(ekf.verify_prediction() == kestrel::Status::kNotPositiveDefinite);
    }
    THEN("the innovation's S is still positive definite") {
      CHECK(ekf.innovation(z).status == kestrel::Status::kOk);
    }
    THEN("the update refuses it and leaves the filter unchanged") {
      CHECK(ekf.update(z) == kestrel::Status::kNotPositiveDefinite);
      CHECK(ekf.P() == P_pred);
    }
    THEN("the probabilistic update refuses it") {
      const typename Filter::MeasVec zs[1] = {z};
      const S beta[1] = {S(0.4)};
      CHECK(ekf.update_pda(zs, beta, 1, S(0.6)) == kestrel::Status::kNotPositiveDefinite);
      CHECK(ekf.P() == P_pred);
    }
  }
}

TEMPLATE_TEST_CASE("Scenario: the taken plot's innovation is formed once and gives update(z)'s result",
                   "[ekf][structured]", double, float) {
  using S = TestType;
  using Filter = CaEkf<S>;
  Filter ekf = started_ca_ekf<S>();
  REQUIRE(ekf.predict(S(0.5)) == kestrel::Status::kOk);
  const typename Filter::MeasVec z(S(std::hypot(-14895.0, 8065.0)), S(std::atan2(8065.0, -14895.0)));

  GIVEN("the distance the gate took and the innovation formed from it") {
    const auto distance = ekf.predicted_measurement().distance(z);
    const auto from_distance = ekf.innovation(z, distance);
    const auto full = ekf.innovation(z);
    THEN("it is innovation(z), bit for bit") {
      REQUIRE(full.status == kestrel::Status::kOk);
      CHECK(from_distance.status == full.status);
      CHECK(from_distance.nu == full.nu);
      CHECK(from_distance.S == full.S);
      CHECK(from_distance.d2 == full.d2);
    }
    THEN("updating from it is update(z), bit for bit") {
      Filter reference = ekf;
      REQUIRE(reference.update(z) == kestrel::Status::kOk);
      REQUIRE(ekf.update_innovation(from_distance) == kestrel::Status::kOk);
      CHECK(ekf.x() == reference.x());
      CHECK(ekf.P() == reference.P());
      CHECK(ekf.diagnostics().nis == reference.diagnostics().nis);
      CHECK(ekf.diagnostics().fused);
    }
  }
  GIVEN("an innovation that was refused") {
    const auto refused = ekf.innovation(typename Filter::MeasVec(std::numeric_limits<S>::quiet_NaN(), S(0.5)));
    REQUIRE(refused.status == kestrel::Status::kNonFinite);
    const typename Filter::State x_before = ekf.x();
    THEN("the update returns its status and keeps the state") {
      CHECK(ekf.update_innovation(refused) == kestrel::Status::kNonFinite);
      CHECK(ekf.x() == x_before);
      CHECK_FALSE(ekf.diagnostics().fused);
    }
  }
}
