// SPDX-License-Identifier: Apache-2.0
// The structure kernels of kestrel/filters/structure.hpp against the dense
// products they replace, and the structure contracts of the models that
// expose it (CA-2D: F and Q block-diagonal, F1 unit upper triangular).
// Tolerance: the kernels reorder the same sums, so they agree with the
// dense products to a few ulps of the entry's scale; 1e-12 of
// sqrt(A_ii A_jj) (covariances) or of the largest entry (gains) leaves room
// for that and catches any missing or misplaced term, which is O(1).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>

#include <Eigen/LU>

#include "kestrel/filters/structure.hpp"
#include "kestrel/models/motion/constant_acceleration_2d.hpp"

namespace {

using kestrel::Mat;
using kestrel::Vec;

/// Deterministic pseudo-random numbers in [-1, 1) (test data only).
struct TestRng {
  std::uint64_t s = 0x9E3779B97F4A7C15ull;
  double next() {
    s ^= s << 13;
    s ^= s >> 7;
    s ^= s << 17;
    return static_cast<double>(s >> 11) * (2.0 / 9007199254740992.0) - 1.0;
  }
};

/// A random symmetric positive definite n x n matrix with entries of very
/// different scales (like a position/velocity/acceleration covariance).
template <int n>
Mat<double, n, n> random_spd(TestRng& rng) {
  Mat<double, n, n> A;
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) A(r, c) = rng.next();
  }
  Mat<double, n, n> P = A * A.transpose() + Mat<double, n, n>::Identity() * 0.1;
  Vec<double, n> scale;
  for (int i = 0; i < n; ++i) scale(i) = std::pow(10.0, (i % 3) - 1);
  const Mat<double, n, n> scaled = scale.asDiagonal() * P * scale.asDiagonal();
  return (scaled + scaled.transpose()) * 0.5;  // exactly symmetric, as a filter's P is
}

/// max |A - B|_ij / sqrt(B_ii B_jj): covariance-relative difference.
template <int n>
double cov_rel_diff(const Mat<double, n, n>& A, const Mat<double, n, n>& B) {
  double worst = 0.0;
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) {
      worst = std::max(worst, std::abs(A(r, c) - B(r, c)) / std::sqrt(B(r, r) * B(c, c)));
    }
  }
  return worst;
}

template <class Derived>
bool exactly_symmetric(const Eigen::MatrixBase<Derived>& A) {
  for (int r = 0; r < A.rows(); ++r) {
    for (int c = 0; c < r; ++c) {
      if (!(A(r, c) == A(c, r))) return false;  // exact equality is the claim
    }
  }
  return true;
}

/// A block-diagonal model whose F1 is a full (not triangular) 2x2 block:
/// the generic branch of transform_covariance.
struct FullBlockMotion {
  using Scalar = double;
  static constexpr int kStateDim = 4;
  static constexpr int kAxisDim = 2;
  struct Layout {
    static constexpr int kX = 0;
    static constexpr int kY = 2;
  };
  using State = Vec<double, 4>;
  using Cov = Mat<double, 4, 4>;
  Mat<double, 2, 2> F1 = Mat<double, 2, 2>::Identity();
  Mat<double, 2, 2> Q1 = Mat<double, 2, 2>::Identity();
  Mat<double, 2, 2> axis_transition(double) const { return F1; }
  Mat<double, 2, 2> axis_process_noise(double) const { return Q1; }
  Cov transition() const {
    Cov F = Cov::Zero();
    F.block<2, 2>(0, 0) = F1;
    F.block<2, 2>(2, 2) = F1;
    return F;
  }
  State propagate(const State& x, double) const { return transition() * x; }
  Cov jacobian(const State&, double) const { return transition(); }
  Cov process_noise(double) const {
    Cov Q = Cov::Zero();
    Q.block<2, 2>(0, 0) = Q1;
    Q.block<2, 2>(2, 2) = Q1;
    return Q;
  }
};

/// A 3-channel measurement of a 6-state whose Jacobian lives in columns 1 and 4.
struct TwoColumnMeasurement {
  using Scalar = double;
  static constexpr int kStateDim = 6;
  static constexpr int kMeasDim = 3;
  static constexpr std::array<int, 2> kJacobianColumns = {1, 4};
  using State = Vec<double, 6>;
  using Measurement = Vec<double, 3>;
  using Jacobian = Mat<double, 3, 6>;
  using NoiseCov = Mat<double, 3, 3>;
  Mat<double, 3, 2> Hc = Mat<double, 3, 2>::Zero();
  Measurement predict(const State& x) const { return jacobian(x) * x; }
  Mat<double, 3, 2> jacobian_columns(const State&) const { return Hc; }
  Jacobian jacobian(const State&) const {
    Jacobian H = Jacobian::Zero();
    H.col(1) = Hc.col(0);
    H.col(4) = Hc.col(1);
    return H;
  }
  NoiseCov noise() const { return NoiseCov::Identity(); }
  Measurement residual(const Measurement& z, const Measurement& zh) const { return z - zh; }
};

}  // namespace

