// SPDX-License-Identifier: Apache-2.0
// Fixed-size Cholesky helpers: the rank-1 update/downdate matches a fresh
// factorisation; a downdate that would lose positive definiteness returns a
// status and leaves L unchanged; the semidefinite factor handles the
// singular DWNA Q and keeps a small channel of a matrix in mixed units;
// the Householder triangularisation of a compound matrix
// gives chol(A A^T); none of them touches the heap.
#include <catch2/catch.hpp>

#include <Eigen/Dense>
#include <cmath>

#include "kestrel/math/cholesky_update.hpp"
#include "kestrel/math/prng.hpp"
#include "kestrel/math/triangular.hpp"
#include "kestrel/models/motion/constant_velocity_2d.hpp"
#include "support/alloc_guard.hpp"

using kestrel::Status;
using M5 = Eigen::Matrix<double, 5, 5>;
using V5 = Eigen::Matrix<double, 5, 1>;

namespace {

M5 random_spd(std::uint64_t seed) {
  kestrel::NormalGenerator<double> n(seed);
  M5 A;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) A(i, j) = n();
  M5 P = A * A.transpose() + M5::Identity();
  // Scales like a tracking covariance: metres and metres per second.
  const V5 s(100.0, 10.0, 1.0, 100.0, 10.0);
  return s.asDiagonal() * P * s.asDiagonal();
}

V5 random_vec(std::uint64_t seed, double scale) {
  kestrel::NormalGenerator<double> n(seed);
  V5 v;
  for (int i = 0; i < 5; ++i) v(i) = scale * n();
  return v;
}

double rel_diff(const M5& a, const M5& b) { return (a - b).norm() / b.norm(); }

}  // namespace

SCENARIO("a rank-1 Cholesky update or downdate matches a fresh factorisation", "[math][cholupdate]") {
  const M5 P = random_spd(1);
  const M5 L0 = Eigen::LLT<M5>(P).matrixL();
  GIVEN("an update P + 0.7 v v^T") {
    const V5 v = random_vec(2, 30.0);
    M5 L = L0;
    REQUIRE(kestrel::cholesky_rank1_update<double, 5>(L, v, 0.7) == Status::kOk);
    THEN("L equals chol(P + 0.7 v v^T) to round-off and stays lower triangular") {
      const M5 fresh = Eigen::LLT<M5>(P + 0.7 * v * v.transpose()).matrixL();
      // Both are the unique positive-diagonal factor; 1e-13 relative is a
      // few hundred ulps of a 5x5 computation in double.
      CHECK(rel_diff(L, fresh) < 1e-13);
      CHECK(L.triangularView<Eigen::StrictlyUpper>().toDenseMatrix().isZero(0.0));
    }
  }
  GIVEN("a downdate P - 0.5 v v^T that stays positive definite") {
    // v = L u with |u|^2 = 1, so P - 0.5 v v^T has eigenvalues >= half of P's.
    V5 u = random_vec(3, 1.0);
    u.normalize();
    const V5 v = L0 * u;
    M5 L = L0;
    REQUIRE(kestrel::cholesky_rank1_update<double, 5>(L, v, -0.5) == Status::kOk);
    THEN("L equals chol(P - 0.5 v v^T)") {
      const M5 fresh = Eigen::LLT<M5>(P - 0.5 * v * v.transpose()).matrixL();
      CHECK(rel_diff(L, fresh) < 1e-12);
    }
  }
  GIVEN("an update followed by the same downdate") {
    const V5 v = random_vec(4, 50.0);
    M5 L = L0;
    REQUIRE(kestrel::cholesky_rank1_update<double, 5>(L, v, 1.0) == Status::kOk);
    REQUIRE(kestrel::cholesky_rank1_update<double, 5>(L, v, -1.0) == Status::kOk);
    THEN("the original factor comes back") { CHECK(rel_diff(L, L0) < 1e-12); }
  }
  GIVEN("a rank-2 downdate by the columns of U") {
    Eigen::Matrix<double, 5, 2> U;
    U.col(0) = L0 * random_vec(5, 1.0).normalized() * 0.6;
    U.col(1) = L0 * random_vec(6, 1.0).normalized() * 0.6;
    M5 L = L0;
    REQUIRE((kestrel::cholesky_rank_update<double, 5, 2>(L, U, -1.0)) == Status::kOk);
    THEN("L equals chol(P - U U^T)") {
      const M5 fresh = Eigen::LLT<M5>(P - U * U.transpose()).matrixL();
      CHECK(rel_diff(L, fresh) < 1e-12);
    }
  }
}

