// SPDX-License-Identifier: Apache-2.0
// The sigma-point Kalman filter, additive noise, over a choice of point set
// (paper 001 section 3.2): Ukf, the scaled unscented transform (table 2; van
// der Merwe 2004 algorithm 8), and Cdkf, Stirling's interpolation with the
// half-width h (table 3; van der Merwe 2004 section 3.4.1 and algorithm 9).
// The point set (filters/sigma_points.hpp) holds the weights and how the
// covariances are formed; this file holds the steps both share, on
// fixed-size storage with 2n + 1 points at compile time. Points are redrawn
// for the update so predict and update stand alone, as the gate needs; on a
// linear model this is exactly the Kalman filter. Commit on success like the
// EKF: kNonFinite, or kNotPositiveDefinite for a failed Cholesky of P, S or
// the updated P, leave x and P unchanged. Equations and choices:
// docs/filters.md, "UKF", "CDKF" and "Choices beyond the paper".
#pragma once

#include "kestrel/filters/sigma_point_parts.hpp"
#include "kestrel/filters/sigma_points.hpp"
#include "kestrel/math/eigen.hpp"
#include "kestrel/math/finite.hpp"
#include "kestrel/math/positive_definite.hpp"
#include "kestrel/models/concepts.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"

namespace kestrel {

/// PointSet<Scalar, n> is a point set of sigma_points.hpp (UnscentedPoints,
/// CentralDifferencePoints); the names, models, weights, x and diagnostics
/// are sigma::FilterParts (sigma_point_parts.hpp).
template <MotionModel Motion, MeasurementModelFor<Motion> Measurement, template <class, int> class PointSet>
class SigmaPointFilter : public sigma::FilterParts<Motion, Measurement, PointSet> {
  using Base = sigma::FilterParts<Motion, Measurement, PointSet>;
  using Base::motion_, Base::measurement_, Base::w_, Base::x_, Base::diag_, Base::fail;

 public:
  using typename Base::Scalar, typename Base::State, typename Base::Cov, typename Base::MeasVec,
      typename Base::MeasCov, typename Base::Innov, typename Base::Config;
  using Base::kStateDim, Base::kMeasDim, Base::kAffinePredict;

  SigmaPointFilter() : SigmaPointFilter(Motion{}, Measurement{}) {}
  SigmaPointFilter(const Motion& motion, const Measurement& measurement, const Config& params = Config{})
      : Base(motion, measurement, params), P_(Cov::Identity()) {}

  /// Set the state and covariance.
  /// @return kOk; kNonFinite (NaN/Inf); kNotPositiveDefinite (P has no
  ///         Cholesky factor, so no sigma points). Filter unchanged on error.
  [[nodiscard]] Status reset(const State& x, const Cov& P) {
    if (!all_finite(x) || !all_finite(P)) return Status::kNonFinite;
    const Cov Ps = symmetrised(P);
    if (Eigen::LLT<Cov>(Ps).info() != Eigen::Success) return Status::kNotPositiveDefinite;
    x_ = x;
    P_ = Ps;
    return Status::kOk;
  }

  /// Predict by dt seconds with the model's process noise Q(dt).
  /// @return kOk; kNonFinite; kNotPositiveDefinite (filter unchanged on error).
  [[nodiscard]] Status predict(Scalar dt) {
    if constexpr (kAffinePredict) {
      // The model's Q added per axis block (sigma_points.hpp): the n x n Q
      // is never formed. P_ is positive definite (reset() and update() check it).
      if (!ScalarTraits<Scalar>::is_finite(dt)) return Status::kNonFinite;
      return commit_prediction(motion_.propagate(x_, dt), sigma::affine_covariance(motion_, P_, dt));
    } else {
      return predict(dt, motion_.process_noise(dt));
    }
  }

  /// Predict by dt seconds with an explicit process noise Q.
  /// @return kOk; kNonFinite; kNotPositiveDefinite (filter unchanged on error).
  [[nodiscard]] Status predict(Scalar dt, const Cov& Q) {
    if (!ScalarTraits<Scalar>::is_finite(dt) || !all_finite(Q)) return Status::kNonFinite;
    State x;
    Cov P;
    if constexpr (kAffinePredict) {
      // Affine motion: either point set's transform is exactly f(x) and
      // F P F^T + Q (sigma_points.hpp), no points drawn. P_ is positive
      // definite here (reset() and update() check it; F is invertible).
      x = motion_.propagate(x_, dt);
      P = sigma::affine_covariance(motion_, P_, Q, dt);
    } else {
      const Eigen::LLT<Cov> llt(P_);
      if (llt.info() != Eigen::Success) return Status::kNotPositiveDefinite;
      const auto X = sigma::draw<Scalar, kStateDim>(x_, llt.matrixL(), w_.spread);
      const auto Y = sigma::propagate(motion_, X, dt);
      x = sigma::state_mean(Y, w_.wi);
      P = w_.covariance(Y, x, Q);
    }
    return commit_prediction(x, P);
  }