SCENARIO("CA-2D exposes its block structure and honours the contract") {
  using Ca = kestrel::ConstantAcceleration2D<double>;
  STATIC_REQUIRE(kestrel::BlockDiagonalMotion<Ca>);
  STATIC_REQUIRE(kestrel::UnitUpperAxisTransition<Ca>);
  STATIC_REQUIRE_FALSE(kestrel::BlockDiagonalMotion<kestrel::Dense<Ca>>);
  STATIC_REQUIRE(kestrel::MotionModel<kestrel::Dense<Ca>>);
  STATIC_REQUIRE(kestrel::BlockDiagonalMotion<FullBlockMotion>);
  STATIC_REQUIRE_FALSE(kestrel::UnitUpperAxisTransition<FullBlockMotion>);
  STATIC_REQUIRE(kestrel::SparseJacobianMeasurement<TwoColumnMeasurement>);
  STATIC_REQUIRE_FALSE(kestrel::SparseJacobianMeasurement<kestrel::Dense<TwoColumnMeasurement>>);

  Ca m;
  m.qj = 16.0;
  for (const double dt : {0.01, 0.5, 1.0, 4.0}) {
    GIVEN("dt = " << dt) {
      const auto F1 = m.axis_transition(dt);
      THEN("F1 is unit upper triangular") {
        for (int r = 0; r < 3; ++r) {
          CHECK(F1(r, r) == 1.0);
          for (int c = 0; c < r; ++c) CHECK(F1(r, c) == 0.0);
        }
      }
      THEN("F and Q are blkdiag(F1, F1) and blkdiag(Q1, Q1)") {
        Ca::Cov F = Ca::Cov::Zero();
        Ca::Cov Q = Ca::Cov::Zero();
        F.block<3, 3>(0, 0) = F1;
        F.block<3, 3>(3, 3) = F1;
        Q.block<3, 3>(0, 0) = m.axis_process_noise(dt);
        Q.block<3, 3>(3, 3) = m.axis_process_noise(dt);
        CHECK(m.jacobian(Ca::State::Zero(), dt) == F);
        CHECK(m.process_noise(dt) == Q);
      }
      THEN("propagate() is F x") {
        Ca::State x;
        x << 1000.0, -20.0, 3.0, -500.0, 40.0, -1.5;
        const Ca::State ref = m.transition(dt) * x;
        CHECK((m.propagate(x, dt) - ref).norm() <= 1e-12 * ref.norm());
      }
    }
  }
}

SCENARIO("Block-wise F P F^T equals the dense product") {
  TestRng rng;
  GIVEN("CA-2D (unit upper triangular F1) and random covariances") {
    kestrel::ConstantAcceleration2D<double> m;
    m.qj = 3.0;
    for (int trial = 0; trial < 20; ++trial) {
      const auto P = random_spd<6>(rng);
      const double dt = 0.05 + 2.0 * std::abs(rng.next());
      const auto F = m.transition(dt);
      const Mat<double, 6, 6> dense = F * P * F.transpose();
      const auto blocks = kestrel::structure::transform_covariance(m, P, dt);
      CHECK(cov_rel_diff<6>(blocks, dense) < 1e-12);
      CHECK(exactly_symmetric(blocks));

      Mat<double, 6, 6> with_q = blocks;
      kestrel::structure::add_process_noise(m, with_q, dt);
      CHECK(cov_rel_diff<6>(with_q, Mat<double, 6, 6>(dense + m.process_noise(dt))) < 1e-12);
      CHECK(exactly_symmetric(with_q));
    }
  }
  GIVEN("a model with a full 2x2 F1 (generic block branch)") {
    FullBlockMotion m;
    for (int trial = 0; trial < 20; ++trial) {
      m.F1 << rng.next(), rng.next(), rng.next(), rng.next();
      const auto P = random_spd<4>(rng);
      const auto F = m.transition();
      const Mat<double, 4, 4> dense = F * P * F.transpose();
      const auto blocks = kestrel::structure::transform_covariance(m, P, 1.0);
      CHECK(cov_rel_diff<4>(blocks, dense) < 1e-12);
      CHECK(exactly_symmetric(blocks));
    }
  }
  GIVEN("an explicit (non block-diagonal) Q") {
    Mat<double, 6, 6> P = random_spd<6>(rng);
    Mat<double, 6, 6> Q = random_spd<6>(rng);
    Q(0, 5) += 0.25;  // slightly asymmetric: the kernel adds (Q + Q^T) / 2
    const Mat<double, 6, 6> expect = P + (Q + Q.transpose()) * 0.5;
    kestrel::structure::add_symmetrised(P, Q);
    CHECK(cov_rel_diff<6>(P, expect) < 1e-15);
    CHECK(exactly_symmetric(P));
  }
}

