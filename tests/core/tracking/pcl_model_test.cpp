// SPDX-License-Identifier: Apache-2.0
// PCL models (docs/models.md, paper 002): bistatic CV-1D F and Q,
// the [Rb, dRb] measurement (H = I, R), the Doppler to range-rate conversion
// (sign and magnitude), bistatic geometry against finite differences, the
// single-point initiator with its zero-Doppler veto, and the PCL filter
// against a textbook linear KF.
#include <catch2/catch.hpp>
#include <Eigen/LU>
#include <cmath>

#include "kestrel/models/measurement/bistatic_geometry.hpp"
#include "kestrel/tracking/pcl_tracker.hpp"

namespace {

using kestrel::Status;
using V3 = kestrel::Vec<double, 3>;

const V3 kRx(0.0, 0.0, 0.0);
const V3 kTx(0.0, -8500.0, 0.0);

}  // namespace

SCENARIO("the bistatic CV-1D model has F = [[1, dt], [0, 1]] and white-acceleration Q", "[pcl][model]") {
  kestrel::BistaticCv1D<double> m;
  m.accel_sigma_mps2 = 4.0;
  STATIC_REQUIRE(kestrel::BistaticCv1D<double>::kStateDim == 2);
  STATIC_REQUIRE(kestrel::BistaticCv1D<double>::Layout::kRb == 0);
  STATIC_REQUIRE(kestrel::BistaticCv1D<double>::Layout::kDRb == 1);
  STATIC_REQUIRE(kestrel::MotionModel<kestrel::BistaticCv1D<float>>);
  GIVEN("dt = 0.5 s") {
    const auto F = m.transition(0.5);
    const auto Q = m.process_noise(0.5);
    THEN("F and Q are the closed forms (exact in binary: dt is a power of two)") {
      CHECK(F(0, 0) == 1.0);
      CHECK(F(0, 1) == 0.5);
      CHECK(F(1, 0) == 0.0);
      CHECK(F(1, 1) == 1.0);
      CHECK(Q(0, 0) == 16.0 * 0.0625 / 4.0);
      CHECK(Q(0, 1) == 16.0 * 0.125 / 2.0);
      CHECK(Q(1, 0) == Q(0, 1));
      CHECK(Q(1, 1) == 16.0 * 0.25);
      CHECK(m.jacobian(kestrel::Vec<double, 2>(1.0, 2.0), 0.5) == F);
    }
    THEN("propagation moves the range by the rate times dt") {
      const auto x = m.propagate(kestrel::Vec<double, 2>(1200.0, -20.0), 0.5);
      CHECK(x(0) == 1190.0);
      CHECK(x(1) == -20.0);
    }
  }
}

SCENARIO("Doppler converts to bistatic range rate as dRb = -lambda fD", "[pcl][model]") {
  GIVEN("the 701 MHz DTV carrier of paper 002") {
    const double lambda = kestrel::wavelength_m(701.0e6);
    THEN("lambda = c0 / f = 0.4277 m (docs/models.md)") { CHECK_THAT(lambda, Catch::WithinAbs(0.4277, 5e-5)); }
    THEN("a positive Doppler is a closing target (negative range rate) and the magnitude is lambda |fD|") {
      CHECK(kestrel::range_rate_from_doppler(10.0, lambda) == Approx(-4.2766).epsilon(1e-4));
      CHECK(kestrel::range_rate_from_doppler(-122.0, lambda) == Approx(52.18).epsilon(1e-3));
      CHECK(kestrel::range_rate_from_doppler(0.0, lambda) == 0.0);
      CHECK(kestrel::doppler_from_range_rate(kestrel::range_rate_from_doppler(37.5, lambda), lambda) ==
            Approx(37.5).epsilon(1e-12));
    }
    THEN("a drone flying south toward the receiver (and the transmitter) closes and has a positive Doppler") {
      const V3 p(0.0, 600.0, 100.0);
      const V3 v(0.0, -10.0, 0.0);
      const double rate = kestrel::bistatic_range_rate(p, v, kTx, kRx);
      CHECK(rate < 0.0);
      CHECK(kestrel::doppler_from_range_rate(rate, lambda) > 0.0);
      // Both lines of sight point almost due north: |dRb| is almost 2 |v|.
      CHECK(rate == Approx(-10.0 * (600.0 / std::hypot(600.0, 100.0) + 9100.0 / std::hypot(9100.0, 100.0))));
    }
  }
}

SCENARIO("bistatic range and rate match the geometry and finite differences", "[pcl][model]") {
  THEN("Rb is 0 on the baseline and the extra path elsewhere") {
    CHECK(kestrel::bistatic_range(V3(0.0, -4000.0, 0.0), kTx, kRx) == Approx(0.0).margin(1e-9));
    CHECK(kestrel::bistatic_range(V3(0.0, 1000.0, 0.0), kTx, kRx) == Approx(2000.0));
    CHECK(kestrel::bistatic_range(V3(300.0, 400.0, 0.0), kTx, kRx) ==
          Approx(std::hypot(300.0, 8900.0) + 500.0 - 8500.0));
  }
  GIVEN("a drone at 50-120 m altitude on a slanted course") {
    const V3 p(-350.0, 620.0, 85.0);
    const V3 v(18.0, -9.0, 1.5);
    THEN("dRb equals the central difference of Rb along the course") {
      // h = 1e-3 s: truncation O(h^2 Rb''') ~ 1e-9 m/s, round-off ~ 1e-13 / 1e-3 = 1e-10 m/s.
      const double h = 1e-3;
      const double numeric = (kestrel::bistatic_range(V3(p + v * h), kTx, kRx) -
                              kestrel::bistatic_range(V3(p - v * h), kTx, kRx)) /
                             (2.0 * h);
      CHECK_THAT(kestrel::bistatic_range_rate(p, v, kTx, kRx), Catch::WithinAbs(numeric, 1e-6));
    }
  }
}

