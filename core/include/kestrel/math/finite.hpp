// SPDX-License-Identifier: Apache-2.0
// Finiteness check and symmetrisation for fixed-size Eigen objects, through
// ScalarTraits so they work for every scalar (fixed point is always finite
// but may saturate; its traits decide).
#pragma once

#include <type_traits>

#include "kestrel/math/eigen.hpp"
#include "kestrel/scalar/scalar_traits.hpp"

#if defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__
#error "Kestrel's finiteness checks need IEEE Inf/NaN: build without -ffast-math / -ffinite-math-only"
#endif

namespace kestrel {

/// true if every coefficient is finite. Loop bound: the fixed size.
template <class Derived>
bool all_finite(const Eigen::MatrixBase<Derived>& m) {
  using S = typename Derived::Scalar;
  if constexpr (std::is_floating_point_v<S>) {
    // IEEE: v * 0 is +-0 for finite v and NaN for Inf or NaN, and a sum with
    // a NaN term is NaN, so one vectorisable reduction answers for every
    // coefficient (no overflow: the terms are zeros). Valid without
    // -ffinite-math-only, which no Kestrel build uses.
    return ScalarTraits<S>::is_finite((m.derived().array() * S(0)).sum());
  } else {
    for (Eigen::Index c = 0; c < m.cols(); ++c) {
      for (Eigen::Index r = 0; r < m.rows(); ++r) {
        if (!ScalarTraits<S>::is_finite(m(r, c))) return false;
      }
    }
    return true;
  }
}

/// (A + A^T) / 2: removes the round-off asymmetry of a covariance product.
/// A is evaluated once (an expression such as F P F^T + Q would otherwise be
/// computed twice, once for each side of the sum).
template <class Derived>
typename Derived::PlainObject symmetrised(const Eigen::MatrixBase<Derived>& A) {
  using S = typename Derived::Scalar;
  const typename Derived::PlainObject a = A;
  return (a + a.transpose()) * S(0.5);
}

}  // namespace kestrel
