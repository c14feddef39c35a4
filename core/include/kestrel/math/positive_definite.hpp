// SPDX-License-Identifier: Apache-2.0
// Positive-definiteness of a symmetric covariance, as the contract every
// filter holds on the P it commits: a P that fails here is refused with
// kNotPositiveDefinite and the filter keeps its previous state.
//
// The test is an LDL^T factorisation of the upper triangle without square
// roots (so it runs in fixed point too): every pivot D_j must be positive
// and finite. n(n-1)/2 divisions (fixed point: n - 1 prepared reciprocals)
// and about n^3/6 + n^2 multiply-adds (15 and about 65 for a 6x6 P).
#pragma once

#include <cstddef>

#include "kestrel/math/eigen.hpp"
#include "kestrel/math/finite.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"

namespace kestrel {

namespace detail {

// Column j of the LDL^T below: w_k = L(j, k) D_k, D_j = P_jj - sum
// L(j, k) w_k, L(i, j) = (P_ij - sum L(i, k) w_k) / D_j, with D_j kept on
// the diagonal of L. Each product L(i, k) w_k = L(i, k) L(j, k) D_k is
// bounded by sqrt(P_ii P_jj) for a positive definite P, so fixed point
// cannot overflow on a matrix that passes.
// The floating-point form has its loops unrolled; the fixed-point form
// keeps them rolled, because there every product is a 64-bit
// multiply-and-shift and the unrolled copy costs a Cortex-M0+ image text it
// cannot spare (figures: docs/performance.md, "The covariance check").
// Fixed point: each column divides by its pivot through one prepared
// reciprocal (FixedPoint::Divisor: 63 significant bits, a quotient within
// 1.5 LSB of the rounded one) instead of a 64-step division per entry; a
// pivot of 1e9 m^2 keeps its precision, which a plain 1/D in Q format
// would not. Only the pivots' signs leave this function.
template <class S, int n, class M>
bool ldlt_pivots_positive_fixed(const M& P) {
  constexpr std::size_t kN = static_cast<std::size_t>(n);
  S L[kN][kN];
  S w[kN];
  for (int j = 0; j < n; ++j) {
    S d = P(j, j);
    for (int k = 0; k < j; ++k) {
      w[k] = L[j][k] * L[k][k];
      d -= L[j][k] * w[k];
    }
    if (!(d > S(0)) || !ScalarTraits<S>::is_finite(d)) return false;
    L[j][j] = d;
    if (j + 1 == n) break;
    const typename S::Divisor by_d = S::divisor(d);
    for (int i = j + 1; i < n; ++i) {
      S v = P(j, i);  // upper triangle: P(i, j) == P(j, i)
      for (int k = 0; k < j; ++k) v -= L[i][k] * w[k];
      L[i][j] = by_d.divide(v);
    }
  }
  return true;
}

template <class S, int n, class M>
bool ldlt_pivots_positive_unrolled(const M& P) {
  constexpr std::size_t kN = static_cast<std::size_t>(n);
  S L[kN][kN];
  S w[kN];
#pragma GCC unroll 16
  for (int j = 0; j < n; ++j) {
    S d = P(j, j);
#pragma GCC unroll 16
    for (int k = 0; k < j; ++k) {
      w[k] = L[j][k] * L[k][k];
      d -= L[j][k] * w[k];
    }
    if (!(d > S(0)) || !ScalarTraits<S>::is_finite(d)) return false;
    L[j][j] = d;
#pragma GCC unroll 16
    for (int i = j + 1; i < n; ++i) {
      S v = P(j, i);
#pragma GCC unroll 16
      for (int k = 0; k < j; ++k) v -= L[i][k] * w[k];
      L[i][j] = v / d;
    }
  }
  return true;
}

}  // namespace detail

/// true if the symmetric matrix P (its upper triangle is read) is positive
/// definite in its own scalar: every LDL^T pivot is > 0 and finite. A NaN
/// or Inf anywhere in the upper triangle fails: it reaches a later pivot
/// as NaN or -Inf, or is an infinite pivot itself. Loop bounds: the fixed
/// size.
template <class Derived>
bool is_positive_definite(const Eigen::MatrixBase<Derived>& P) {
  using S = typename Derived::Scalar;
  constexpr int n = Derived::RowsAtCompileTime;
  static_assert(n > 0 && n == Derived::ColsAtCompileTime, "a fixed-size square matrix");
  if constexpr (ScalarTraits<S>::kIsFixedPoint) {
    return detail::ldlt_pivots_positive_fixed<S, n>(P);
  } else {
    return detail::ldlt_pivots_positive_unrolled<S, n>(P);
  }
}

/// Whether a state and its covariance may be committed: kNonFinite for a
/// NaN/Inf (or a saturated fixed-point value) in x or P,
/// kNotPositiveDefinite for a P that fails is_positive_definite(), else kOk.
template <class DerivedX, class DerivedP>
Status state_status(const Eigen::MatrixBase<DerivedX>& x, const Eigen::MatrixBase<DerivedP>& P) {
  if (!all_finite(x)) return Status::kNonFinite;
  if (is_positive_definite(P)) return Status::kOk;
  return all_finite(P) ? Status::kNotPositiveDefinite : Status::kNonFinite;
}

}  // namespace kestrel
