// SPDX-License-Identifier: Apache-2.0
// Multipath TOA (docs/models.md) and CV-3D + sound speed (docs/models.md):
// analytic Jacobian against central differences for the direct and the
// seabed-reflected path; the image source gives the length of the specular
// path; F and Q of the 7-state model.
#include <catch2/catch.hpp>
#include <cmath>

#include "kestrel/models/measurement/multipath_toa.hpp"
#include "kestrel/models/motion/constant_velocity_3d_sound_speed.hpp"

namespace {

using Motion = kestrel::ConstantVelocity3DSoundSpeed<double>;
using Toa = kestrel::MultipathToa<Motion, 4>;
using kestrel::ArrivalPath;
using L = Motion::Layout;

/// The UW-003 geometry (docs/scenarios.md), plus one beacon moored 40 m down (so the beacon
/// depth term of the Jacobian is exercised too).
Toa sonar_model(double beacon3_depth_m = 0.0) {
  Toa toa;
  toa.config.beacon_count = 4;
  toa.config.beacons_m[0] = Toa::Position(0, 0, 0);
  toa.config.beacons_m[1] = Toa::Position(2000, 0, 0);
  toa.config.beacons_m[2] = Toa::Position(0, 2000, 0);
  toa.config.beacons_m[3] = Toa::Position(2000, 2000, beacon3_depth_m);
  toa.config.seabed_depth_m = 150;
  toa.config.sigma_toa_s = 3e-3;
  return toa;
}

Motion::State state(double x, double y, double z, double c) {
  Motion::State s;
  s << x, y, z, 1.2, 1.0, -0.2, c;
  return s;
}

}  // namespace

SCENARIO("the multipath TOA Jacobian matches central differences on both paths", "[models][toa]") {
  const Toa toa = sonar_model(40.0);
  // Shallow, mid-water, near the seabed, under a beacon, and off the array.
  const double states[][4] = {{500, 800, 60, 1500},   {1700, 300, 5, 1498.2}, {1000, 1000, 140, 1501.7},
                              {1990, 1980, 75, 1500}, {-400, 2600, 100, 1499}};
  for (const auto& s : states) {
    GIVEN("a target at (" << s[0] << ", " << s[1] << ", " << s[2] << ") with c = " << s[3]) {
      const Motion::State x = state(s[0], s[1], s[2], s[3]);
      const Toa::Jacobian H = toa.jacobian(x);
      THEN("each column equals (h(x + e) - h(x - e)) / 2e for every channel") {
        for (int col = 0; col < Motion::kStateDim; ++col) {
          // Steps of 1 mm in position and 1 mm/s in c: the times are smooth
          // on metre scales, so the O(h^2) truncation error is ~1e-12 of an
          // entry, far below the 1e-6 relative tolerance and far above
          // double round-off on ~1 s values divided by 2e-3.
          const double h = 1e-3;
          Motion::State xp = x, xm = x;
          xp(col) += h;
          xm(col) -= h;
          const Toa::Measurement d = toa.residual(toa.predict(xp), toa.predict(xm)) / (2 * h);
          for (int ch = 0; ch < Toa::kMeasDim; ++ch) {
            const double scale = std::max(1e-12, H.row(ch).cwiseAbs().maxCoeff());
            INFO("channel " << ch << " column " << col);
            CHECK(std::abs(d(ch) - H(ch, col)) <= 1e-6 * scale);
          }
        }
      }
      THEN("the direct row is paper 003 eq. 7 and the reflected depth entry has the image's sign") {
        const Toa::Position p(s[0], s[1], s[2]);
        for (int b = 0; b < 4; ++b) {
          const Toa::Position bi = toa.config.beacons_m[b];
          const double d = (p - bi).norm();
          const int cd = Toa::channel(b, ArrivalPath::kDirect);
          CHECK(H(cd, L::kX) == Approx((s[0] - bi(0)) / (d * s[3])).epsilon(1e-12));
          CHECK(H(cd, L::kZ) == Approx((s[2] - bi(2)) / (d * s[3])).epsilon(1e-12));
          CHECK(H(cd, L::kC) == Approx(-d / (s[3] * s[3])).epsilon(1e-12));
          const int cr = Toa::channel(b, ArrivalPath::kReflected);
          const double dr = (Toa::Position(s[0], s[1], 300 - s[2]) - bi).norm();
          CHECK(H(cr, L::kZ) == Approx(-(300 - s[2] - bi(2)) / (dr * s[3])).epsilon(1e-12));
          CHECK(H(cr, L::kC) == Approx(-dr / (s[3] * s[3])).epsilon(1e-12));
          CHECK(H.row(cd).segment<3>(L::kVx).isZero());
        }
      }
    }
  }
}

