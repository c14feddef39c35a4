// SPDX-License-Identifier: Apache-2.0
// Robust gating of confirmed tracks: a Huber-type update with hard rejection
// (Huber's psi on the Mahalanobis norm of the innovation, cut off beyond an
// outer gate, as in Hampel's redescending M-estimators). A plot inside the
// chi-square gate g updates as usual; one between g and the outer gate
// g x factor is taken with its innovation shrunk to the gate's boundary,
// nu' = nu sqrt(g / d2), so nu'^T S^-1 nu' = g; one beyond is a miss. In a
// noise burst tracks keep taking their plots, each moving the state no
// further than a plot on the gate's edge would, while a gross outlier cannot
// drag the track. Under this gate a tracker built with
// AdaptiveMeasurementNoise may also adapt R per track
// (association/adaptive_noise.hpp). Why: docs/robustness.md, "The robust
// gate".
#pragma once

#include "kestrel/filters/innovation.hpp"
#include "kestrel/math/eigen.hpp"
#include "kestrel/scalar/scalar_traits.hpp"

namespace kestrel {

template <class Scalar, int kMeasDim>
struct RobustGate {
  /// g, the d2 up to which an update is plain; 0: robust gating off.
  Scalar inner{};

  /// true if the plot of innovation `in` is taken with a shrunk innovation.
  bool clips(const Innovation<Scalar, kMeasDim>& in) const {
    return inner > Scalar(0) && in.status == Status::kOk && in.d2 > inner;
  }

  /// The measurement whose innovation against the same prediction is
  /// nu sqrt(g / d2): z - (1 - sqrt(g / d2)) nu. Residuals are linear in
  /// z (an angle residual wraps the same), so the filter's own update
  /// then applies the shrunk innovation with its usual gain.
  /// @pre clips(in).
  Vec<Scalar, kMeasDim> shrink(const Vec<Scalar, kMeasDim>& z, const Innovation<Scalar, kMeasDim>& in) const {
    const Scalar keep = ScalarTraits<Scalar>::sqrt(inner / in.d2);
    return z - (Scalar(1) - keep) * in.nu;
  }
};

}  // namespace kestrel
