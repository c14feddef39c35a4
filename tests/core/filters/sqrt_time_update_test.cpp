// SPDX-License-Identifier: Apache-2.0
// The square-root time update of an affine, block-diagonal motion
// (kestrel/filters/sqrt_time_update.hpp) against the dense triangularisation
// qr{[F Sx, Sq]} it replaces (math/triangular.hpp) and the block factor of
// Q against the n x n semidefinite Cholesky.
// Tolerance: both return the unique lower-triangular factor with a
// non-negative diagonal of the same full-rank matrix, by Householder
// reflections applied in a different order; they agree to a few ulps of
// each row's scale sqrt(P-_ii). 1e-12 of it leaves room for that and
// catches any missing or misplaced term, which is O(1). The factor of Q is
// claimed bit for bit (it skips products that are exactly zero).
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "kestrel/filters/sqrt_time_update.hpp"
#include "kestrel/math/cholesky_update.hpp"
#include "kestrel/math/triangular.hpp"
#include "kestrel/models/motion/constant_acceleration_2d.hpp"
#include "kestrel/models/motion/constant_velocity_2d.hpp"
#include "support/alloc_guard.hpp"

namespace {

using kestrel::Mat;
using kestrel::Status;

/// Deterministic pseudo-random numbers in [-1, 1) (test data only).
struct TestRng {
  std::uint64_t s = 0x2545F4914F6CDD1Dull;
  double next() {
    s ^= s << 13;
    s ^= s >> 7;
    s ^= s << 17;
    return static_cast<double>(s >> 11) * (2.0 / 9007199254740992.0) - 1.0;
  }
};

/// A random lower-triangular factor with a positive diagonal and rows of
/// very different scales (like the factor of a position/velocity/acceleration
/// covariance).
template <int n>
Mat<double, n, n> random_factor(TestRng& rng) {
  Mat<double, n, n> L = Mat<double, n, n>::Zero();
  for (int r = 0; r < n; ++r) {
    const double scale = std::pow(10.0, (r % 3) - 1);
    for (int c = 0; c < r; ++c) L(r, c) = scale * rng.next();
    L(r, r) = scale * (0.1 + std::abs(rng.next()));
  }
  return L;
}

/// A block-diagonal model whose F1 is a full (not triangular) 2x2 block:
/// the generic branch of affine_sqrt().
struct FullBlockMotion {
  using Scalar = double;
  static constexpr int kStateDim = 4;
  static constexpr int kAxisDim = 2;
  struct Layout {
    static constexpr int kX = 0;
    static constexpr int kY = 2;
  };
  using State = kestrel::Vec<double, 4>;
  using Cov = Mat<double, 4, 4>;
  Mat<double, 2, 2> F1 = Mat<double, 2, 2>::Identity();
  Mat<double, 2, 2> Q1 = Mat<double, 2, 2>::Identity();
  Mat<double, 2, 2> axis_transition(double) const { return F1; }
  Mat<double, 2, 2> axis_process_noise(double) const { return Q1; }
  Cov transition(double) const {
    Cov F = Cov::Zero();
    F.block<2, 2>(0, 0) = F1;
    F.block<2, 2>(2, 2) = F1;
    return F;
  }
  State propagate(const State& x, double dt) const { return transition(dt) * x; }
  Cov jacobian(const State&, double dt) const { return transition(dt); }
  Cov process_noise(double) const {
    Cov Q = Cov::Zero();
    Q.block<2, 2>(0, 0) = Q1;
    Q.block<2, 2>(2, 2) = Q1;
    return Q;
  }
};

/// The dense reference: triangularise([F Sx, Sq]).
template <class M>
typename M::Cov dense_update(const M& m, const typename M::Cov& Sx, const typename M::Cov& Sq, double dt) {
  constexpr int n = M::kStateDim;
  Mat<double, n, 2 * n> A;
  A.template leftCols<n>() = m.transition(dt) * Sx;
  A.template rightCols<n>() = Sq;
  return kestrel::triangularise(A);
}

/// max |L - Lref|_ij / sqrt((Lref Lref^T)_ii): each row against its scale.
template <int n>
double row_rel_diff(const Mat<double, n, n>& L, const Mat<double, n, n>& ref) {
  double worst = 0.0;
  for (int r = 0; r < n; ++r) {
    const double scale = ref.row(r).norm();
    for (int c = 0; c < n; ++c) worst = std::max(worst, std::abs(L(r, c) - ref(r, c)) / scale);
  }
  return worst;
}

template <int n>
bool lower_with_nonnegative_diagonal(const Mat<double, n, n>& L) {
  for (int r = 0; r < n; ++r) {
    if (L(r, r) < 0.0) return false;
    for (int c = r + 1; c < n; ++c) {
      if (!(L(r, c) == 0.0)) return false;  // exact zero is the claim
    }
  }
  return true;
}

}  // namespace

