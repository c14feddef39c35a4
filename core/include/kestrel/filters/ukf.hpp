// Unscented Kalman filter, scaled unscented transform, additive noise (SPEC
// section 5; paper 001 section 3.2 and table 2, which is van der Merwe 2004,
// algorithm 8 / Wan and van der Merwe 2000). Generic over any motion and
// measurement model pair the EKF takes; fixed-size storage, 2n + 1 sigma
// points at compile time.
//
// predict(dt, Q):  X = [x, x +- c L] with P = L L^T (c = sqrt(n + lambda)),
//   Y_i = f(X_i, dt), x- = sum Wm_i Y_i,
//   P- = sum Wc_i (Y_i - x-)(Y_i - x-)^T + Q.
// update(z, R):    sigma points are redrawn from (x-, P-) (the additive-noise
//   form; van der Merwe's alternative of augmenting the propagated set is
//   not used so that predict and update stand alone, as the gate needs),
//   Z_i = h(X_i), z- = sum Wm_i Z_i, S = sum Wc_i dZ_i dZ_i^T + R,
//   Pxz = sum Wc_i (X_i - x-) dZ_i^T, K = Pxz S^-1,
//   x+ = x- + K residual(z, z-), P+ = P- - K S K^T (symmetrised).
// On a linear model this is exactly the Kalman filter (tested).
// With an affine (block-diagonal) motion model the time update is taken in
// its closed form x- = f(x), P- = F P F^T + Q per axis block, exactly the
// unscented transform of such a model (filters/sigma_points.hpp).
// Bearings: means and deviations go through the model's residual(), see
// filters/sigma_points.hpp.
//
// Commit-on-success like the EKF: a non-finite input or result returns
// kNonFinite; a failed Cholesky of P (before drawing points), of S, or of the
// updated P returns kNotPositiveDefinite; x and P are then unchanged.
#pragma once

#include "kestrel/filters/innovation.hpp"
#include "kestrel/filters/sigma_points.hpp"
#include "kestrel/math/eigen.hpp"
#include "kestrel/math/finite.hpp"
#include "kestrel/math/positive_definite.hpp"
#include "kestrel/models/concepts.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"

namespace kestrel {

template <MotionModel Motion, MeasurementModelFor<Motion> Measurement>
class Ukf {
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
  using Params = UnscentedParams<Scalar, kStateDim>;
  using Weights = UnscentedWeights<Scalar, kStateDim>;
  /// Closed-form time update of an affine (block-diagonal) motion model
  /// (sigma_points.hpp); false for Dense<M> and nonlinear models.
  static constexpr bool kAffinePredict = sigma::kAffineTimeUpdate<Motion>;

  Ukf() : Ukf(Motion{}, Measurement{}) {}
  Ukf(const Motion& motion, const Measurement& measurement, const Params& params = Params{})
      : motion_(motion),
        measurement_(measurement),
        params_(params),
        w_(Weights::from(params)),
        x_(State::Zero()),
        P_(Cov::Identity()) {
    diag_ = Diagnostics{MeasVec::Zero(), MeasVec::Zero(), Scalar(0), false, Status::kNotInitialised};
  }

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
      // Affine motion: the unscented transform is exactly f(x) and
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
      P = symmetrised(weighted_outer(Y, x) + Q);
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
    const Status st = moments(z, R, m);
    if (st != Status::kOk) return fail(st);
    const Mat<Scalar, kStateDim, kMeasDim> K = sigma::gain(m.llt_S, m.Pxz);
    const State x = x_ + K * m.nu;
    const Cov P = symmetrised(P_ - K * m.S * K.transpose());
    if (const Status c = state_status(x, P); c != Status::kOk) return fail(c);
    if (Eigen::LLT<Cov>(P).info() != Eigen::Success) return fail(Status::kNotPositiveDefinite);
    x_ = x;
    P_ = P;
    diag_.innovation = m.nu;
    diag_.innovation_variance = m.S.diagonal();
    diag_.nis = m.nu.dot(m.llt_S.solve(m.nu));
    diag_.fused = true;
    diag_.status = Status::kOk;
    return Status::kOk;
  }

  const State& x() const { return x_; }
  const Cov& P() const { return P_; }
  const Motion& motion() const { return motion_; }
  const Measurement& measurement() const { return measurement_; }
  Motion& motion() { return motion_; }
  Measurement& measurement() { return measurement_; }
  const Params& params() const { return params_; }
  const Weights& weights() const { return w_; }
  /// Diagnostics of the last update attempt.
  const Diagnostics& diagnostics() const { return diag_; }

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
    const auto dZ = sigma::measurement_deviations(measurement_, Z, z_mean);
    // Deviations of the redrawn points from their own mean x_: X_0 - x = 0
    // exactly, so only X_1..X_2n contribute to Pxz.
    MeasCov S = dZ.col(0) * dZ.col(0).transpose() * w_.wc0;
    Mat<Scalar, kStateDim, kMeasDim> Pxz = Mat<Scalar, kStateDim, kMeasDim>::Zero();
    for (int i = 1; i < kSigmaCount; ++i) {
      S += dZ.col(i) * dZ.col(i).transpose() * w_.wi;
      Pxz += (X.col(i) - x_) * dZ.col(i).transpose() * w_.wi;
    }
    m.S = symmetrised(S + R);
    m.Pxz = Pxz;
    m.nu = measurement_.residual(z, z_mean);
    if (!all_finite(m.S) || !all_finite(m.Pxz) || !all_finite(m.nu)) return Status::kNonFinite;
    m.llt_S.compute(m.S);
    if (m.llt_S.info() != Eigen::Success) return Status::kNotPositiveDefinite;
    return Status::kOk;
  }

  /// sum Wc_i (Y_i - m)(Y_i - m)^T.
  Cov weighted_outer(const sigma::Points<Scalar, kStateDim>& Y, const State& m) const {
    const State d0 = Y.col(0) - m;
    Cov P = d0 * d0.transpose() * w_.wc0;
    for (int i = 1; i < kSigmaCount; ++i) {
      const State d = Y.col(i) - m;
      P += d * d.transpose() * w_.wi;
    }
    return P;
  }

  /// Commit a predicted x- and P-, or return kNonFinite and keep the filter.
  Status commit_prediction(const State& x, const Cov& P) {
    if (const Status c = state_status(x, P); c != Status::kOk) return c;
    x_ = x;
    P_ = P;
    return Status::kOk;
  }

  Status fail(Status s) {
    diag_.status = s;
    return s;
  }

  Motion motion_;
  Measurement measurement_;
  Params params_;
  Weights w_;
  State x_;
  Cov P_;
  Diagnostics diag_;
};

}  // namespace kestrel
