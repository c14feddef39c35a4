// Finiteness check and symmetrisation for fixed-size Eigen objects, through
// ScalarTraits so they work for every scalar (fixed point is always finite
// but may saturate; its traits decide).
#pragma once

#include "kestrel/math/eigen.hpp"
#include "kestrel/scalar/scalar_traits.hpp"

namespace kestrel {

/// true if every coefficient is finite. Loop bound: the fixed size.
template <class Derived>
bool all_finite(const Eigen::MatrixBase<Derived>& m) {
  using S = typename Derived::Scalar;
  for (Eigen::Index c = 0; c < m.cols(); ++c) {
    for (Eigen::Index r = 0; r < m.rows(); ++r) {
      if (!ScalarTraits<S>::is_finite(m(r, c))) return false;
    }
  }
  return true;
}

/// (A + A^T) / 2: removes the round-off asymmetry of a covariance product.
template <class Derived>
typename Derived::PlainObject symmetrised(const Eigen::MatrixBase<Derived>& A) {
  using S = typename Derived::Scalar;
  return (A + A.transpose()) * S(0.5);
}

}  // namespace kestrel
