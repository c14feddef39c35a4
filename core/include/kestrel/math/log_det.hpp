// SPDX-License-Identifier: Apache-2.0
// ln|S| of a small symmetric positive definite matrix, from the pivots of
// its LDL^T factorisation (fixed loops, no square root): the track score
// and the probabilistic association need the Gaussian's normalisation.
#pragma once

#include "kestrel/math/eigen.hpp"
#include "kestrel/scalar/scalar_traits.hpp"

namespace kestrel {

/// @return false (out unchanged) if a pivot is not positive and finite.
template <class S, int m>
bool log_det_spd(const Mat<S, m, m>& Sm, S& out) {
  using T = ScalarTraits<S>;
  Mat<S, m, m> A = Sm;  // L below the diagonal, D on it
  S sum(0);
  for (int j = 0; j < m; ++j) {
    S d = A(j, j);
    for (int k = 0; k < j; ++k) d -= A(j, k) * A(j, k) * A(k, k);
    if (!(d > S(0)) || !T::is_finite(d)) return false;
    A(j, j) = d;
    sum += T::log(d);
    for (int i = j + 1; i < m; ++i) {
      S v = A(i, j);
      for (int k = 0; k < j; ++k) v -= A(i, k) * A(j, k) * A(k, k);
      A(i, j) = v / d;
    }
  }
  out = sum;
  return true;
}

}  // namespace kestrel