SCENARIO("the bistatic measurement measures the state itself", "[pcl][model]") {
  using M = kestrel::PclMeasurement<double>;
  STATIC_REQUIRE(kestrel::MeasurementModelFor<M, kestrel::PclMotion<double>>);
  kestrel::PclTrackerParams params;
  const M m = kestrel::pcl_measurement<double>(params);
  const kestrel::Vec<double, 2> x(1500.0, -12.0);
  CHECK(m.predict(x) == x);
  CHECK(m.jacobian(x) == kestrel::Mat<double, 2, 2>::Identity());
  CHECK(m.noise()(0, 0) == 100.0);
  // sigma_dRb = lambda * sigma_fD = 0.4277 * 0.5 m/s.
  CHECK(m.noise()(1, 1) == Approx(std::pow(0.5 * 299792458.0 / 701.0e6, 2)).epsilon(1e-12));
  CHECK(m.noise()(0, 1) == 0.0);
  kestrel::Vec<double, 2> xs;
  kestrel::Mat<double, 2, 2> P;
  m.to_state(x, xs, P);
  CHECK(xs == x);
  CHECK(P == m.noise());
}

SCENARIO("the single-point initiator starts from one candidate unless its Doppler is below the veto",
         "[pcl][initiator]") {
  kestrel::PclTrackerParams params;  // 2 Hz veto
  const auto init = kestrel::pcl_initiator<double>(params);
  const double lambda = kestrel::pcl_wavelength_m<double>(params);
  STATIC_REQUIRE(kestrel::PclInitiator<double>::kSinglePoint);
  kestrel::Vec<double, 2> x(-1.0, -1.0);
  kestrel::Mat<double, 2, 2> P = kestrel::Mat<double, 2, 2>::Constant(-1.0);
  const auto x_before = x;
  const auto P_before = P;
  WHEN("the candidate's |fD| is 1.9 Hz (the zero-Doppler ridge)") {
    THEN("it is refused with kOutOfRange and x, P are untouched") {
      CHECK(init.initiate(kestrel::Vec<double, 2>(800.0, 1.9 * lambda), x, P) == Status::kOutOfRange);
      CHECK(init.initiate(kestrel::Vec<double, 2>(800.0, -1.9 * lambda), x, P) == Status::kOutOfRange);
      CHECK(x == x_before);
      CHECK(P == P_before);
    }
  }
  WHEN("the candidate's |fD| is 2.1 Hz") {
    const kestrel::Vec<double, 2> z(800.0, -2.1 * lambda);
    THEN("the track starts at the candidate with P = R") {
      REQUIRE(init.initiate(z, x, P) == Status::kOk);
      CHECK(x == z);
      CHECK(P == kestrel::pcl_measurement<double>(params).noise());
    }
  }
  WHEN("the candidate holds a NaN") {
    THEN("kNonFinite") {
      CHECK(init.initiate(kestrel::Vec<double, 2>(std::nan(""), 5.0), x, P) == Status::kNonFinite);
      CHECK(x == x_before);
    }
  }
}

TEMPLATE_TEST_CASE("the PCL filter is the textbook linear Kalman filter", "[pcl][kf]", double, float) {
  using S = TestType;
  using M2 = kestrel::Mat<double, 2, 2>;
  using V2 = kestrel::Vec<double, 2>;
  kestrel::PclTrackerParams params;
  auto kf = kestrel::pcl_filter<S>(params);
  const V2 x0(1800.0, -15.0);
  const M2 P0 = kestrel::pcl_measurement<double>(params).noise();
  REQUIRE(kf.reset(x0.cast<S>(), P0.cast<S>()) == Status::kOk);

  // Textbook KF in double: x- = F x, P- = F P F' + Q, K = P- H' S^-1,
  // x+ = x- + K nu, P+ = (I - K H) P- (H = I here).
  kestrel::BistaticCv1D<double> motion;
  motion.accel_sigma_mps2 = params.accel_sigma_mps2;
  const M2 R = P0;
  V2 x = x0;
  M2 P = P0;
  const V2 zs[5] = {V2(1791.0, -15.3), V2(1786.5, -14.9), V2(1775.0, -15.6), V2(1771.2, -15.2), V2(1761.0, -15.1)};
  for (const auto& z : zs) {
    REQUIRE(kf.predict(S(0.5)) == Status::kOk);
    REQUIRE(kf.update(z.cast<S>()) == Status::kOk);
    const M2 F = motion.transition(0.5);
    x = F * x;
    P = F * P * F.transpose() + motion.process_noise(0.5);
    const M2 K = P * (P + R).inverse();
    x = x + K * (z - x);
    P = (M2::Identity() - K) * P;
  }
  // double: Joseph vs standard form differ by round-off only (1e-9 relative).
  // float: 24-bit mantissa on ranges near 2 km, so 1e-4 relative.
  const double tol = sizeof(S) == sizeof(double) ? 1e-9 : 1e-4;
  for (int i = 0; i < 2; ++i) {
    CHECK_THAT(static_cast<double>(kf.x()(i)), Catch::WithinRel(x(i), tol));
    for (int j = 0; j < 2; ++j) CHECK_THAT(static_cast<double>(kf.P()(i, j)), Catch::WithinRel(P(i, j), 10 * tol));
  }
}