SCENARIO("Sparse-Jacobian products and the whitened update equal the dense ones") {
  TestRng rng;
  TwoColumnMeasurement h;
  for (int trial = 0; trial < 20; ++trial) {
    GIVEN("random P, Hc, R and a residual") {
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 2; ++c) h.Hc(r, c) = rng.next();
      }
      const auto P = random_spd<6>(rng);
      const auto R = random_spd<3>(rng);
      const kestrel::structure::SparseJacobian<TwoColumnMeasurement> J{h.Hc};
      const Mat<double, 3, 6> H = h.jacobian(TwoColumnMeasurement::State::Zero());
      REQUIRE(J.full() == H);

      const Mat<double, 6, 3> PHt_dense = P * H.transpose();
      const Mat<double, 3, 3> HPHt_dense = H * P * H.transpose();
      const auto PHt = J.p_ht(P);
      const auto HPHt = J.hpht(P);
      CHECK((PHt - PHt_dense).cwiseAbs().maxCoeff() <= 1e-12 * PHt_dense.cwiseAbs().maxCoeff());
      CHECK((HPHt - HPHt_dense).cwiseAbs().maxCoeff() <= 1e-12 * HPHt_dense.cwiseAbs().maxCoeff());
      CHECK(exactly_symmetric(HPHt));

      const Mat<double, 3, 3> S = HPHt_dense + R;
      const Mat<double, 3, 3> Sinv_dense = S.inverse();
      const Mat<double, 6, 3> K_dense = PHt_dense * Sinv_dense;
      const Vec<double, 3> nu(rng.next(), rng.next(), rng.next());
      const double d2_dense = nu.dot(Sinv_dense * nu);

      double d2 = -1.0;
      REQUIRE(kestrel::structure::nis(S, nu, d2));
      CHECK(std::abs(d2 - d2_dense) <= 1e-12 * d2_dense);

      // The whitened update equals the textbook one: U w = K nu, |w|^2 the
      // NIS, and P - U U^T the Joseph form of the optimal gain.
      Mat<double, 6, 3> U;
      Vec<double, 3> w;
      REQUIRE(kestrel::structure::whitened_gain(PHt_dense, S, nu, U, w));
      const Vec<double, 6> Knu = K_dense * nu;
      CHECK((U * w - Knu).cwiseAbs().maxCoeff() <= 1e-12 * Knu.cwiseAbs().maxCoeff());
      CHECK(std::abs(w.squaredNorm() - d2_dense) <= 1e-12 * d2_dense);
      const Mat<double, 6, 6> A = Mat<double, 6, 6>::Identity() - K_dense * H;
      const Mat<double, 6, 6> joseph_dense = A * P * A.transpose() + K_dense * R * K_dense.transpose();
      const auto P_post = kestrel::structure::symmetric_downdate(P, U);
      CHECK(cov_rel_diff<6>(P_post, joseph_dense) < 1e-10);
      CHECK(exactly_symmetric(P_post));
    }
  }
  GIVEN("an S that is not positive definite") {
    Mat<double, 2, 2> S;
    S << 1.0, 2.0, 2.0, 1.0;
    Mat<double, 6, 2> U = Mat<double, 6, 2>::Constant(7.0);
    Vec<double, 2> w = Vec<double, 2>::Constant(7.0);
    double d2 = 7.0;
    THEN("whitened_gain() and nis() refuse it and write nothing") {
      CHECK_FALSE(kestrel::structure::whitened_gain(Mat<double, 6, 2>(Mat<double, 6, 2>::Ones()), S,
                                                    Vec<double, 2>(1.0, 1.0), U, w));
      CHECK_FALSE(kestrel::structure::nis(S, Vec<double, 2>(1.0, 1.0), d2));
      CHECK(U == Mat<double, 6, 2>::Constant(7.0));
      CHECK(w == Vec<double, 2>::Constant(7.0));
      CHECK(d2 == 7.0);
    }
  }
}

SCENARIO("all_finite_mirrored finds a non-finite coefficient anywhere in a mirrored matrix") {
  TestRng rng;
  const auto P = random_spd<6>(rng);
  const Mat<float, 6, 6> Pf = P.cast<float>();
  CHECK(kestrel::structure::all_finite_mirrored(P));
  CHECK(kestrel::structure::all_finite_mirrored(Pf));
  const double bad[3] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                         -std::numeric_limits<double>::infinity()};
  for (int c = 0; c < 6; ++c) {
    for (int r = 0; r <= c; ++r) {
      for (const double b : bad) {
        Mat<double, 6, 6> Q = P;
        Q(r, c) = b;
        Q(c, r) = b;
        Mat<float, 6, 6> Qf = Pf;
        Qf(r, c) = static_cast<float>(b);
        Qf(c, r) = static_cast<float>(b);
        INFO("entry (" << r << ", " << c << ") = " << b);
        CHECK_FALSE(kestrel::structure::all_finite_mirrored(Q));
        CHECK_FALSE(kestrel::structure::all_finite_mirrored(Qf));
      }
    }
  }
  // Huge but finite entries do not overflow the reduction (terms are zeros).
  const Mat<double, 6, 6> huge = Mat<double, 6, 6>::Constant(std::numeric_limits<double>::max());
  CHECK(kestrel::structure::all_finite_mirrored(huge));
}
