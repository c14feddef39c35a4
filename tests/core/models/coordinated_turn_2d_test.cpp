// SPDX-License-Identifier: Apache-2.0
// CT-2D motion model: the analytic Jacobian against central differences on
// both sides of the series limit, w -> 0 equal to constant velocity, the
// exact circle, continuity across the series limit, float, and an Ekf on it.
#include <catch2/catch.hpp>
#include <cmath>

#include "kestrel/filters/ekf.hpp"
#include "kestrel/models/concepts.hpp"
#include "kestrel/models/measurement/polar_radar.hpp"
#include "kestrel/models/motion/constant_velocity_2d.hpp"
#include "kestrel/models/motion/coordinated_turn_2d.hpp"

namespace {

using Ct = kestrel::CoordinatedTurn2D<double>;
using L = Ct::Layout;

/// Central differences of propagate() in every state component.
Ct::Cov numeric_jacobian(const Ct& m, const Ct::State& x, double dt) {
  Ct::Cov J;
  for (int c = 0; c < Ct::kStateDim; ++c) {
    // Steps that keep the round-off of km-sized positions (1e-12 m over
    // 2h) and the h^2 truncation both below the 1e-6 tolerance.
    const double h = c == L::kW ? 1e-6 : 1e-5 * std::max(1.0, std::abs(x(c)));
    Ct::State xp = x, xm = x;
    xp(c) += h;
    xm(c) -= h;
    J.col(c) = (m.propagate(xp, dt) - m.propagate(xm, dt)) / (2 * h);
  }
  return J;
}

}  // namespace

SCENARIO("CT-2D satisfies the motion model contract", "[models][ct2d]") {
  STATIC_REQUIRE(kestrel::MotionModel<Ct>);
  STATIC_REQUIRE(kestrel::MotionModel<kestrel::CoordinatedTurn2D<float>>);
  STATIC_REQUIRE(Ct::kStateDim == 5);
  STATIC_REQUIRE(L::kX == 0);
  STATIC_REQUIRE(L::kVx == 1);
  STATIC_REQUIRE(L::kY == 2);
  STATIC_REQUIRE(L::kVy == 3);
  STATIC_REQUIRE(L::kW == 4);
}

SCENARIO("CT-2D analytic Jacobian matches central differences", "[models][ct2d]") {
  Ct m;
  const double dt = 0.5;
  // Turn rates on both sides of the series limit |w T| = 0.3 and at zero.
  for (const double w : {0.0, 1e-7, 0.02, -0.1, 0.59, 0.61, -1.3, 2.0}) {
    GIVEN("w = " << w << " rad/s and T = 0.5 s") {
      Ct::State x;
      x << -15000.0, 200.0, 8000.0, 125.7, w;
      const Ct::Cov F = m.jacobian(x, dt);
      const Ct::Cov N = numeric_jacobian(m, x, dt);
      THEN("every entry agrees to 1e-6 of the column's scale") {
        // The w column is up to |v| T^2 ~ 60 m/(rad/s); the others are O(1).
        for (int c = 0; c < Ct::kStateDim; ++c) {
          const double scale = std::max(1.0, N.col(c).cwiseAbs().maxCoeff());
          INFO("column " << c << "\nanalytic\n" << F << "\nnumeric\n" << N);
          CHECK((F.col(c) - N.col(c)).cwiseAbs().maxCoeff() <= 1e-6 * scale);
        }
      }
    }
  }
}

SCENARIO("CT-2D at w = 0 is constant velocity", "[models][ct2d]") {
  Ct m;
  kestrel::ConstantVelocity2D<double> cv;
  const double dt = 0.5;
  Ct::State x;
  x << 1000.0, 10.0, -2000.0, 5.0, 0.0;
  const kestrel::Vec<double, 4> xcv(1000.0, 10.0, -2000.0, 5.0);
  WHEN("w is exactly 0") {
    const Ct::State p = m.propagate(x, dt);
    const Ct::Cov F = m.jacobian(x, dt);
    THEN("propagation and the position-velocity block of F are CV's, bit for bit") {
      const auto pcv = cv.propagate(xcv, dt);
      CHECK(p(L::kX) == pcv(0));
      CHECK(p(L::kVx) == pcv(1));
      CHECK(p(L::kY) == pcv(2));
      CHECK(p(L::kVy) == pcv(3));
      CHECK(p(L::kW) == 0.0);
      CHECK(F.topLeftCorner<4, 4>() == cv.jacobian(xcv, dt));
    }
    THEN("the turn-rate column is the limit: d x/dw = -vy T^2/2, d y/dw = vx T^2/2") {
      CHECK(F(L::kX, L::kW) == Approx(-5.0 * dt * dt / 2).epsilon(1e-15));
      CHECK(F(L::kY, L::kW) == Approx(10.0 * dt * dt / 2).epsilon(1e-15));
      CHECK(F(L::kVx, L::kW) == Approx(-5.0 * dt).epsilon(1e-15));
      CHECK(F(L::kVy, L::kW) == Approx(10.0 * dt).epsilon(1e-15));
    }
  }
  WHEN("w is 1e-12 rad/s") {
    x(L::kW) = 1e-12;
    THEN("propagation differs from CV by far less than a millimetre") {
      const Ct::State p = m.propagate(x, dt);
      const auto pcv = cv.propagate(xcv, dt);
      CHECK(std::abs(p(L::kX) - pcv(0)) < 1e-9);
      CHECK(std::abs(p(L::kY) - pcv(2)) < 1e-9);
    }
  }
}

