// Ellipsoidal gate (SPEC section 6): accept a measurement when its normalised
// squared distance nu^T S^-1 nu is below the chi-square quantile of the
// measurement dimension at the chosen probability.
#pragma once

#include "kestrel/association/chi_square.hpp"
#include "kestrel/filters/innovation.hpp"
#include "kestrel/scalar/scalar_traits.hpp"

namespace kestrel {

template <class Scalar, int kMeasDim>
struct EllipsoidalGate {
  Scalar threshold;  ///< Chi-square quantile, unitless (same units as d2).

  static EllipsoidalGate with_probability(GateProbability p) {
    return EllipsoidalGate{ScalarTraits<Scalar>::from_double(chi_square_quantile<kMeasDim>(p))};
  }

  /// true if the innovation is valid and inside the gate.
  bool accepts(const Innovation<Scalar, kMeasDim>& in) const {
    return in.status == Status::kOk && in.d2 <= threshold;
  }
};

}  // namespace kestrel
