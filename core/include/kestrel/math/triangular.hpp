// SPDX-License-Identifier: Apache-2.0
// Square-root covariance helpers on fixed-size storage: the "qr{}" step of
// the square-root sigma-point filters (van der Merwe 2004, SR-UKF and SR-CDKF
// algorithms: S = qr{[compound matrix]}) and triangular solves with a
// lower-triangular factor (K = (Pxz / S_y^T) / S_y).
//
// triangularise(A): for an n x k compound matrix A (k >= n) it returns the
// lower-triangular L with L L^T = A A^T, positive diagonal, by Householder
// reflections applied to A^T (Golub and Van Loan 4th ed. 5.2.2). Only the
// R factor is formed, never Q. Loops run over compile-time sizes; no heap.
#pragma once

#include "kestrel/math/eigen.hpp"
#include "kestrel/scalar/scalar_traits.hpp"

namespace kestrel {

/// Lower-triangular L (n x n, non-negative diagonal) with L L^T = A A^T.
template <class S, int kN, int kK>
Mat<S, kN, kN> triangularise(const Mat<S, kN, kK>& A) {
  static_assert(kK >= kN, "the compound matrix needs at least n columns");
  using T = ScalarTraits<S>;
  Mat<S, kK, kN> B = A.transpose();
  Vec<S, kK> v;
  for (int j = 0; j < kN; ++j) {
    S norm2 = S(0);
    for (int i = j; i < kK; ++i) norm2 += B(i, j) * B(i, j);
    if (!(norm2 > S(0))) continue;  // column already zero below the diagonal
    const S norm = T::sqrt(norm2);
    const S bjj = B(j, j);
    const S alpha = bjj < S(0) ? norm : -norm;  // avoid cancellation in v_0
    for (int i = j; i < kK; ++i) v(i) = B(i, j);
    v(j) = bjj - alpha;
    const S vnorm2 = norm2 - bjj * bjj + v(j) * v(j);
    B(j, j) = alpha;
    for (int i = j + 1; i < kK; ++i) B(i, j) = S(0);
    if (!(vnorm2 > S(0))) continue;
    for (int c = j + 1; c < kN; ++c) {
      S dot = S(0);
      for (int i = j; i < kK; ++i) dot += v(i) * B(i, c);
      const S f = S(2) * dot / vnorm2;
      for (int i = j; i < kK; ++i) B(i, c) -= f * v(i);
    }
  }
  // L = R^T with each row of R made to have a non-negative diagonal (a sign
  // flip of a row of R leaves R^T R unchanged).
  Mat<S, kN, kN> L = Mat<S, kN, kN>::Zero();
  for (int r = 0; r < kN; ++r) {
    const S sign = B(r, r) < S(0) ? S(-1) : S(1);
    for (int c = r; c < kN; ++c) L(c, r) = sign * B(r, c);
  }
  return L;
}

/// X with L X = B (forward substitution); L lower triangular, nonzero diagonal.
template <class S, int kN, int kC>
Mat<S, kN, kC> solve_lower(const Mat<S, kN, kN>& L, const Mat<S, kN, kC>& B) {
  Mat<S, kN, kC> X;
  for (int c = 0; c < kC; ++c) {
    for (int i = 0; i < kN; ++i) {
      S a = B(i, c);
      for (int k = 0; k < i; ++k) a -= L(i, k) * X(k, c);
      X(i, c) = a / L(i, i);
    }
  }
  return X;
}

/// X with L^T X = B (back substitution); L lower triangular, nonzero diagonal.
template <class S, int kN, int kC>
Mat<S, kN, kC> solve_lower_transposed(const Mat<S, kN, kN>& L, const Mat<S, kN, kC>& B) {
  Mat<S, kN, kC> X;
  for (int c = 0; c < kC; ++c) {
    for (int i = kN - 1; i >= 0; --i) {
      S a = B(i, c);
      for (int k = i + 1; k < kN; ++k) a -= L(k, i) * X(k, c);
      X(i, c) = a / L(i, i);
    }
  }
  return X;
}

}  // namespace kestrel
