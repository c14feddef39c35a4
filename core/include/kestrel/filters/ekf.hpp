// Extended Kalman filter on fixed-size storage (SPEC section 5; paper 000
// section 2-1 and paper 001 section 2 for the equations). The update uses the
// Joseph form P+ = (I - K H) P (I - K H)^T + K R K^T, which stays symmetric
// positive semi-definite under round-off, then symmetrises. With a linear
// motion and measurement model it is exactly the linear Kalman filter.
//
// Every public operation computes into locals and commits only on success:
// a non-finite input or result returns kNonFinite, a failed Cholesky of S
// returns kNotPositiveDefinite, and in both cases x and P are unchanged.
// The explicit-Q / explicit-R overloads are what adaptive filters (R2-AEKF)
// build on, so no adaptive filter copies this update.
#pragma once

#include "kestrel/filters/innovation.hpp"
#include "kestrel/math/eigen.hpp"
#include "kestrel/math/finite.hpp"
#include "kestrel/models/concepts.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"

namespace kestrel {

template <MotionModel Motion, MeasurementModelFor<Motion> Measurement>
class Ekf {
 public:
  using Scalar = typename Motion::Scalar;
  static constexpr int kStateDim = Motion::kStateDim;
  static constexpr int kMeasDim = Measurement::kMeasDim;
  using MotionModel = Motion;
  using MeasurementModel = Measurement;
  using Layout = typename Motion::Layout;
  using State = typename Motion::State;
  using Cov = typename Motion::Cov;
  using MeasVec = typename Measurement::Measurement;
  using MeasCov = typename Measurement::NoiseCov;
  using Innov = Innovation<Scalar, kMeasDim>;
  using Diagnostics = FusionDiagnostics<Scalar, kMeasDim>;

  Ekf() : Ekf(Motion{}, Measurement{}) {}
  Ekf(const Motion& motion, const Measurement& measurement)
      : motion_(motion), measurement_(measurement), x_(State::Zero()), P_(Cov::Identity()) {
    diag_ = Diagnostics{MeasVec::Zero(), MeasVec::Zero(), Scalar(0), false, Status::kNotInitialised};
  }

  /// Set the state and covariance.
  /// @return kOk; kNonFinite if any entry is NaN/Inf (filter unchanged).
  [[nodiscard]] Status reset(const State& x, const Cov& P) {
    if (!all_finite(x) || !all_finite(P)) return Status::kNonFinite;
    x_ = x;
    P_ = symmetrised(P);
    return Status::kOk;
  }

  /// Predict by dt seconds with the model's process noise Q(dt).
  /// @return kOk; kNonFinite (filter unchanged).
  [[nodiscard]] Status predict(Scalar dt) { return predict(dt, motion_.process_noise(dt)); }

  /// Predict by dt seconds with an explicit process noise Q (adaptive filters).
  /// @return kOk; kNonFinite (filter unchanged).
  [[nodiscard]] Status predict(Scalar dt, const Cov& Q) {
    const Cov F = motion_.jacobian(x_, dt);
    const State x = motion_.propagate(x_, dt);
    const Cov P = symmetrised(F * P_ * F.transpose() + Q);
    if (!all_finite(x) || !all_finite(P)) return Status::kNonFinite;
    x_ = x;
    P_ = P;
    return Status::kOk;
  }

  /// Innovation of z against the current (predicted) state with the model's R.
  /// Pure: the gate uses it before deciding to update.
  Innov innovation(const MeasVec& z) const { return innovation(z, measurement_.noise()); }

  /// Innovation of z with an explicit measurement noise R.
  Innov innovation(const MeasVec& z, const MeasCov& R) const {
    Innov out{MeasVec::Zero(), MeasCov::Zero(), Scalar(0), Status::kOk};
    if (!all_finite(z) || !all_finite(R)) {
      out.status = Status::kNonFinite;
      return out;
    }
    const auto H = measurement_.jacobian(x_);
    out.nu = measurement_.residual(z, measurement_.predict(x_));
    out.S = symmetrised(H * P_ * H.transpose() + R);
    if (!all_finite(H) || !all_finite(out.nu) || !all_finite(out.S)) {
      out.status = Status::kNonFinite;
      return out;
    }
    const Eigen::LLT<MeasCov> llt(out.S);
    if (llt.info() != Eigen::Success) {
      out.status = Status::kNotPositiveDefinite;
      return out;
    }
    out.d2 = out.nu.dot(llt.solve(out.nu));
    return out;
  }

  /// Update with z and the model's R.
  /// @return kOk; kNonFinite or kNotPositiveDefinite (filter unchanged).
  [[nodiscard]] Status update(const MeasVec& z) { return update(z, measurement_.noise()); }

  /// Update with z and an explicit R (Joseph form, then symmetrised).
  /// @return kOk; kNonFinite or kNotPositiveDefinite (filter unchanged).
  [[nodiscard]] Status update(const MeasVec& z, const MeasCov& R) {
    diag_.fused = false;
    if (!all_finite(z) || !all_finite(R)) return fail(Status::kNonFinite);
    const auto H = measurement_.jacobian(x_);
    const MeasVec nu = measurement_.residual(z, measurement_.predict(x_));
    const MeasCov S = symmetrised(H * P_ * H.transpose() + R);
    if (!all_finite(H) || !all_finite(nu) || !all_finite(S)) return fail(Status::kNonFinite);
    const Eigen::LLT<MeasCov> llt(S);
    if (llt.info() != Eigen::Success) return fail(Status::kNotPositiveDefinite);

    // K = P H^T S^-1, computed as (S^-1 H P)^T since S and P are symmetric.
    // One vector solve per column: a matrix right-hand side sends Eigen to
    // its blocked triangular solver, which may call malloc (the board's heap
    // guard caught it); vector solves unroll on fixed-size storage.
    const Mat<Scalar, kMeasDim, kStateDim> HP = H * P_;
    Mat<Scalar, kMeasDim, kStateDim> SinvHP;
    for (int c = 0; c < kStateDim; ++c) SinvHP.col(c) = llt.solve(HP.col(c));
    const Mat<Scalar, kStateDim, kMeasDim> K = SinvHP.transpose();
    const State x = x_ + K * nu;
    const Cov A = Cov::Identity() - K * H;
    const Cov P = symmetrised(A * P_ * A.transpose() + K * R * K.transpose());
    if (!all_finite(x) || !all_finite(P)) return fail(Status::kNonFinite);

    x_ = x;
    P_ = P;
    diag_.innovation = nu;
    diag_.innovation_variance = S.diagonal();
    diag_.nis = nu.dot(llt.solve(nu));
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
  /// Diagnostics of the last update attempt.
  const Diagnostics& diagnostics() const { return diag_; }

 private:
  Status fail(Status s) {
    diag_.status = s;
    return s;
  }

  Motion motion_;
  Measurement measurement_;
  State x_;
  Cov P_;
  Diagnostics diag_;
};

}  // namespace kestrel
