// SPDX-License-Identifier: Apache-2.0
// Innovation-based adaptation of a track's measurement noise, in the
// covariance-matching class of adaptive Kalman filters (R. K. Mehra,
// "Approaches to adaptive filtering", IEEE Trans. Automatic Control 17(5),
// 1972): the filter fuses the track's plots with lambda R, and lambda follows
// the NIS excess of each plot, since a consistent track has E[d2] = m,
//   lambda' = clamp(lambda (1 + alpha (min(d2, cap) / m - 1)), 1, lambda_max).
// The cap (the chi-square gate) bounds one plot's push, and every lambda R is
// positive definite, so the filter's own update keeps P positive definite.
// No state but lambda, no allocation. Applied by AdaptiveMeasurementNoise
// (tracking/measurement_noise.hpp) to confirmed tracks under the robust gate,
// on a plot that follows a hit of the previous frame; why and how it
// behaves: docs/robustness.md, "Adaptive measurement noise".
#pragma once

#include "kestrel/scalar/scalar_traits.hpp"

namespace kestrel {

template <class Scalar>
struct AdaptiveNoise {
  /// alpha in (0, 1]: the weight of each plot's NIS excess; 0: off.
  Scalar gain{};
  /// lambda_max > 1: the largest scale of R; at most 1: off.
  Scalar max_scale{};
  /// The d2 a plot's NIS is capped at before it enters (the chi-square gate's).
  Scalar nis_cap{};

  /// true when the adaptation acts.
  bool enabled() const { return gain > Scalar(0) && gain <= Scalar(1) && max_scale > Scalar(1) && nis_cap > Scalar(0); }

  /// The scale after a plot of NIS `d2` (against S with the current scale)
  /// over `channels` channels. Non-finite or negative d2, or a scale
  /// outside [1, max_scale], give a result within [1, max_scale].
  /// @pre enabled(), channels >= 1.
  Scalar next(Scalar scale, Scalar d2, int channels) const {
    Scalar q = d2;
    if (!(q >= Scalar(0))) q = Scalar(0);  // a NaN counts as a plot on the prediction
    if (q > nis_cap) q = nis_cap;
    const Scalar excess = q / Scalar(channels) - Scalar(1);
    Scalar s = clamped(scale);
    s = s + s * (gain * excess);
    return clamped(s);
  }

  /// scale within [1, max_scale] (a NaN: 1).
  Scalar clamped(Scalar scale) const {
    if (!(scale > Scalar(1))) return Scalar(1);
    if (scale > max_scale) return max_scale;
    return scale;
  }
};

}  // namespace kestrel
