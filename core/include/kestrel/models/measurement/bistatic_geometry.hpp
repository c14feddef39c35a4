// SPDX-License-Identifier: Apache-2.0
// Bistatic geometry of a passive radar (docs/models.md, bistatic; paper 002
// section II): a stationary transmitter tx and receiver rx, a target at p
// moving with velocity v. The bistatic range is the extra path length
// Rb = |p - tx| + |p - rx| - |tx - rx| (0 on the baseline, the constant-Rb
// surfaces are ellipsoids with foci tx and rx), and its rate is the velocity
// projected on the sum of the two unit line-of-sight vectors,
// dRb = v . ((p - tx)/|p - tx| + (p - rx)/|p - rx|). The tracker never needs
// these (it filters Rb and dRb directly); scenarios and tests use them to
// turn a 3D truth into what the sensor measures.
#pragma once

#include "kestrel/math/eigen.hpp"
#include "kestrel/scalar/scalar_traits.hpp"

namespace kestrel {

/// Rb = |p - tx| + |p - rx| - |tx - rx|, m (all positions in one Cartesian frame, m).
template <class S>
S bistatic_range(const Vec<S, 3>& p, const Vec<S, 3>& tx, const Vec<S, 3>& rx) {
  using T = ScalarTraits<S>;
  return T::sqrt((p - tx).squaredNorm()) + T::sqrt((p - rx).squaredNorm()) - T::sqrt((tx - rx).squaredNorm());
}

/// dRb/dt for a target at p with velocity v (m/s) and a stationary tx and rx:
/// v . (u_tx + u_rx), u the unit vectors from each site to the target, m/s.
/// Positive when the bistatic range opens. Non-finite when p sits on tx or rx.
template <class S>
S bistatic_range_rate(const Vec<S, 3>& p, const Vec<S, 3>& v, const Vec<S, 3>& tx, const Vec<S, 3>& rx) {
  using T = ScalarTraits<S>;
  const Vec<S, 3> d_tx = p - tx;
  const Vec<S, 3> d_rx = p - rx;
  return v.dot(d_tx / T::sqrt(d_tx.squaredNorm()) + d_rx / T::sqrt(d_rx.squaredNorm()));
}

}  // namespace kestrel
