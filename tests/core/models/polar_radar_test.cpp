// SPDX-License-Identifier: Apache-2.0
// Polar radar: analytic Jacobian against central differences, bearing wrap.
#include <catch2/catch.hpp>
#include <cmath>

#include "kestrel/models/measurement/polar_radar.hpp"
#include "kestrel/models/motion/constant_acceleration_2d.hpp"

using Motion = kestrel::ConstantAcceleration2D<double>;
using Radar = kestrel::PolarRadar<Motion>;
constexpr double kPi = 3.14159265358979323846;

SCENARIO("the polar radar Jacobian matches central differences", "[models][polar]") {
  Radar radar;
  radar.sigma_range_m = 3.0;
  radar.sigma_bearing_rad = 0.3 * kPi / 180;
  // Positions in all four quadrants, including next to the +-pi bearing cut.
  const double positions[][2] = {{-15000, 8000}, {12000, 300}, {-9000, -1e-3}, {250, -7000}, {-20000, 1e-3}};
  for (const auto& p : positions) {
    GIVEN("a target at (" << p[0] << ", " << p[1] << ")") {
      Motion::State x;
      x << p[0], 100, 1, p[1], -50, 2;
      const auto H = radar.jacobian(x);
      THEN("each column equals (h(x + e) - h(x - e)) / 2e") {
        for (int c = 0; c < 6; ++c) {
          const double h = 1e-3 * std::max(1.0, std::abs(x(c)));
          Motion::State xp = x, xm = x;
          xp(c) += h;
          xm(c) -= h;
          // residual() wraps, so a difference across the bearing cut stays small.
          // Evaluate into a value: auto would keep an Eigen expression that
          // refers to the temporary residual after it is destroyed.
          const Radar::Measurement d = radar.residual(radar.predict(xp), radar.predict(xm)) / (2 * h);
          // Central differences are O(h^2) accurate: relative 1e-6 of the
          // largest entry is far above that error and far below a wrong term.
          const double scale = std::max(1e-12, H.row(0).cwiseAbs().maxCoeff());
          const double scale_b = std::max(1e-12, H.row(1).cwiseAbs().maxCoeff());
          CHECK(std::abs(d(0) - H(0, c)) <= 1e-6 * scale);
          CHECK(std::abs(d(1) - H(1, c)) <= 1e-6 * scale_b);
        }
      }
    }
  }
}

SCENARIO("bearing residuals wrap across +-pi", "[models][polar][wrap]") {
  Radar radar;
  GIVEN("a measured bearing just below +pi and a predicted one just above -pi") {
    Radar::Measurement z, zh;
    z << 1000, kPi - 0.01;
    zh << 1000, -kPi + 0.01;
    THEN("the residual is the short way round, -0.02 rad") {
      CHECK(radar.residual(z, zh)(1) == Approx(-0.02).margin(1e-12));
      CHECK(radar.residual(zh, z)(1) == Approx(0.02).margin(1e-12));
    }
  }
  GIVEN("angles exactly at the cut") {
    THEN("wrap_angle maps into (-pi, pi]") {
      CHECK(kestrel::wrap_angle(-kPi) == Approx(kPi));
      CHECK(kestrel::wrap_angle(kPi) == Approx(kPi));
      CHECK(kestrel::wrap_angle(3 * kPi) == Approx(kPi));
      CHECK(kestrel::wrap_angle(7.5 * kPi) == Approx(-0.5 * kPi));
      CHECK(kestrel::wrap_angle(0.25f) == Approx(0.25f));
    }
  }
  GIVEN("the range residual") {
    Radar::Measurement z, zh;
    z << 1000, 0.1;
    zh << 990, 0.1;
    THEN("it is not wrapped") { CHECK(radar.residual(z, zh)(0) == Approx(10.0)); }
  }
}