  /// Innovation of z against the current (predicted) state with the model's R.
  /// Pure: the gate uses it before deciding to update.
  Innov innovation(const MeasVec& z) const { return innovation(z, measurement_.noise()); }

  /// Innovation of z with an explicit measurement noise R.
  Innov innovation(const MeasVec& z, const MeasCov& R) const {
    Innov out{MeasVec::Zero(), MeasCov::Zero(), Scalar(0), Status::kOk};
    Moments m;
    out.status = moments(z, R, m);
    if (out.status != Status::kOk) return out;
    out.nu = m.nu;
    out.S = m.S;
    out.d2 = m.nu.dot(m.llt_S.solve(m.nu));
    return out;
  }

  /// Update with z and the model's R.
  /// @return kOk; kNonFinite or kNotPositiveDefinite (filter unchanged).
  [[nodiscard]] Status update(const MeasVec& z) { return update(z, measurement_.noise()); }

  /// Update with z and an explicit R.
  /// @return kOk; kNonFinite or kNotPositiveDefinite (filter unchanged).
  [[nodiscard]] Status update(const MeasVec& z, const MeasCov& R) {
    diag_.fused = false;
    Moments m;
    KESTREL_TRY_OR(fail, moments(z, R, m));
    const Mat<Scalar, kStateDim, kMeasDim> K = sigma::gain(m.llt_S, m.Pxz);
    const State x = x_ + K * m.nu;
    const Cov P = symmetrised(P_ - K * m.S * K.transpose());
    KESTREL_TRY_OR(fail, state_status(x, P));
    if (Eigen::LLT<Cov>(P).info() != Eigen::Success) return fail(Status::kNotPositiveDefinite);
    x_ = x;
    P_ = P;
    diag_.fused_all(m.nu, m.S.diagonal(), m.nu.dot(m.llt_S.solve(m.nu)));
    return Status::kOk;
  }

  const Cov& P() const { return P_; }

 private:
  /// Statistics of the predicted measurement shared by innovation() and update().
  struct Moments {
    MeasVec nu;
    MeasCov S;
    Mat<Scalar, kStateDim, kMeasDim> Pxz;
    Eigen::LLT<MeasCov> llt_S;
  };

  Status moments(const MeasVec& z, const MeasCov& R, Moments& m) const {
    if (!all_finite(z) || !all_finite(R)) return Status::kNonFinite;
    const Eigen::LLT<Cov> llt(P_);
    if (llt.info() != Eigen::Success) return Status::kNotPositiveDefinite;
    const Cov L = llt.matrixL();
    const auto X = sigma::draw<Scalar, kStateDim>(x_, L, w_.spread);
    const auto Z = sigma::measure_drawn(measurement_, X, L);
    const MeasVec z_mean = sigma::measurement_mean(measurement_, Z, w_.wi);
    w_.moments(measurement_, X, x_, L, Z, z_mean, R, m.S, m.Pxz);
    m.nu = measurement_.residual(z, z_mean);
    if (!all_finite(m.S) || !all_finite(m.Pxz) || !all_finite(m.nu)) return Status::kNonFinite;
    m.llt_S.compute(m.S);
    if (m.llt_S.info() != Eigen::Success) return Status::kNotPositiveDefinite;
    return Status::kOk;
  }

  /// Commit a predicted x- and P-, or return kNonFinite and keep the filter.
  Status commit_prediction(const State& x, const Cov& P) {
    KESTREL_TRY(state_status(x, P));
    x_ = x;
    P_ = P;
    return Status::kOk;
  }

  Cov P_;
};

/// Unscented Kalman filter (algorithm 8), the parameters of docs/filters.md by default:
/// UnscentedConfig<S, n>{alpha = 1, beta = 2, kappa = 3 - n}.
template <MotionModel Motion, MeasurementModelFor<Motion> Measurement>
using Ukf = SigmaPointFilter<Motion, Measurement, UnscentedPoints>;

/// Central difference Kalman filter (algorithm 9), the parameter of docs/filters.md by
/// default: CentralDifferenceConfig<S>{h = sqrt(3)}.
template <MotionModel Motion, MeasurementModelFor<Motion> Measurement>
using Cdkf = SigmaPointFilter<Motion, Measurement, CentralDifferencePoints>;

}  // namespace kestrel
