// SPDX-License-Identifier: Apache-2.0
// Innovation-based adaptation of a track's measurement noise: the filter
// fuses the track's plots with lambda R instead of R, and lambda follows
// the track's normalised innovation squared (NIS), in the
// covariance-matching class of adaptive Kalman filters (R. K. Mehra,
// "Approaches to adaptive filtering", IEEE Trans. Automatic Control 17(5),
// 1972): with S = H P H^T + lambda R, a consistent track has E[d2] = m
// (m channels), so lambda is moved by the NIS excess of each plot it takes,
//   lambda' = clamp(lambda (1 + alpha (min(d2, cap) / m - 1)), 1, lambda_max).
// A sensor noisier than its model (a burst) drives lambda up within a few
// plots and the track weighs its prediction accordingly, its covariance
// growing with it instead of being pulled plot by plot; when the noise is
// back to nominal the NIS falls to m / lambda and lambda decays to 1 at the
// rate (1 - alpha) per plot. The cap (the chi-square gate) keeps a single
// far plot from moving lambda by more than alpha (cap / m - 1) of itself,
// and lambda never leaves [1, lambda_max]; every lambda R is positive
// definite, so the filter's own update keeps P positive definite. No state
// but lambda, no allocation, two multiplications a plot. A tracker built
// with AdaptiveMeasurementNoise (tracking/measurement_noise.hpp, a
// compile-time choice; boards leave it out) applies it to confirmed tracks
// under the robust gate, and only on a plot that follows a hit of the
// previous frame.
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
