// SPDX-License-Identifier: Apache-2.0
// Polar radar with range rate: analytic Jacobian against central
// differences (CA-2D and CV-2D, double and float), the r -> 0 rule, the
// residual wrap, the concepts the filters ask for, and the EKF's
// structured update against its dense oracle.
#include <catch2/catch.hpp>
#include <cmath>

#include "kestrel/filters/ekf.hpp"
#include "kestrel/filters/structure.hpp"
#include "kestrel/models/concepts.hpp"
#include "kestrel/models/measurement/polar_radar.hpp"
#include "kestrel/models/measurement/polar_radar_range_rate.hpp"
#include "kestrel/models/motion/constant_acceleration_2d.hpp"
#include "kestrel/models/motion/constant_velocity_2d.hpp"

namespace {
using Ca = kestrel::ConstantAcceleration2D<double>;
using Cv = kestrel::ConstantVelocity2D<double>;
using CaF = kestrel::ConstantAcceleration2D<float>;
using Radar = kestrel::PolarRadarRangeRate<Ca>;
using RadarCv = kestrel::PolarRadarRangeRate<Cv>;
using RadarF = kestrel::PolarRadarRangeRate<CaF>;
constexpr double kPi = 3.14159265358979323846;

template <class R>
R make_radar() {
  using S = typename R::Scalar;
  R radar;
  radar.sigma_range_m = S(3.0);
  radar.sigma_bearing_rad = S(0.3 * kPi / 180);
  radar.sigma_range_rate_mps = S(0.5);
  return radar;
}

/// max over the columns of |(h(x + e_c) - h(x - e_c)) / 2e - H(:, c)|, per
/// row, relative to that row's largest |H| entry.
template <class R>
Eigen::Vector3d worst_relative_fd_error(const R& radar, const typename R::State& x) {
  const auto H = radar.jacobian(x);
  Eigen::Vector3d worst = Eigen::Vector3d::Zero();
  for (int c = 0; c < R::kStateDim; ++c) {
    // Step 1e-6 relative: truncation O(h^2 |h'''|) stays below 1e-9 of the
    // row scale even at r = 0.5 m, round-off O(eps |h| / h) below 1e-8.
    const double h = 1e-6 * std::max(1.0, std::abs(x(c)));
    typename R::State xp = x, xm = x;
    xp(c) += h;
    xm(c) -= h;
    // residual() wraps, so a difference across the bearing cut stays small.
    const typename R::Measurement d = radar.residual(radar.predict(xp), radar.predict(xm)) / (2 * h);
    for (int r = 0; r < 3; ++r) {
      const double scale = std::max(1e-12, H.row(r).cwiseAbs().maxCoeff());
      worst(r) = std::max(worst(r), std::abs(d(r) - H(r, c)) / scale);
    }
  }
  return worst;
}
}  // namespace

SCENARIO("the range-rate radar satisfies the filters' contracts", "[models][polar][range_rate]") {
  STATIC_REQUIRE(kestrel::MeasurementModelFor<Radar, Ca>);
  STATIC_REQUIRE(kestrel::MeasurementModelFor<RadarCv, Cv>);
  STATIC_REQUIRE(kestrel::MeasurementModelFor<RadarF, CaF>);
  STATIC_REQUIRE(Radar::kMeasDim == 3);
  // Four non-zero columns (x, vx, y, vy): the EKF's structured update applies.
  STATIC_REQUIRE(kestrel::SparseJacobianMeasurement<Radar>);
  STATIC_REQUIRE(kestrel::Ekf<Ca, Radar>::kSparseUpdate);
  STATIC_REQUIRE(kestrel::Ekf<CaF, RadarF>::kSparseUpdate);
  STATIC_REQUIRE_FALSE(kestrel::Ekf<Ca, kestrel::Dense<Radar>>::kSparseUpdate);
}

