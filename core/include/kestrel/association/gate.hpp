// SPDX-License-Identifier: Apache-2.0
// Ellipsoidal gate (docs/tracking.md): accept a measurement when its normalised
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
    // Converted at compile time: a fixed-point image does no double work here.
    using T = ScalarTraits<Scalar>;
    constexpr Scalar kThreshold[] = {
        T::from_double(chi_square_quantile<kMeasDim>(GateProbability::k90)),
        T::from_double(chi_square_quantile<kMeasDim>(GateProbability::k95)),
        T::from_double(chi_square_quantile<kMeasDim>(GateProbability::k99)),
        T::from_double(chi_square_quantile<kMeasDim>(GateProbability::k995)),
        T::from_double(chi_square_quantile<kMeasDim>(GateProbability::k999))};
    return EllipsoidalGate{kThreshold[static_cast<int>(p)]};
  }

  /// true if the innovation is valid and inside the gate.
  bool accepts(const Innovation<Scalar, kMeasDim>& in) const {
    return in.status == Status::kOk && in.d2 <= threshold;
  }
  bool accepts(const PlotDistance<Scalar>& d) const { return d.status == Status::kOk && d.d2 <= threshold; }
};

}  // namespace kestrel