SCENARIO("The block-profile square-root time update equals the dense triangularisation",
         "[structured][sigma][sqrt_time_update]") {
  TestRng rng;
  GIVEN("CA-2D, random factors Sx and a full lower-triangular Sq (the explicit-Q predict)") {
    kestrel::ConstantAcceleration2D<double> m;
    m.qj = 3.0;
    for (int trial = 0; trial < 20; ++trial) {
      const auto Sx = random_factor<6>(rng);
      const auto Sq = random_factor<6>(rng);
      const double dt = 0.05 + 2.0 * std::abs(rng.next());
      const auto L = kestrel::sigma::affine_sqrt_time_update(m, Sx, Sq, dt);
      const auto ref = dense_update(m, Sx, Sq, dt);
      CHECK(lower_with_nonnegative_diagonal<6>(L));
      CHECK(row_rel_diff<6>(L, ref) < 1e-12);
    }
  }
  GIVEN("CA-2D with the model's own block-diagonal Q") {
    kestrel::ConstantAcceleration2D<double> m;
    m.qj = 16.0;
    for (int trial = 0; trial < 20; ++trial) {
      const auto Sx = random_factor<6>(rng);
      const double dt = 0.05 + 2.0 * std::abs(rng.next());
      Mat<double, 6, 6> Sq;
      REQUIRE(kestrel::sigma::block_sqrt_process_noise(m, dt, Sq) == Status::kOk);
      const auto L = kestrel::sigma::affine_sqrt_time_update(m, Sx, Sq, dt);
      CHECK(lower_with_nonnegative_diagonal<6>(L));
      CHECK(row_rel_diff<6>(L, dense_update(m, Sx, Sq, dt)) < 1e-12);
    }
  }
  GIVEN("CV-2D with its singular DWNA Q (zero columns in Sq)") {
    kestrel::ConstantVelocity2D<double> m;
    m.sa = 0.1;
    for (int trial = 0; trial < 20; ++trial) {
      const auto Sx = random_factor<4>(rng);
      const double dt = 0.05 + 2.0 * std::abs(rng.next());
      Mat<double, 4, 4> Sq;
      REQUIRE(kestrel::sigma::block_sqrt_process_noise(m, dt, Sq) == Status::kOk);
      const auto L = kestrel::sigma::affine_sqrt_time_update(m, Sx, Sq, dt);
      CHECK(lower_with_nonnegative_diagonal<4>(L));
      CHECK(row_rel_diff<4>(L, dense_update(m, Sx, Sq, dt)) < 1e-12);
    }
  }
  GIVEN("a model with a full 2x2 F1 (generic block branch)") {
    FullBlockMotion m;
    for (int trial = 0; trial < 20; ++trial) {
      m.F1 << rng.next(), rng.next(), rng.next(), rng.next();
      const auto Sx = random_factor<4>(rng);
      const auto Sq = random_factor<4>(rng);
      const auto L = kestrel::sigma::affine_sqrt_time_update(m, Sx, Sq, 1.0);
      CHECK(lower_with_nonnegative_diagonal<4>(L));
      CHECK(row_rel_diff<4>(L, dense_update(m, Sx, Sq, 1.0)) < 1e-12);
    }
  }
  GIVEN("a zero Sx and Sq (rows already zero: no reflection)") {
    kestrel::ConstantAcceleration2D<double> m;
    const Mat<double, 6, 6> zero = Mat<double, 6, 6>::Zero();
    CHECK(kestrel::sigma::affine_sqrt_time_update(m, zero, zero, 0.5).isZero(0.0));
  }
}

SCENARIO("The block factor of Q is the n x n semidefinite Cholesky, bit for bit",
         "[structured][sigma][sqrt_time_update]") {
  GIVEN("CA-2D (full-rank Q1) and CV-2D (singular DWNA Q1) over a range of steps") {
    kestrel::ConstantAcceleration2D<double> ca;
    ca.qj = 16.0;
    kestrel::ConstantVelocity2D<double> cv;
    cv.sa = 0.1;
    for (const double dt : {1e-3, 0.05, 0.5, 1.0, 4.0}) {
      Mat<double, 6, 6> block_ca, full_ca;
      REQUIRE(kestrel::sigma::block_sqrt_process_noise(ca, dt, block_ca) == Status::kOk);
      REQUIRE(kestrel::cholesky_semidefinite<double, 6>(ca.process_noise(dt), full_ca) == Status::kOk);
      CHECK(block_ca == full_ca);
      Mat<double, 4, 4> block_cv, full_cv;
      REQUIRE(kestrel::sigma::block_sqrt_process_noise(cv, dt, block_cv) == Status::kOk);
      REQUIRE(kestrel::cholesky_semidefinite<double, 4>(cv.process_noise(dt), full_cv) == Status::kOk);
      CHECK(block_cv == full_cv);
    }
  }
  GIVEN("a non-finite or an indefinite Q1") {
    FullBlockMotion m;
    Mat<double, 4, 4> Sq = Mat<double, 4, 4>::Identity();
    m.Q1(1, 1) = std::numeric_limits<double>::quiet_NaN();
    CHECK(kestrel::sigma::block_sqrt_process_noise(m, 1.0, Sq) == Status::kNonFinite);
    m.Q1 << 1.0, 0.0, 0.0, -1.0;
    CHECK(kestrel::sigma::block_sqrt_process_noise(m, 1.0, Sq) == Status::kNotPositiveDefinite);
    THEN("Sq is left unchanged") { CHECK(Sq == Mat<double, 4, 4>::Identity()); }
  }
}

SCENARIO("The block-profile square-root time update allocates nothing", "[structured][sigma][alloc]") {
  TestRng rng;
  kestrel::ConstantAcceleration2D<double> m;
  m.qj = 16.0;
  const auto Sx = random_factor<6>(rng);
  Mat<double, 6, 6> Sq, L;
  Status st = Status::kOk;
  std::size_t allocations = 0;
  {
    kestrel::test::AllocationGuard guard;
    st = kestrel::sigma::block_sqrt_process_noise(m, 0.5, Sq);
    L = kestrel::sigma::affine_sqrt_time_update(m, Sx, Sq, 0.5);
    allocations = guard.allocations();
  }
  REQUIRE(st == Status::kOk);
  CHECK(L(0, 0) > 0.0);
  CHECK(allocations == 0);
}