SCENARIO("the range-rate radar Jacobian matches central differences", "[models][polar][range_rate]") {
  const Radar radar = make_radar<Radar>();
  // [x, vx, ax, y, vy, ay]: all four quadrants, next to the +-pi bearing
  // cut, opening, closing and tangential motion, and close to the radar.
  const double states[][6] = {
      {-15000, 200, 1, 8000, 125.7, -2}, {12000, -180, 0, 300, 40, 3},  {-9000, 50, 0, -1e-3, -220, 0},
      {250, 0, 0, -7000, 0, 0},          {-20000, 10, 0, 1e-3, 300, 0}, {3.0, 100, 0, 4.0, -75, 0},
      {0.3, -20, 0, -0.4, 35, 0},
  };
  for (const auto& s : states) {
    GIVEN("the state x = " << s[0] << ", vx = " << s[1] << ", y = " << s[3] << ", vy = " << s[4]) {
      Ca::State x;
      x << s[0], s[1], s[2], s[3], s[4], s[5];
      THEN("every row of H equals the central differences to 1e-6 of its scale") {
        const Eigen::Vector3d worst = worst_relative_fd_error(radar, x);
        CHECK(worst(0) < 1e-6);
        CHECK(worst(1) < 1e-6);
        CHECK(worst(2) < 1e-6);
      }
      THEN("range rate is (x vx + y vy) / r and depends on velocity only in its own row") {
        const double r = std::hypot(s[0], s[3]);
        CHECK_THAT(radar.predict(x)(2), Catch::Matchers::WithinRel((s[0] * s[1] + s[3] * s[4]) / r, 1e-12));
        const auto H = radar.jacobian(x);
        CHECK(H(0, 1) == 0.0);
        CHECK(H(1, 4) == 0.0);
        CHECK(H.col(2).isZero());  // accelerations never enter
        CHECK(H.col(5).isZero());
      }
    }
  }
  GIVEN("the CV-2D state layout [x vx y vy]") {
    const RadarCv cv = make_radar<RadarCv>();
    Cv::State x;
    x << -15000, 200, 8000, 125.7;
    THEN("the Jacobian matches central differences there too") {
      const Eigen::Vector3d worst = worst_relative_fd_error(cv, x);
      CHECK(worst.maxCoeff() < 1e-6);
    }
  }
  GIVEN("the float build at an S1 state") {
    const RadarF radar_f = make_radar<RadarF>();
    Ca::State x;
    x << -15000, 200, 1, 8000, 125.7, -2;
    const auto H = radar.jacobian(x);
    const auto Hf = radar_f.jacobian(x.cast<float>());
    THEN("it equals the double Jacobian to float precision, row by row") {
      for (int r = 0; r < 3; ++r) {
        // A few float ulps of the row's largest entry (2^-24 = 6e-8 each).
        const double scale = H.row(r).cwiseAbs().maxCoeff();
        CHECK((Hf.row(r).cast<double>() - H.row(r)).cwiseAbs().maxCoeff() < 1e-6 * scale);
      }
      CHECK_THAT(double(radar_f.predict(x.cast<float>())(2)), Catch::Matchers::WithinAbs(radar.predict(x)(2), 1e-4));
    }
  }
}

SCENARIO("a target on the radar is refused, not linearised", "[models][polar][range_rate][origin]") {
  GIVEN("a state at r = 0") {
    const Radar radar = make_radar<Radar>();
    Ca::State x;
    x << 0, 100, 0, 0, -50, 0;
    THEN("range rate and the Jacobian are not finite (0/0)") {
      CHECK_FALSE(std::isfinite(radar.predict(x)(2)));
      CHECK_FALSE(kestrel::all_finite(radar.jacobian(x)));
    }
    for (int dense = 0; dense < 2; ++dense) {
      WHEN(std::string(dense ? "the dense" : "the structured") + " EKF is updated there") {
        Ca motion;
        motion.qj = 1.6;
        Ca::Cov P = Ca::Cov::Identity() * 100.0;
        Radar::Measurement z;
        z << 5.0, 0.1, 3.0;
        kestrel::Status s{};
        kestrel::Status si{};
        Ca::State x_after;
        Ca::Cov P_after;
        if (dense) {
          kestrel::Ekf<Ca, kestrel::Dense<Radar>> ekf(motion, kestrel::Dense<Radar>(radar));
          REQUIRE(ekf.reset(x, P) == kestrel::Status::kOk);
          si = ekf.innovation(z).status;
          s = ekf.update(z);
          x_after = ekf.x();
          P_after = ekf.P();
        } else {
          kestrel::Ekf<Ca, Radar> ekf(motion, radar);
          REQUIRE(ekf.reset(x, P) == kestrel::Status::kOk);
          si = ekf.innovation(z).status;
          s = ekf.update(z);
          x_after = ekf.x();
          P_after = ekf.P();
        }
        THEN("innovation and update report kNonFinite and the filter is unchanged") {
          CHECK(si == kestrel::Status::kNonFinite);
          CHECK(s == kestrel::Status::kNonFinite);
          CHECK(x_after == x);
          CHECK(P_after == P);
        }
      }
    }
  }
  GIVEN("the float filter at r = 0") {
    const RadarF radar = make_radar<RadarF>();
    kestrel::Ekf<CaF, RadarF> ekf(CaF{}, radar);
    CaF::State x;
    x << 0, 100, 0, 0, -50, 0;
    REQUIRE(ekf.reset(x, CaF::Cov::Identity()) == kestrel::Status::kOk);
    RadarF::Measurement z;
    z << 5.0f, 0.1f, 3.0f;
    THEN("the update is refused with kNonFinite too") {
      CHECK(ekf.update(z) == kestrel::Status::kNonFinite);
      CHECK(ekf.x() == x);
    }
  }
}

