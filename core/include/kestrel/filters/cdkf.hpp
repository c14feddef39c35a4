// Central difference Kalman filter: Stirling's interpolation formula in
// place of the Taylor series (SPEC section 5; paper 001 section 3.2 and
// table 3, which is van der Merwe 2004 section 3.4.1 and algorithm 9, after
// Norgaard, Poulsen and Ravn 2000 and Ito and Xiong 2000). One parameter, the
// interval half-width h; h^2 = 3 (SPEC 5, h = sqrt(3)) is optimal for a
// Gaussian prior. Generic over any motion and measurement model pair the EKF
// takes; fixed-size storage, 2n + 1 points at compile time.
//
// With X = [x, x + h L, x - h L] (P = L L^T), Y_i = f(X_i, dt):
//   x- = Wm_0 Y_0 + Wm_i sum Y_i, Wm_0 = (h^2 - n)/h^2, Wm_i = 1/(2h^2),
//   P- = sum_(i=1..n) [Wc1 (Y_i - Y_(n+i))^2 + Wc2 (Y_i + Y_(n+i) - 2 Y_0)^2] + Q,
//        Wc1 = 1/(4h^2), Wc2 = (h^2 - 1)/(4h^4)   (v^2 means v v^T).
// Update, points redrawn from (x-, P-), Z_i = h(X_i):
//   z- as above, S = the same two sums over Z + R,
//   Pxz = sqrt(Wc1) L [Z_(1..n) - Z_(n+1..2n)]^T, K = Pxz S^-1,
//   x+ = x- + K residual(z, z-), P+ = P- - K S K^T (symmetrised).
// Every measurement difference goes through residual() (bearing wrap, see
// filters/sigma_points.hpp). On a linear model this is exactly the KF.
// With an affine (block-diagonal) motion model the time update is taken in
// its closed form x- = f(x), P- = F P F^T + Q per axis block, exactly the
// central-difference transform of such a model (sigma_points.hpp).
//
// Commit-on-success like the EKF: kNonFinite; kNotPositiveDefinite for a
// failed Cholesky of P, S or the updated P; x and P unchanged on error.
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
class Cdkf {
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
  using Params = CentralDifferenceParams<Scalar>;
  using Weights = CentralDifferenceWeights<Scalar, kStateDim>;
  /// Closed-form time update of an affine (block-diagonal) motion model
  /// (sigma_points.hpp); false for Dense<M> and nonlinear models.
  static constexpr bool kAffinePredict = sigma::kAffineTimeUpdate<Motion>;

  Cdkf() : Cdkf(Motion{}, Measurement{}) {}
  Cdkf(const Motion& motion, const Measurement& measurement, const Params& params = Params{})
      : motion_(motion),
        measurement_(measurement),
        params_(params),
        w_(Weights::from(params)),
        x_(State::Zero()),
        P_(Cov::Identity()) {
    diag_ = Diagnostics{MeasVec::Zero(), MeasVec::Zero(), Scalar(0), false, Status::kNotInitialised};
  }

  /// Set the state and covariance.
  /// @return kOk; kNonFinite; kNotPositiveDefinite (filter unchanged on error).
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
      // Affine motion: the first-order differences give exactly F P F^T,
      // the second-order ones vanish (sigma_points.hpp); no points drawn.
      // P_ is positive definite here (reset() and update() check it).
      x = motion_.propagate(x_, dt);
      P = sigma::affine_covariance(motion_, P_, Q, dt);
    } else {
      const Eigen::LLT<Cov> llt(P_);
      if (llt.info() != Eigen::Success) return Status::kNotPositiveDefinite;
      const auto X = sigma::draw<Scalar, kStateDim>(x_, llt.matrixL(), w_.spread);
      const auto Y = sigma::propagate(motion_, X, dt);
      x = sigma::state_mean(Y, w_.wi);
      Mat<Scalar, kStateDim, kStateDim> D1, D2;
      sigma::central_differences<kStateDim>(Y, [](const State& a, const State& b) -> State { return a - b; },
                                            D1, D2);
      P = symmetrised(D1 * D1.transpose() * w_.wc1 + D2 * D2.transpose() * w_.wc2 + Q);
    }
    return commit_prediction(x, P);
  }

  /// Innovation of z against the current (predicted) state with the model's R.
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
    Mat<Scalar, kMeasDim, kStateDim> D1, D2;
    const Measurement& h = measurement_;
    sigma::central_differences<kStateDim>(
        Z, [&h](const MeasVec& a, const MeasVec& b) -> MeasVec { return h.residual(a, b); }, D1, D2);
    m.S = symmetrised(D1 * D1.transpose() * w_.wc1 + D2 * D2.transpose() * w_.wc2 + R);
    m.Pxz = L * D1.transpose() * w_.sqrt_wc1;
    m.nu = measurement_.residual(z, z_mean);
    if (!all_finite(m.S) || !all_finite(m.Pxz) || !all_finite(m.nu)) return Status::kNonFinite;
    m.llt_S.compute(m.S);
    if (m.llt_S.info() != Eigen::Success) return Status::kNotPositiveDefinite;
    return Status::kOk;
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