SCENARIO("a downdate that would lose positive definiteness returns a status", "[math][cholupdate][status]") {
  const M5 P = random_spd(7);
  const M5 L0 = Eigen::LLT<M5>(P).matrixL();
  V5 u = random_vec(8, 1.0);
  u.normalize();
  GIVEN("v = 1.01 L u: P - v v^T has a negative eigenvalue") {
    const V5 v = 1.01 * (L0 * u);
    M5 L = L0;
    THEN("kNotPositiveDefinite and L is unchanged") {
      CHECK(kestrel::cholesky_rank1_update<double, 5>(L, v, -1.0) == Status::kNotPositiveDefinite);
      CHECK(L == L0);
    }
  }
  GIVEN("v = L u exactly: P - v v^T is singular") {
    const V5 v = L0 * u;
    M5 L = L0;
    THEN("kNotPositiveDefinite (definite only within round-off) and L is unchanged") {
      CHECK(kestrel::cholesky_rank1_update<double, 5>(L, v, -1.0) == Status::kNotPositiveDefinite);
      CHECK(L == L0);
    }
  }
  GIVEN("a rank-2 downdate whose second column breaks definiteness") {
    Eigen::Matrix<double, 5, 2> U;
    U.col(0) = L0 * u * 0.5;
    U.col(1) = L0 * u * 0.9;  // 0.25 + 0.81 > 1 along u
    M5 L = L0;
    THEN("all or nothing: kNotPositiveDefinite and L unchanged") {
      CHECK((kestrel::cholesky_rank_update<double, 5, 2>(L, U, -1.0)) == Status::kNotPositiveDefinite);
      CHECK(L == L0);
    }
  }
  GIVEN("a NaN in v") {
    V5 v = L0 * u;
    v(2) = std::numeric_limits<double>::quiet_NaN();
    M5 L = L0;
    THEN("kNonFinite and L unchanged") {
      CHECK(kestrel::cholesky_rank1_update<double, 5>(L, v, 1.0) == Status::kNonFinite);
      CHECK(L == L0);
    }
  }
}

SCENARIO("the semidefinite factor gives a square root of the singular DWNA Q", "[math][cholupdate]") {
  kestrel::ConstantVelocity2D<double> cv;
  cv.sa = 0.1;
  const auto Q = cv.process_noise(1.0);
  GIVEN("Q of CV-2D (rank 2 of 4)") {
    REQUIRE(Eigen::LLT<Eigen::Matrix4d>(Q).info() != Eigen::Success);  // why LLT is not enough
    Eigen::Matrix4d L;
    REQUIRE(kestrel::cholesky_semidefinite<double, 4>(Q, L) == Status::kOk);
    THEN("L L^T = Q and the velocity columns are zero") {
      CHECK((L * L.transpose() - Q).norm() < 1e-15 * Q.norm());
      CHECK(L.col(1).isZero(0.0));
      CHECK(L.col(3).isZero(0.0));
    }
  }
  GIVEN("an indefinite matrix") {
    Eigen::Matrix4d A = Eigen::Matrix4d::Identity();
    A(1, 1) = -0.5;
    Eigen::Matrix4d L = Eigen::Matrix4d::Constant(3.0);
    THEN("kNotPositiveDefinite and the output untouched") {
      CHECK(kestrel::cholesky_semidefinite<double, 4>(A, L) == Status::kNotPositiveDefinite);
      CHECK(L == Eigen::Matrix4d::Constant(3.0));
    }
  }
}