SCENARIO("range-rate radar residuals wrap the bearing only", "[models][polar][range_rate][wrap]") {
  const Radar radar = make_radar<Radar>();
  GIVEN("a measured bearing just below +pi and a predicted one just above -pi") {
    Radar::Measurement z, zh;
    z << 1000, kPi - 0.01, 150.0;
    zh << 990, -kPi + 0.01, -150.0;
    const Radar::Measurement nu = radar.residual(z, zh);
    THEN("the bearing residual is the short way round, -0.02 rad") {
      CHECK_THAT(nu(1), Catch::Matchers::WithinAbs(-0.02, 1e-12));
    }
    THEN("range and range rate are plain differences (300 m/s is not wrapped)") {
      CHECK(nu(0) == 10.0);
      CHECK(nu(2) == 300.0);
    }
  }
  GIVEN("the range-bearing radar with the same sigmas") {
    const kestrel::PolarRadar<Ca> rb = radar.range_bearing();
    Radar::Measurement z;
    z << 12000, 2.5, -40;
    THEN("to_position and the first two rows of R are the range-bearing radar's") {
      kestrel::Vec<double, 2> p, p_rb;
      kestrel::Mat<double, 2, 2> P, P_rb;
      radar.to_position(z, p, P);
      rb.to_position(z.head<2>(), p_rb, P_rb);
      CHECK(p == p_rb);
      CHECK(P == P_rb);
      CHECK(radar.noise().topLeftCorner<2, 2>() == rb.noise());
      CHECK(radar.noise()(2, 2) == 0.25);
    }
  }
}

SCENARIO("the structured EKF update with range rate equals the dense one", "[models][polar][range_rate][ekf]") {
  GIVEN("EKF-CA with range rate, structured and dense, after a predict from an S1-like start") {
    const Radar radar = make_radar<Radar>();
    Ca motion;
    motion.qj = 1.6;
    kestrel::Ekf<Ca, Radar> fast(motion, radar);
    kestrel::Ekf<Ca, kestrel::Dense<Radar>> dense(motion, kestrel::Dense<Radar>(radar));
    Ca::State x;
    x << -15000, 190, 0, 8000, 130, 0;
    Ca::Cov P = Ca::Cov::Zero();
    P.diagonal() << 400, 900, 100, 400, 900, 100;
    REQUIRE(fast.reset(x, P) == kestrel::Status::kOk);
    REQUIRE(dense.reset(x, P) == kestrel::Status::kOk);
    REQUIRE(fast.predict(0.5) == kestrel::Status::kOk);
    REQUIRE(dense.predict(0.5) == kestrel::Status::kOk);
    Radar::Measurement z;
    z << 17103.0, 2.6515, -60.3;
    WHEN("both fold in the same plot") {
      const auto in_fast = fast.innovation(z);
      const auto in_dense = dense.innovation(z);
      REQUIRE(fast.update(z) == kestrel::Status::kOk);
      REQUIRE(dense.update(z) == kestrel::Status::kOk);
      THEN("state, covariance and NIS agree to 1e-9 relative (ekf.hpp's bound)") {
        CHECK((fast.x() - dense.x()).cwiseAbs().maxCoeff() <= 1e-9 * dense.x().cwiseAbs().maxCoeff());
        CHECK((fast.P() - dense.P()).cwiseAbs().maxCoeff() <= 1e-9 * dense.P().cwiseAbs().maxCoeff());
        CHECK_THAT(in_fast.d2, Catch::Matchers::WithinRel(in_dense.d2, 1e-9));
      }
      THEN("the range-rate channel cut the radial velocity variance") {
        // u^T P_vv u before and after, u the line of sight.
        const Eigen::Vector2d u = Eigen::Vector2d(x(0), x(3)).normalized();
        Eigen::Matrix2d Pvv;
        Pvv << fast.P()(1, 1), fast.P()(1, 4), fast.P()(4, 1), fast.P()(4, 4);
        // 900 m^2/s^2 before (plus 0.5 s of jerk noise); srr = 0.5 m/s pulls it under 1.
        CHECK(u.dot(Pvv * u) < 1.0);
      }
    }
  }
}
