// SPDX-License-Identifier: Apache-2.0
// Compile-time contracts between models and filters (docs/models.md).
// A filter names its models as template parameters constrained by these
// concepts; a model that lacks residual() or mixes scalars fails to compile
// at the filter's declaration, not deep inside Eigen (tests/compile_fail/).
#pragma once

#include <concepts>

#include "kestrel/math/eigen.hpp"

namespace kestrel {

/// A motion model: fixed state size, noise-free propagation, its Jacobian and
/// the process noise for a time step dt (seconds, in the model's scalar).
template <class M>
concept MotionModel = requires(const M& m, const typename M::State& x, typename M::Scalar dt) {
  typename M::Scalar;
  typename M::State;
  typename M::Cov;
  requires M::kStateDim > 0;
  { m.propagate(x, dt) } -> std::same_as<typename M::State>;
  { m.jacobian(x, dt) } -> std::same_as<typename M::Cov>;
  { m.process_noise(dt) } -> std::same_as<typename M::Cov>;
};

/// A measurement model for motion model Motion: predicted measurement, its
/// Jacobian, the noise covariance and the residual (which owns angle wraps).
template <class H, class Motion>
concept MeasurementModelFor =
    MotionModel<Motion> &&
    std::same_as<typename H::Scalar, typename Motion::Scalar> &&
    (H::kStateDim == Motion::kStateDim) && (H::kMeasDim > 0) &&
    requires(const H& h, const typename Motion::State& x, const typename H::Measurement& z) {
      { h.predict(x) } -> std::same_as<typename H::Measurement>;
      { h.jacobian(x) } -> std::same_as<typename H::Jacobian>;
      { h.noise() } -> std::same_as<typename H::NoiseCov>;
      { h.residual(z, z) } -> std::same_as<typename H::Measurement>;
    };

}  // namespace kestrel
