// Positive-definiteness of a symmetric covariance, as the contract every
// filter holds on the P it commits: a P that fails here is refused with
// kNotPositiveDefinite and the filter keeps its previous state.
//
// The test is an LDL^T factorisation of the upper triangle without square
// roots (so it runs in fixed point too): every pivot D_j must be positive
// and finite. n(n-1)/2 divisions and about n^3/3 multiply-adds (15 and
// about 70 for a 6x6 P).
#pragma once

#include "kestrel/math/eigen.hpp"
#include "kestrel/math/finite.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"

namespace kestrel {

/// true if the symmetric matrix P (its upper triangle is read) is positive
/// definite in its own scalar: every LDL^T pivot is > 0 and finite. A NaN
/// anywhere in the upper triangle fails. Loop bounds: the fixed size.
template <class Derived>
bool is_positive_definite(const Eigen::MatrixBase<Derived>& P) {
  using S = typename Derived::Scalar;
  constexpr int n = Derived::RowsAtCompileTime;
  static_assert(n > 0 && n == Derived::ColsAtCompileTime, "a fixed-size square matrix");
  // LDL^T column by column: L below the diagonal, packed (n(n-1)/2
  // entries), and the pivots D; the stack holds n(n+1)/2 scalars. L is
  // formed by a division, not by a reciprocal of the pivot: in fixed point
  // 1/D of a large pivot (a position variance of 1e9 m^2) keeps only a few
  // significant bits. Each product (L(i, k) D_k) L(j, k) is bounded by
  // sqrt(P_ii P_jj) for a positive definite P, so fixed point cannot
  // overflow on a matrix that passes.
  constexpr int kPacked = n * (n - 1) / 2 > 0 ? n * (n - 1) / 2 : 1;
  S L[kPacked] = {};
  S D[n] = {};
  const auto at = [](int i, int j) { return i * (i - 1) / 2 + j; };  // i > j
  for (int j = 0; j < n; ++j) {
    S d = P(j, j);
    for (int k = 0; k < j; ++k) d -= (L[at(j, k)] * D[k]) * L[at(j, k)];
    if (!(d > S(0)) || !ScalarTraits<S>::is_finite(d)) return false;
    D[j] = d;
    for (int i = j + 1; i < n; ++i) {
      S v = P(j, i);  // upper triangle: P(i, j) == P(j, i)
      for (int k = 0; k < j; ++k) v -= (L[at(i, k)] * D[k]) * L[at(j, k)];
      const S l = v / d;
      if (!ScalarTraits<S>::is_finite(l)) return false;
      L[at(i, j)] = l;
    }
  }
  return true;
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
