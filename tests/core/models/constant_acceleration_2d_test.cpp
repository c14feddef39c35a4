// SPDX-License-Identifier: Apache-2.0
// CA-2D motion model: F and Q as docs/models.md writes them.
#include <catch2/catch.hpp>

#include "kestrel/models/motion/constant_acceleration_2d.hpp"

using kestrel::ConstantAcceleration2D;

SCENARIO("CA-2D transition and white-jerk noise follow docs/models.md", "[models][ca2d]") {
  GIVEN("a CA-2D model with qj = 2 and a step T = 0.5 s") {
    ConstantAcceleration2D<double> m;
    m.qj = 2.0;
    const double T = 0.5;
    WHEN("F and Q are built") {
      const auto F = m.transition(T);
      const auto Q = m.process_noise(T);
      THEN("F is blkdiag(F1, F1) with F1 = [[1,T,T^2/2],[0,1,T],[0,0,1]]") {
        for (int a = 0; a < 2; ++a) {
          const int o = 3 * a;
          CHECK(F(o + 0, o + 1) == T);
          CHECK(F(o + 0, o + 2) == T * T / 2);
          CHECK(F(o + 1, o + 2) == T);
          CHECK(F(o + 2, o + 2) == 1.0);
        }
        CHECK(F.block<3, 3>(0, 3).isZero());
        CHECK(F.block<3, 3>(3, 0).isZero());
      }
      THEN("Q is qj times the integrated white-jerk matrix, per axis") {
        // Exact rationals of T = 0.5; tolerance is round-off only.
        CHECK(Q(0, 0) == Approx(2.0 * 0.03125 / 20).epsilon(1e-15));
        CHECK(Q(0, 1) == Approx(2.0 * 0.0625 / 8).epsilon(1e-15));
        CHECK(Q(0, 2) == Approx(2.0 * 0.125 / 6).epsilon(1e-15));
        CHECK(Q(1, 1) == Approx(2.0 * 0.125 / 3).epsilon(1e-15));
        CHECK(Q(1, 2) == Approx(2.0 * 0.25 / 2).epsilon(1e-15));
        CHECK(Q(2, 2) == Approx(2.0 * 0.5).epsilon(1e-15));
        CHECK(Q.block<3, 3>(3, 3) == Q.block<3, 3>(0, 0));
        CHECK(Q.block<3, 3>(0, 3).isZero());
        CHECK((Q - Q.transpose()).isZero());
      }
    }
    WHEN("a state is propagated") {
      Eigen::Matrix<double, 6, 1> x;
      x << 1, 2, 4, -1, 3, -2;
      const auto xp = m.propagate(x, T);
      THEN("positions follow p + v T + a T^2 / 2") {
        CHECK(xp(0) == Approx(1 + 2 * T + 4 * T * T / 2));
        CHECK(xp(3) == Approx(-1 + 3 * T - 2 * T * T / 2));
        CHECK(xp(1) == Approx(2 + 4 * T));
      }
    }
  }
}
