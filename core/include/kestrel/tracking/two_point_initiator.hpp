// SPDX-License-Identifier: Apache-2.0
// Two-point differencing initiation (docs/tracking.md): a sensor that measures
// position only (polar radar) needs two detections to infer velocity. From
// plots z1 (time t1) and z2 (t2): position p2, velocity (p2 - p1)/dt,
// acceleration 0; covariance from the first-order polar-to-Cartesian
// conversion J R J^T of each plot: Var(p) = P2, Var(v) = (P1 + P2)/dt^2,
// Cov(p, v) = P2/dt; acceleration variance from the config (CA models).
#pragma once

#include "kestrel/math/eigen.hpp"
#include "kestrel/math/finite.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"

namespace kestrel {

template <class Motion, class Measurement>
struct TwoPointInitiator {
  using Scalar = typename Motion::Scalar;
  using State = typename Motion::State;
  using Cov = typename Motion::Cov;
  using MeasVec = typename Measurement::Measurement;
  using L = typename Motion::Layout;
  static constexpr bool kSinglePoint = false;

  Measurement measurement;   ///< Sensor model (for to_position and its R).
  Scalar max_speed_mps;      ///< A pair implying a faster target is not a track.
  Scalar accel_sigma_mps2;   ///< Initial acceleration standard deviation (CA models).

  /// Pairing cost of a seed z1 with a later plot z2 dt seconds after it: the
  /// implied speed in m/s (lower is better).
  /// @return the speed; kOutOfRange if dt <= 0 or the speed exceeds
  ///         max_speed_mps; kNonFinite.
  Result<Scalar> pair_cost(const MeasVec& z1, const MeasVec& z2, Scalar dt) const {
    if (!(dt > Scalar(0))) return Status::kOutOfRange;
    Vec<Scalar, 2> p1, p2;
    Mat<Scalar, 2, 2> P1, P2;
    measurement.to_position(z1, p1, P1);
    measurement.to_position(z2, p2, P2);
    const Vec<Scalar, 2> d = p2 - p1;
    const Scalar speed = ScalarTraits<Scalar>::hypot(d(0), d(1)) / dt;
    if (!ScalarTraits<Scalar>::is_finite(speed)) return Status::kNonFinite;
    if (speed > max_speed_mps) return Status::kOutOfRange;
    return speed;
  }

  /// State and covariance from the pair (z1 at t - dt, z2 at t).
  /// @return kOk; kOutOfRange if dt <= 0; kNonFinite.
  [[nodiscard]] Status initiate(const MeasVec& z1, const MeasVec& z2, Scalar dt, State& x,
                                Cov& P) const {
    if (!(dt > Scalar(0))) return Status::kOutOfRange;
    Vec<Scalar, 2> p1, p2;
    Mat<Scalar, 2, 2> P1, P2;
    measurement.to_position(z1, p1, P1);
    measurement.to_position(z2, p2, P2);
    const Vec<Scalar, 2> v = (p2 - p1) / dt;
    const Mat<Scalar, 2, 2> Pvv = (P1 + P2) / (dt * dt);
    const Mat<Scalar, 2, 2> Ppv = P2 / dt;

    constexpr int kPos[2] = {L::kX, L::kY};
    constexpr int kVel[2] = {L::kVx, L::kVy};
    State xs = State::Zero();
    Cov Ps = Cov::Zero();
    for (int i = 0; i < 2; ++i) {
      xs(kPos[i]) = p2(i);
      xs(kVel[i]) = v(i);
      for (int j = 0; j < 2; ++j) {
        Ps(kPos[i], kPos[j]) = P2(i, j);
        Ps(kVel[i], kVel[j]) = Pvv(i, j);
        Ps(kPos[i], kVel[j]) = Ppv(i, j);
        Ps(kVel[j], kPos[i]) = Ppv(i, j);
      }
    }
    if constexpr (requires { L::kAx; L::kAy; }) {
      Ps(L::kAx, L::kAx) = accel_sigma_mps2 * accel_sigma_mps2;
      Ps(L::kAy, L::kAy) = accel_sigma_mps2 * accel_sigma_mps2;
    }
    if (!all_finite(xs) || !all_finite(Ps)) return Status::kNonFinite;
    x = xs;
    P = Ps;
    return Status::kOk;
  }
};

/// A TwoPointInitiator whose tracker keeps more than one hypothesis of a
/// start, for a pair that holds an outlier: a seed keeps pairing, once per
/// frame, for seed_extra_frames frames after the next one, even after it
/// has paired, while each frame offers it a plot no track took; and, with
/// seed_from_pairs, the plot that completes a pair starts a seed of its
/// own. Each pair is a track of its own. A separate type because the
/// tracker compiles these rules only for it: an image built with
/// TwoPointInitiator carries none of their code.
template <class Motion, class Measurement>
struct TwoPointHypothesesInitiator : TwoPointInitiator<Motion, Measurement> {
  static constexpr bool kKeepsHypotheses = true;
  std::uint8_t seed_extra_frames = 0;  ///< 0: a seed pairs in the next frame only.
  bool seed_from_pairs = false;        ///< The plot that completes a pair starts a seed too.
};

}  // namespace kestrel