SCENARIO("the semidefinite factor keeps a small channel of a matrix in mixed units", "[math][cholupdate]") {
  GIVEN("the polar radar's R in float: 9 m^2 and (0.3 deg)^2 = 2.74e-5 rad^2") {
    // 2.74e-5 is below 32 eps_float * 9 = 3.4e-5, the zero-pivot tolerance
    // a largest-diagonal rule gives: that rule dropped the bearing channel.
    const float sb = 0.3f * 3.14159265f / 180.0f;
    Eigen::Matrix2f R = Eigen::Matrix2f::Zero();
    R(0, 0) = 9.0f;
    R(1, 1) = sb * sb;
    Eigen::Matrix2f L;
    REQUIRE(kestrel::cholesky_semidefinite<float, 2>(R, L) == Status::kOk);
    THEN("L is the exact diagonal square root") {
      // A diagonal A has no round-off in d_j: sqrt is correctly rounded.
      CHECK(L(0, 0) == 3.0f);
      CHECK(L(1, 1) == std::sqrt(sb * sb));
    }
  }
  GIVEN("the DWNA Q of CV-2D in float with its velocity rows in km/s (D Q D)") {
    kestrel::ConstantVelocity2D<float> cv;
    cv.sa = 2.0f;
    Eigen::Matrix4f D = Eigen::Matrix4f::Identity();
    D(1, 1) = 1e-3f;
    D(3, 3) = 1e-3f;
    const Eigen::Matrix4f Q = D * cv.process_noise(0.5f) * D;
    Eigen::Matrix4f L;
    REQUIRE(kestrel::cholesky_semidefinite<float, 4>(Q, L) == Status::kOk);
    THEN("the velocity columns are still exact zeros and L L^T = Q") {
      CHECK(L.col(1).isZero(0.0f));
      CHECK(L.col(3).isZero(0.0f));
      // float round-off of a 4 x 4 product, relative to Q's norm.
      CHECK((L * L.transpose() - Q).norm() <= 1e-6f * Q.norm());
    }
  }
}

SCENARIO("triangularise gives chol(A A^T) of a compound matrix", "[math][qr]") {
  kestrel::NormalGenerator<double> n(9);
  Eigen::Matrix<double, 4, 12> A;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 12; ++j) A(i, j) = n() * (i + 1) * 10.0;
  A(2, 0) = -A(2, 0);  // some negative leading entries
  const Eigen::Matrix4d L = kestrel::triangularise(A);
  const Eigen::Matrix4d fresh = Eigen::LLT<Eigen::Matrix4d>(A * A.transpose()).matrixL();
  THEN("L is lower triangular with a positive diagonal and equals the Cholesky factor") {
    CHECK(L.triangularView<Eigen::StrictlyUpper>().toDenseMatrix().isZero(0.0));
    CHECK((L.diagonal().array() > 0.0).all());
    CHECK((L - fresh).norm() < 1e-13 * fresh.norm());
  }
  THEN("the triangular solves invert L and L^T") {
    Eigen::Matrix<double, 4, 3> B;
    B << 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12;
    const auto X = kestrel::solve_lower<double, 4, 3>(L, B);
    const auto Y = kestrel::solve_lower_transposed<double, 4, 3>(L, B);
    CHECK((L * X - B).norm() < 1e-12 * B.norm());
    CHECK((L.transpose() * Y - B).norm() < 1e-12 * B.norm());
  }
}

SCENARIO("the square-root helpers allocate nothing", "[math][alloc]") {
  const M5 P = random_spd(10);
  M5 L = Eigen::LLT<M5>(P).matrixL();
  const V5 v = random_vec(11, 10.0);
  Eigen::Matrix<double, 4, 12> A = Eigen::Matrix<double, 4, 12>::Ones();
  A.block<4, 4>(0, 0) += Eigen::Matrix4d::Identity();
  std::size_t allocations = 0;
  Status up, down;
  Eigen::Matrix4d T;
  {
    kestrel::test::AllocationGuard guard;
    up = kestrel::cholesky_rank1_update<double, 5>(L, v, 1.0);
    down = kestrel::cholesky_rank1_update<double, 5>(L, v, -1.0);
    T = kestrel::triangularise(A);
    allocations = guard.allocations();
  }
  REQUIRE(up == Status::kOk);
  REQUIRE(down == Status::kOk);
  CHECK(T(0, 0) > 0.0);
  CHECK(allocations == 0);
}
