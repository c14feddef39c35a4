// SPDX-License-Identifier: Apache-2.0
// The square-root time update of an affine, block-diagonal motion model:
// Sx- = qr{[F Sx, sqrt(Q)]}, exactly the SR-UKF and SR-CDKF time update of
// such a model (van der Merwe 2004, algorithms 10 and 11; docs/filters.md,
// "Why the affine time update is exact"). The triangularisation is
// math/triangular.hpp's Householder (Golub and Van Loan 4th ed. 5.2.2)
// restricted to the compound matrix's non-zeros: with the columns ordered by
// axis block, row j is zero past column 2d (j/d + 1), and no reflection fills
// those zeros, so each reflection acts on a shorter, compile-time-sized
// segment. The factor of Q = blkdiag(Q1, ...) is blkdiag(chol(Q1), ...), bit
// for bit the blocks of the full one. Derivation: docs/filters.md, "The
// staircase of the square-root time update".
#pragma once

#include "kestrel/filters/sigma_points.hpp"
#include "kestrel/filters/structure.hpp"
#include "kestrel/math/cholesky_update.hpp"
#include "kestrel/math/eigen.hpp"
#include "kestrel/math/finite.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"

namespace kestrel::sigma {

/// Lower-triangular factor of the model's Q(dt) = blkdiag(Q1, ..., Q1),
/// Q1 = axis_process_noise(dt), from one d x d semidefinite Cholesky of Q1
/// with the n x n matrix's zero-pivot tolerance (so the result is the n x n
/// cholesky_semidefinite(Q) exactly: the off-block products it skips are 0).
/// @return kOk; kNonFinite (NaN/Inf in Q1); kNotPositiveDefinite (Q1
///         indefinite). Sq is written only on kOk.
template <BlockDiagonalMotion M>
[[nodiscard]] Status block_sqrt_process_noise(const M& motion, typename M::Scalar dt, typename M::Cov& Sq) {
  using S = typename M::Scalar;
  constexpr int d = M::kAxisDim;
  constexpr int kAxes = M::kStateDim / d;
  const Mat<S, d, d> Q1 = motion.axis_process_noise(dt);
  if (!all_finite(Q1)) return Status::kNonFinite;
  Mat<S, d, d> L1;
  KESTREL_TRY(cholesky_semidefinite<S, d, M::kStateDim>(Q1, L1));
  Sq.setZero();
  structure::static_for<0, kAxes>([&](auto ia) {
    constexpr int i = decltype(ia)::value;
    Sq.template block<d, d>(i * d, i * d) = L1;
  });
  return Status::kOk;
}

/// Lower-triangular Sx- (non-negative diagonal) with
/// Sx- Sx-^T = F Sx Sx^T F^T + Sq Sq^T, F = blkdiag(axis_transition(dt), ...),
/// for lower-triangular Sx and Sq: the triangularisation qr{[F Sx, Sq]} on
/// the staircase profile of the header note.
template <BlockDiagonalMotion M>
typename M::Cov affine_sqrt_time_update(const M& motion, const typename M::Cov& Sx, const typename M::Cov& Sq,
                                        typename M::Scalar dt) {
  using S = typename M::Scalar;
  using T = ScalarTraits<S>;
  constexpr int n = M::kStateDim;
  constexpr int d = M::kAxisDim;
  // B = M^T, M's columns in axis-block order: column r of B is row r of M
  // (Householder on B's columns clears M's rows). Entries of column r past
  // its profile end are never read, so never written.
  const typename M::Cov FS = affine_sqrt(motion, Sx, dt);
  Mat<S, 2 * n, n> B;
  structure::static_for<0, n>([&](auto ra) {
    constexpr int r = decltype(ra)::value;
    structure::static_for<0, r / d + 1>([&](auto ba) {
      constexpr int b = decltype(ba)::value;
      B.col(r).template segment<d>(2 * d * b) = FS.row(r).template segment<d>(d * b).transpose();
      B.col(r).template segment<d>(2 * d * b + d) = Sq.row(r).template segment<d>(d * b).transpose();
    });
  });
  structure::static_for<0, n>([&](auto ja) {
    constexpr int j = decltype(ja)::value;
    constexpr int kLen = 2 * d * (j / d + 1) - j;  // e_j - j
    auto v = B.col(j).template segment<kLen>(j);
    const S norm2 = v.squaredNorm();
    if (!(norm2 > S(0))) return;  // row j already zero past its diagonal
    const S bjj = v(0);
    // alpha takes the sign opposite to b_jj, so v_0 = b_jj - alpha does not cancel.
    const S alpha = bjj < S(0) ? T::sqrt(norm2) : -T::sqrt(norm2);
    v(0) = bjj - alpha;
    // H = I - 2 v v^T / (v^T v) with v^T v = 2 (norm2 - b_jj alpha) > 0
    // (alpha^2 = norm2 and b_jj alpha <= 0): one division per reflection.
    const S inv = S(1) / (norm2 - bjj * alpha);
    structure::static_for<j + 1, n>([&](auto ca) {
      constexpr int c = decltype(ca)::value;
      auto col = B.col(c).template segment<kLen>(j);
      col -= (v.dot(col) * inv) * v;
    });
    B(j, j) = alpha;
  });
  // L = R^T, each row of R flipped to a non-negative diagonal (R^T R unchanged).
  typename M::Cov L = M::Cov::Zero();
  structure::static_for<0, n>([&](auto ra) {
    constexpr int r = decltype(ra)::value;
    const S sign = B(r, r) < S(0) ? S(-1) : S(1);
    L.col(r).template tail<n - r>() = sign * B.row(r).template tail<n - r>().transpose();
  });
  return L;
}

}  // namespace kestrel::sigma
