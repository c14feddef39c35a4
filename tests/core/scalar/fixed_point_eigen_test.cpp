// SPDX-License-Identifier: Apache-2.0
// FixedPoint as an Eigen scalar: NumTraits, fixed-size products and
// reductions against double, allocation-free, and order-independent sums.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "kestrel/scalar/fixed_point_eigen.hpp"
#include "kestrel/scalar/fixed_point_io.hpp"
#include "support/alloc_guard.hpp"

TEMPLATE_TEST_CASE("Scenario: Eigen computes with the fixed-point scalar", "[fixed_point][eigen]", kestrel::Q31_32,
                   kestrel::Q23_40) {
  using Q = TestType;
  using M6 = kestrel::Mat<Q, 6, 6>;
  using D6 = kestrel::Mat<double, 6, 6>;
  STATIC_REQUIRE(Eigen::NumTraits<Q>::IsComplex == 0);
  STATIC_REQUIRE(Eigen::NumTraits<Q>::epsilon().raw() == 1);
  std::mt19937_64 g(11);
  std::uniform_real_distribution<double> u(-100.0, 100.0);
  GIVEN("random 6x6 matrices") {
    M6 A, B;
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) {
        A(i, j) = Q::from_double(u(g));
        B(i, j) = Q::from_double(u(g));
      }
    }
    const D6 Ad = A.template cast<double>();
    const D6 Bd = B.template cast<double>();
    WHEN("they are multiplied, transposed and summed without touching the heap") {
      kestrel::test::AllocationGuard guard;
      const M6 C = A * B.transpose() + A;
      const Q trace = C.trace();
      const Q dot = A.col(0).dot(B.col(1));
      REQUIRE(guard.allocations() == 0);
      THEN("each entry is within 6 roundings of 0.5 LSB of the double result") {
        const D6 Cd = Ad * Bd.transpose() + Ad;
        const double lsb = std::ldexp(1.0, -Q::kFractionBits);
        // Six products each rounded once (0.5 LSB), exact additions; the
        // double reference itself is exact to 1e-12 at these magnitudes.
        const double tol = 6 * 0.5 * lsb + 1e-11;
        for (int i = 0; i < 6; ++i) {
          for (int j = 0; j < 6; ++j) CHECK(std::fabs(static_cast<double>(C(i, j)) - Cd(i, j)) <= tol);
        }
        CHECK(std::fabs(static_cast<double>(trace) - Cd.trace()) <= 36 * 0.5 * lsb + 1e-10);
        CHECK(std::fabs(static_cast<double>(dot) - Ad.col(0).dot(Bd.col(1))) <= tol);
      }
      THEN("a sum of rounded products does not depend on the order of the additions") {
        Q forward(0);
        Q backward(0);
        for (int k = 0; k < 6; ++k) forward += A(0, k) * B(1, k);
        for (int k = 5; k >= 0; --k) backward += A(0, k) * B(1, k);
        CHECK(forward == backward);
        CHECK(forward == C(0, 1) - A(0, 1));
      }
    }
  }
  GIVEN("scalar helpers Eigen uses") {
    THEN("abs, sqrt, comparisons and integer literals work through Eigen") {
      kestrel::Vec<Q, 3> v(Q(-3), Q(4), Q(0));
      CHECK(v.cwiseAbs().maxCoeff() == Q(4));
      CHECK(v.template head<2>().norm() == Q(5));
      CHECK((v * 2)(1) == Q(8));
    }
  }
}
