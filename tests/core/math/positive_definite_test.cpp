// SPDX-License-Identifier: Apache-2.0
// is_positive_definite: agrees with Eigen's LLT on symmetric matrices whose
// eigenvalues are clearly away from zero, in double, float and Q31.32;
// refuses indefinite, negative, singular and NaN matrices; state_status
// tells non-finite from not positive definite.
#include <catch2/catch.hpp>

#include <Eigen/Dense>
#include <limits>

#include "kestrel/math/positive_definite.hpp"
#include "kestrel/math/prng.hpp"
#include "kestrel/scalar/fixed_point.hpp"
#include "kestrel/scalar/fixed_point_eigen.hpp"

namespace {

using M6d = Eigen::Matrix<double, 6, 6>;

/// Q diag(lambda) Q^T with Q orthogonal, scaled like a CA-2D covariance
/// (m, m/s, m/s^2 per axis). Eigenvalues of the unscaled matrix are
/// +-[0.2, 5]; `negative` of them are negative.
M6d random_symmetric(std::uint64_t seed, int negative) {
  kestrel::NormalGenerator<double> n(seed);
  M6d A;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) A(i, j) = n();
  const Eigen::HouseholderQR<M6d> qr(A);
  const M6d Q = qr.householderQ();
  Eigen::Matrix<double, 6, 1> lambda;
  for (int i = 0; i < 6; ++i) lambda(i) = (0.2 + 4.8 * std::abs(n()) / 3.0) * (i < negative ? -1.0 : 1.0);
  const M6d M = Q * lambda.asDiagonal() * Q.transpose();
  const Eigen::Matrix<double, 6, 1> s(30.0, 5.0, 1.0, 30.0, 5.0, 1.0);
  const M6d P = s.asDiagonal() * M * s.asDiagonal();
  return (P + P.transpose()) * 0.5;
}

template <class S>
Eigen::Matrix<S, 6, 6> cast(const M6d& P) {
  Eigen::Matrix<S, 6, 6> out;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) out(i, j) = kestrel::ScalarTraits<S>::from_double(P(i, j));
  return out;
}

}  // namespace

TEMPLATE_TEST_CASE("Scenario: the LDL^T check agrees with Eigen's LLT away from singularity", "[math][pd]", double,
                   float, kestrel::Q31_32) {
  using S = TestType;
  int pd = 0;
  int not_pd = 0;
  for (std::uint64_t seed = 1; seed <= 400; ++seed) {
    const int negative = static_cast<int>(seed % 4);  // 0: PD; 1-3 negative eigenvalues
    const M6d P = random_symmetric(seed, negative);
    const bool expected = Eigen::LLT<M6d>(P).info() == Eigen::Success;
    REQUIRE(expected == (negative == 0));
    CHECK(kestrel::is_positive_definite(cast<S>(P)) == expected);
    (expected ? pd : not_pd)++;
  }
  CHECK(pd == 100);
  CHECK(not_pd == 300);
}

TEMPLATE_TEST_CASE("Scenario: matrices a covariance must never be are refused", "[math][pd]", double, float,
                   kestrel::Q31_32) {
  using S = TestType;
  using M = Eigen::Matrix<S, 3, 3>;
  GIVEN("the identity") { CHECK(kestrel::is_positive_definite(M(M::Identity()))); }
  GIVEN("a negative variance") {
    M P = M::Identity();
    P(1, 1) = S(-1);
    CHECK_FALSE(kestrel::is_positive_definite(P));
  }
  GIVEN("a zero variance (singular)") {
    M P = M::Identity();
    P(2, 2) = S(0);
    CHECK_FALSE(kestrel::is_positive_definite(P));
  }
  GIVEN("positive variances with a correlation above 1") {
    M P = M::Identity();
    P(0, 1) = P(1, 0) = S(2);
    CHECK_FALSE(kestrel::is_positive_definite(P));
  }
  GIVEN("the failing entry is found in the last pivot") {
    // [[4 2 2] [2 4 2] [2 2 c]]: D = 4, 3, c - 4/3, so PD for c > 4/3 only.
    M P;
    P << S(4), S(2), S(2), S(2), S(4), S(2), S(2), S(2), S(2);
    CHECK(kestrel::is_positive_definite(P));
    P(2, 2) = S(1);
    CHECK_FALSE(kestrel::is_positive_definite(P));
  }
}

TEMPLATE_TEST_CASE("Scenario: NaN and Inf fail, and state_status names the cause", "[math][pd]", double, float) {
  using S = TestType;
  using M = Eigen::Matrix<S, 3, 3>;
  using V = Eigen::Matrix<S, 3, 1>;
  const S nan = std::numeric_limits<S>::quiet_NaN();
  M P = M::Identity();
  const V x = V::Zero();
  CHECK(kestrel::state_status(x, P) == kestrel::Status::kOk);
  P(0, 2) = P(2, 0) = nan;
  CHECK_FALSE(kestrel::is_positive_definite(P));
  CHECK(kestrel::state_status(x, P) == kestrel::Status::kNonFinite);
  P = M::Identity();
  P(1, 1) = std::numeric_limits<S>::infinity();
  CHECK_FALSE(kestrel::is_positive_definite(P));
  P = M::Identity();
  P(0, 0) = S(-2);
  CHECK(kestrel::state_status(x, P) == kestrel::Status::kNotPositiveDefinite);
  V bad = V::Zero();
  bad(1) = nan;
  CHECK(kestrel::state_status(bad, M(M::Identity())) == kestrel::Status::kNonFinite);
}
