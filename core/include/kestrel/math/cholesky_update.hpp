// SPDX-License-Identifier: Apache-2.0
// Lower-triangular Cholesky factors on fixed-size storage: the rank-1 update
// and downdate the square-root sigma-point filters need (van der Merwe and
// Wan 2001, "The square-root unscented Kalman filter...", eq. for cholupdate;
// the algorithm is LINPACK's dchud/dchdd, Golub and Van Loan 4th ed. 6.5.4),
// and a factorisation that accepts positive semi-definite matrices (the DWNA
// process noise of CV-2D is singular, so LLT cannot give its square root).
//
// Why not Eigen: LLT::rankUpdate in Eigen 3.4 builds a dynamic-size
// temporary and allocates on the heap (EIGEN_NO_MALLOC aborts). Everything
// here is loops over compile-time sizes, no heap, no recursion.
//
// Conventions: L is lower triangular with P = L L^T. Every function works on
// a copy and writes its output only on success (commit-on-success, like the
// filters): a failed downdate leaves L unchanged.
#pragma once

#include <Eigen/Core>

#include "kestrel/math/eigen.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"

namespace kestrel {

/// L <- chol(L L^T + w v v^T) for a scalar weight w (w > 0: update; w < 0:
/// downdate by sqrt(|w|) v; w = 0: no change). L must be lower triangular;
/// only its lower triangle is read and written.
/// Update: Givens rotations, which also handle zero pivots (a semidefinite
/// factor such as the square root of a DWNA Q). Downdate: hyperbolic
/// rotations; it is refused when a new pivot r satisfies r^2 <= eps * L_kk^2,
/// i.e. the result would be positive definite only within round-off.
/// @return kOk; kNotPositiveDefinite (downdate would lose positive
///         definiteness, L unchanged); kNonFinite (NaN/Inf input, L unchanged).
template <class S, int kN>
[[nodiscard]] Status cholesky_rank1_update(Mat<S, kN, kN>& L, const Vec<S, kN>& v, S w) {
  using T = ScalarTraits<S>;
  if (!T::is_finite(w)) return Status::kNonFinite;
  if (!(w > S(0)) && !(w < S(0))) return Status::kOk;
  const bool downdate = w < S(0);
  const S root_w = T::sqrt(downdate ? -w : w);
  Vec<S, kN> x = v * root_w;
  Mat<S, kN, kN> out = L;
  const S eps = Eigen::NumTraits<S>::epsilon();
  for (int k = 0; k < kN; ++k) {
    const S lkk = out(k, k);
    const S xk = x(k);
    if (!T::is_finite(lkk) || !T::is_finite(xk)) return Status::kNonFinite;
    if (!downdate) {
      const S r = T::hypot(lkk, xk);
      if (!(r > S(0))) continue;  // zero pivot and nothing to add: column stays 0
      const S c = lkk / r;
      const S s = xk / r;
      out(k, k) = r;
      for (int i = k + 1; i < kN; ++i) {
        const S lik = out(i, k);
        out(i, k) = c * lik + s * x(i);
        x(i) = c * x(i) - s * lik;
      }
    } else {
      const S r2 = lkk * lkk - xk * xk;
      if (!(r2 > eps * lkk * lkk)) return Status::kNotPositiveDefinite;
      const S r = T::sqrt(r2);
      const S c = r / lkk;
      const S s = xk / lkk;
      out(k, k) = r;
      for (int i = k + 1; i < kN; ++i) {
        out(i, k) = (out(i, k) - s * x(i)) / c;
        x(i) = c * x(i) - s * out(i, k);
      }
    }
  }
  for (int c = 0; c < kN; ++c) {
    for (int r = c; r < kN; ++r) {
      if (!T::is_finite(out(r, c))) return Status::kNonFinite;
    }
  }
  L = out;
  return Status::kOk;
}

/// Rank-kM update or downdate: L <- chol(L L^T + w U U^T), one column of U
/// after the other (van der Merwe 2004, SR-UKF measurement update:
/// S = cholupdate(S, K S_y, -1)). All or nothing: on failure L is unchanged.
/// @return kOk; kNotPositiveDefinite; kNonFinite.
template <class S, int kN, int kM>
[[nodiscard]] Status cholesky_rank_update(Mat<S, kN, kN>& L, const Mat<S, kN, kM>& U, S w) {
  Mat<S, kN, kN> out = L;
  for (int j = 0; j < kM; ++j) {
    KESTREL_TRY(cholesky_rank1_update<S, kN>(out, U.col(j), w));
  }
  L = out;
  return Status::kOk;
}

/// Lower-triangular L with A = L L^T for a symmetric positive semi-definite A
/// (reads the lower triangle). A pivot d_j <= tol_j is treated as an exact
/// zero and its column set to 0, with tol_j = 16 * kTolN * eps *
/// (|A_jj| + sum_k L_jk^2), the scale of d_j's round-off (a rank-deficient
/// matrix such as the DWNA Q; kTolN = n by default; a diagonal scaling of A,
/// such as a change of units, does not change which pivots are zero); a
/// pivot below -tol_j means A is indefinite. A diagonal block of a
/// larger block-diagonal matrix passes that matrix's size as kTolN, so its
/// factor is exactly the corresponding block of the larger factor.
/// @return kOk; kNotPositiveDefinite (indefinite A; L unchanged); kNonFinite.
template <class S, int kN, int kTolN = kN>
[[nodiscard]] Status cholesky_semidefinite(const Mat<S, kN, kN>& A, Mat<S, kN, kN>& L) {
  using T = ScalarTraits<S>;
  for (int i = 0; i < kN; ++i) {
    if (!T::is_finite(A(i, i))) return Status::kNonFinite;
  }
  const S rel_tol = S(16 * kTolN) * Eigen::NumTraits<S>::epsilon();
  Mat<S, kN, kN> out = Mat<S, kN, kN>::Zero();
  for (int j = 0; j < kN; ++j) {
    S d = A(j, j);
    S mag = A(j, j) < S(0) ? -A(j, j) : A(j, j);
    for (int k = 0; k < j; ++k) {
      d -= out(j, k) * out(j, k);
      mag += out(j, k) * out(j, k);
    }
    // The round-off of d is relative to the terms that form it, not to the
    // largest diagonal: a tolerance on max_i A_ii zeroes a small channel of
    // a matrix in mixed units (R of the polar radar in float: 2.7e-5 rad^2
    // next to 9 m^2 is below 32 eps * 9).
    const S tol = rel_tol * mag;
    if (!T::is_finite(d)) return Status::kNonFinite;
    if (d < -tol) return Status::kNotPositiveDefinite;
    if (!(d > tol)) continue;  // semidefinite direction: column stays zero
    const S ljj = T::sqrt(d);
    out(j, j) = ljj;
    for (int i = j + 1; i < kN; ++i) {
      S a = A(i, j);
      for (int k = 0; k < j; ++k) a -= out(i, k) * out(j, k);
      out(i, j) = a / ljj;
      if (!T::is_finite(out(i, j))) return Status::kNonFinite;
    }
  }
  L = out;
  return Status::kOk;
}

}  // namespace kestrel