SCENARIO("CT-2D follows the exact circle on both sides of the series limit", "[models][ct2d]") {
  Ct m;
  for (const double w : {0.05, 0.599999, 0.600001, -0.2}) {
    GIVEN("a target at the origin heading +x at 200 m/s turning at w = " << w << " rad/s") {
      Ct::State x;
      x << 0.0, 200.0, 0.0, 0.0, w;
      const double dt = 0.5;
      const double a = w * dt;
      const double R = 200.0 / w;
      const Ct::State p = m.propagate(x, dt);
      THEN("it lands on the circle of radius v/w, its velocity turned by w T") {
        // 1e-12 relative: the series' truncation and the closed form's
        // cancellation are both below it at |a| = 0.3 (header comment).
        CHECK(p(L::kX) == Approx(R * std::sin(a)).epsilon(1e-12));
        CHECK(p(L::kY) == Approx(R * (1 - std::cos(a))).epsilon(1e-12));
        CHECK(p(L::kVx) == Approx(200.0 * std::cos(a)).epsilon(1e-12));
        CHECK(p(L::kVy) == Approx(200.0 * std::sin(a)).epsilon(1e-12));
        CHECK(std::hypot(p(L::kVx), p(L::kVy)) == Approx(200.0).epsilon(1e-14));
      }
    }
  }
}

SCENARIO("CT-2D in float stays within float precision of double", "[models][ct2d][float]") {
  kestrel::CoordinatedTurn2D<float> mf;
  Ct md;
  for (const double w : {0.0, 1e-6, 0.3, 0.59, 0.61, -1.0}) {
    GIVEN("w = " << w << " rad/s") {
      Ct::State xd;
      xd << -15000.0, 200.0, 8000.0, 125.0, w;
      const kestrel::CoordinatedTurn2D<float>::State xf = xd.cast<float>();
      const auto pd = md.propagate(xd, 0.5);
      const auto pf = mf.propagate(xf, 0.5f);
      const auto Fd = md.jacobian(xd, 0.5);
      const auto Ff = mf.jacobian(xf, 0.5f);
      THEN("propagation agrees to a few float ulps of the position and F to 1e-5 of its scale") {
        CHECK(std::abs(double(pf(L::kX)) - pd(L::kX)) < 4e-3);  // 15 km: ulp 1e-3 m
        CHECK(std::abs(double(pf(L::kY)) - pd(L::kY)) < 4e-3);
        CHECK(std::abs(double(pf(L::kVx)) - pd(L::kVx)) < 1e-4);
        CHECK(std::abs(double(pf(L::kVy)) - pd(L::kVy)) < 1e-4);
        CHECK(Ff.allFinite());
        for (int c = 0; c < Ct::kStateDim; ++c) {
          const double scale = std::max(1.0, Fd.col(c).cwiseAbs().maxCoeff());
          CHECK((Ff.col(c).cast<double>() - Fd.col(c)).cwiseAbs().maxCoeff() <= 1e-5 * scale);
        }
      }
    }
  }
}

SCENARIO("CT-2D process noise is DWNA per axis plus a turn-rate random walk", "[models][ct2d]") {
  Ct m;
  m.sa = 2.0;
  m.sw = 0.05;
  const Ct::Cov Q = m.process_noise(0.5);
  CHECK(Q(L::kX, L::kX) == Approx(4.0 * 0.0625 / 4).epsilon(1e-15));
  CHECK(Q(L::kX, L::kVx) == Approx(4.0 * 0.125 / 2).epsilon(1e-15));
  CHECK(Q(L::kVx, L::kVx) == Approx(4.0 * 0.25).epsilon(1e-15));
  CHECK(Q(L::kY, L::kY) == Q(L::kX, L::kX));
  CHECK(Q(L::kVy, L::kY) == Q(L::kVx, L::kX));
  CHECK(Q(L::kW, L::kW) == Approx(0.05 * 0.05 * 0.5).epsilon(1e-15));
  CHECK(Q(L::kX, L::kY) == 0.0);
  CHECK((Q - Q.transpose()).isZero(0.0));
}

TEMPLATE_TEST_CASE("Scenario: an Ekf runs on CT-2D with the polar radar", "[models][ct2d][ekf]", double, float) {
  using S = TestType;
  using Motion = kestrel::CoordinatedTurn2D<S>;
  using Radar = kestrel::PolarRadar<Motion>;
  Motion m;
  m.sa = S(1);
  m.sw = S(0.02);
  Radar h;
  h.sigma_range_m = S(3);
  h.sigma_bearing_rad = S(0.3 * 3.14159265358979 / 180);
  kestrel::Ekf<Motion, Radar> ekf(m, h);
  typename Motion::State x0;
  x0 << S(-8000), S(180), S(12000), S(0), S(0);
  const typename Motion::Cov P0 =
      kestrel::Vec<S, 5>(S(100), S(400), S(100), S(400), S(0.01)).asDiagonal();
  REQUIRE(ekf.reset(x0, P0) == kestrel::Status::kOk);
  // Truth: a 1500 m radius left turn at 180 m/s (w = 0.12 rad/s), plots
  // without noise; the turn rate must be learnt from them.
  const double w = 0.12, R = 1500.0;
  for (int k = 1; k <= 40; ++k) {
    const double t = 0.5 * k;
    const double px = -8000.0 + R * std::sin(w * t);
    const double py = 12000.0 + R * (1 - std::cos(w * t));
    REQUIRE(ekf.predict(S(0.5)) == kestrel::Status::kOk);
    const typename Radar::Measurement z(S(std::hypot(px, py)), S(std::atan2(py, px)));
    REQUIRE(ekf.update(z) == kestrel::Status::kOk);
  }
  CHECK(double(ekf.x()(Motion::Layout::kW)) == Approx(w).margin(0.01));
}
