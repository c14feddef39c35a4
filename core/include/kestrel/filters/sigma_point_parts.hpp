// SPDX-License-Identifier: Apache-2.0
// What the plain and the square-root sigma-point filters
// (filters/sigma_point_filter.hpp, filters/sr_sigma_point_filter.hpp) hold
// alike: their type vocabulary, the two models, the point set's parameters
// and weights (filters/sigma_points.hpp), the state x and the diagnostics of
// the last update, with their accessors. Each filter adds its covariance form
// (P; or Sx with P = Sx Sx^T) and the steps of its algorithm (van der Merwe
// 2004 algorithms 8-11).
#pragma once

#include "kestrel/filters/innovation.hpp"
#include "kestrel/filters/sigma_points.hpp"
#include "kestrel/math/eigen.hpp"
#include "kestrel/models/concepts.hpp"
#include "kestrel/status.hpp"

namespace kestrel::sigma {

/// PointSet<Scalar, n> is a point set of sigma_points.hpp (UnscentedPoints,
/// CentralDifferencePoints).
template <MotionModel Motion, MeasurementModelFor<Motion> Measurement, template <class, int> class PointSet>
class FilterParts {
 public:
  using Scalar = typename Motion::Scalar;
  static constexpr int kStateDim = Motion::kStateDim;
  static constexpr int kMeasDim = Measurement::kMeasDim;
  static constexpr int kSigmaCount = kSigmaPointCount<kStateDim>;
  using MotionModel = Motion;
  using MeasurementModel = Measurement;
  using Layout = typename Motion::Layout;
  using State = typename Motion::State;
  using Cov = typename Motion::Cov;
  using MeasVec = typename Measurement::Measurement;
  using MeasCov = typename Measurement::NoiseCov;
  using Innov = Innovation<Scalar, kMeasDim>;
  using Diagnostics = FusionDiagnostics<Scalar, kMeasDim>;
  /// The point set with its weights.
  using Weights = PointSet<Scalar, kStateDim>;
  using Config = typename Weights::Config;
  /// Closed-form time update of an affine (block-diagonal) motion model
  /// (sigma_points.hpp); false for Dense<M> and nonlinear models.
  static constexpr bool kAffinePredict = kAffineTimeUpdate<Motion>;

  const State& x() const { return x_; }
  const Motion& motion() const { return motion_; }
  const Measurement& measurement() const { return measurement_; }
  Motion& motion() { return motion_; }
  Measurement& measurement() { return measurement_; }
  const Config& params() const { return params_; }
  const Weights& weights() const { return w_; }
  /// Diagnostics of the last update attempt.
  const Diagnostics& diagnostics() const { return diag_; }

 protected:
  FilterParts(const Motion& motion, const Measurement& measurement, const Config& params)
      : motion_(motion), measurement_(measurement), params_(params), w_(Weights::from(params)), x_(State::Zero()) {
    diag_ = Diagnostics{};
  }

  /// Record a refused update in the diagnostics and return its status.
  Status fail(Status s) {
    diag_.status = s;
    return s;
  }

  Motion motion_;
  Measurement measurement_;
  Config params_;
  Weights w_;
  State x_;
  Diagnostics diag_;
};

}  // namespace kestrel::sigma