SCENARIO("the reflected time is the length of the specular seabed path over c", "[models][toa]") {
  const Toa toa = sonar_model(40.0);
  GIVEN("a target at 60 m depth and each beacon") {
    const Motion::State x = state(500, 800, 60, 1500);
    const Toa::Measurement t = toa.predict(x);
    THEN("the image-source time equals the two-segment path via the specular point") {
      for (int b = 0; b < 4; ++b) {
        const Toa::Position bi = toa.config.beacons_m[b];
        // Specular point on the seabed: it splits the horizontal separation
        // in the ratio of the heights above the seabed (equal angles).
        const double ht = 150 - 60;
        const double hb = 150 - bi(2);
        const Toa::Position target(500, 800, 60);
        const Toa::Position q = target + (bi - target) * (ht / (ht + hb));
        const Toa::Position specular(q(0), q(1), 150);
        const double path = (specular - target).norm() + (bi - specular).norm();
        CHECK(t(Toa::channel(b, ArrivalPath::kReflected)) == Approx(path / 1500).epsilon(1e-12));
        CHECK(t(Toa::channel(b, ArrivalPath::kDirect)) == Approx((target - bi).norm() / 1500).epsilon(1e-12));
        CHECK(t(Toa::channel(b, ArrivalPath::kReflected)) > t(Toa::channel(b, ArrivalPath::kDirect)));
      }
    }
  }
  GIVEN("a model with two of its four beacon slots configured") {
    Toa two = sonar_model();
    two.config.beacon_count = 2;
    const Motion::State x = state(500, 800, 60, 1500);
    THEN("the unconfigured channels predict 0 with zero Jacobian rows") {
      const Toa::Measurement t = two.predict(x);
      const Toa::Jacobian H = two.jacobian(x);
      for (int ch = 4; ch < Toa::kMeasDim; ++ch) {
        CHECK_FALSE(two.channel_valid(ch));
        CHECK(t(ch) == 0.0);
        CHECK(H.row(ch).isZero());
      }
      CHECK(two.channel_valid(3));
    }
  }
  THEN("channels are 2 * beacon + path") {
    STATIC_REQUIRE(Toa::kMeasDim == 8);
    STATIC_REQUIRE(Toa::channel(3, ArrivalPath::kReflected) == 7);
    STATIC_REQUIRE(Toa::beacon_of(5) == 2);
    STATIC_REQUIRE(Toa::path_of(5) == ArrivalPath::kReflected);
  }
}

SCENARIO("CV-3D + sound speed: F(dt) and Q(dt)", "[models][cv3d]") {
  Motion m;
  m.accel_sigma_mps2 = 0.05;
  m.sound_speed_q_m2ps3 = 0.01;
  GIVEN("a step of 2 s") {
    const double T = 2.0;
    const Motion::Cov F = m.transition(T);
    const Motion::Cov Q = m.process_noise(T);
    THEN("positions advance by T * velocity and c is carried over") {
      const Motion::State x = state(500, 800, 60, 1500);
      const Motion::State y = m.propagate(x, T);
      CHECK(y(L::kX) == Approx(502.4));
      CHECK(y(L::kY) == Approx(802.0));
      CHECK(y(L::kZ) == Approx(59.6));
      CHECK(y.segment<3>(L::kVx) == x.segment<3>(L::kVx));
      CHECK(y(L::kC) == 1500.0);
      CHECK(m.jacobian(x, T) == F);
    }
    THEN("each axis has sa^2 [[T^4/4, T^3/2], [T^3/2, T^2]] and c has qc T") {
      const double q = 0.05 * 0.05;
      for (int a = 0; a < 3; ++a) {
        CHECK(Q(L::kX + a, L::kX + a) == Approx(q * 16 / 4));
        CHECK(Q(L::kX + a, L::kVx + a) == Approx(q * 8 / 2));
        CHECK(Q(L::kVx + a, L::kX + a) == Approx(q * 8 / 2));
        CHECK(Q(L::kVx + a, L::kVx + a) == Approx(q * 4));
      }
      CHECK(Q(L::kC, L::kC) == Approx(0.02));
      CHECK(Q(L::kX, L::kY) == 0.0);
      CHECK(Q(L::kX, L::kC) == 0.0);
      CHECK((Q - Q.transpose()).isZero());
    }
  }
}
