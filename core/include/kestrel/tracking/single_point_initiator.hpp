// SPDX-License-Identifier: Apache-2.0
// Single-point initiation (docs/tracking.md and docs/scenarios.md, PCL-002): when one
// measurement determines the whole state (the passive radar measures Rb and,
// through the Doppler, dRb), a tentative track starts initialised from one
// unused candidate: x0 = z, P0 = R, through the measurement model's
// to_state(). No two-point differencing is needed.
//
// The initiator is also where a start is vetoed: a candidate with
// |z(c)| < min_abs(c) on any channel c is refused with kOutOfRange, and
// Tracker counts it in StepStats::refused instead of starting a track. For
// PCL-002 this is "no track started from a candidate with |fD| < 2 Hz"
// (min_abs = [0, 2 Hz * lambda] on [Rb, dRb]), which keeps the zero-Doppler
// clutter ridge (direct signal and stationary clutter leaking through the
// cancellation) from seeding tracks while a confirmed track may still pass
// through zero Doppler.
#pragma once

#include "kestrel/math/eigen.hpp"
#include "kestrel/math/finite.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"

namespace kestrel {

template <class Motion, class Measurement>
  requires requires(const Measurement& m, const typename Measurement::Measurement& z, typename Motion::State& x,
                    typename Motion::Cov& P) { m.to_state(z, x, P); }
struct SinglePointInitiator {
  using Scalar = typename Motion::Scalar;
  using State = typename Motion::State;
  using Cov = typename Motion::Cov;
  using MeasVec = typename Measurement::Measurement;
  static constexpr int kMeasDim = Measurement::kMeasDim;
  /// Tracker: a track starts initialised from one measurement (no seeds).
  static constexpr bool kSinglePoint = true;

  Measurement measurement;  ///< Sensor model (its to_state and R).
  MeasVec min_abs = MeasVec::Zero();  ///< Refuse a start when |z(c)| < min_abs(c); 0 disables channel c.

  /// true if z may start a track (no channel below its min_abs).
  bool accepts(const MeasVec& z) const {
    for (int c = 0; c < kMeasDim; ++c) {
      if (ScalarTraits<Scalar>::abs(z(c)) < min_abs(c)) return false;
    }
    return true;
  }

  /// State and covariance of a new track from the single measurement z.
  /// @return kOk; kOutOfRange (vetoed by min_abs: the tracker starts nothing);
  ///         kNonFinite (x and P unchanged).
  [[nodiscard]] Status initiate(const MeasVec& z, State& x, Cov& P) const {
    if (!all_finite(z)) return Status::kNonFinite;
    if (!accepts(z)) return Status::kOutOfRange;
    State xs;
    Cov Ps;
    measurement.to_state(z, xs, Ps);
    if (!all_finite(xs) || !all_finite(Ps)) return Status::kNonFinite;
    x = xs;
    P = Ps;
    return Status::kOk;
  }
};

}  // namespace kestrel
