// SPDX-License-Identifier: Apache-2.0
// CV-2D motion model: F and the DWNA Q as docs/models.md writes them, and the
// noise gain G with sa^2 G G^T = Q.
#include <catch2/catch.hpp>

#include "kestrel/models/motion/constant_velocity_2d.hpp"

using kestrel::ConstantVelocity2D;

SCENARIO("CV-2D transition and DWNA noise follow docs/models.md", "[models][cv2d]") {
  GIVEN("a CV-2D model with sa = 0.3 m/s^2 and T = 0.5 s") {
    ConstantVelocity2D<double> m;
    m.sa = 0.3;
    const double T = 0.5;
    using L = ConstantVelocity2D<double>::Layout;
    STATIC_REQUIRE(L::kX == 0);
    STATIC_REQUIRE(L::kVx == 1);
    STATIC_REQUIRE(L::kY == 2);
    STATIC_REQUIRE(L::kVy == 3);
    WHEN("F, Q and G are built") {
      const auto F = m.transition(T);
      const auto Q = m.process_noise(T);
      const auto G = m.noise_gain(T);
      THEN("F is blkdiag([[1, T], [0, 1]], same)") {
        Eigen::Matrix4d expected;
        expected << 1, T, 0, 0, 0, 1, 0, 0, 0, 0, 1, T, 0, 0, 0, 1;
        CHECK(F == expected);
      }
      THEN("Q is sa^2 [[T^4/4, T^3/2], [T^3/2, T^2]] per axis, no cross-axis terms") {
        // T = 0.5 and sa^2 = 0.09: exact binary fractions times 0.09.
        CHECK(Q(0, 0) == Approx(0.09 * 0.0625 / 4).epsilon(1e-15));
        CHECK(Q(0, 1) == Approx(0.09 * 0.125 / 2).epsilon(1e-15));
        CHECK(Q(1, 1) == Approx(0.09 * 0.25).epsilon(1e-15));
        CHECK(Q.block<2, 2>(2, 2) == Q.block<2, 2>(0, 0));
        CHECK(Q.block<2, 2>(0, 2).isZero(0.0));
        CHECK((Q - Q.transpose()).isZero(0.0));
      }
      THEN("sa^2 G G^T = Q (the kick of the CRPF has exactly the model's covariance)") {
        CHECK((m.sa * m.sa * G * G.transpose() - Q).norm() < 1e-17);
      }
    }
    WHEN("a state is propagated") {
      Eigen::Vector4d x(1000, 10, 1000, 5);
      THEN("it equals F x") { CHECK((m.propagate(x, T) - m.transition(T) * x).isZero(0.0)); }
      THEN("the Jacobian is F") { CHECK(m.jacobian(x, T) == m.transition(T)); }
    }
  }
}
