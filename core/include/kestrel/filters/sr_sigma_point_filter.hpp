// SPDX-License-Identifier: Apache-2.0
// The square-root sigma-point Kalman filter, additive noise, over a choice of
// point set (paper 001 section 3.3): SrUkf (table 4; van der Merwe and Wan
// 2001, van der Merwe 2004 algorithm 10) and SrCdkf (table 5; van der Merwe
// 2004 algorithm 11). It carries the lower-triangular factor Sx (P = Sx Sx^T)
// instead of P, so no Cholesky of P is taken per step; the points and weights
// are those of the plain form, and in exact arithmetic so are the estimates
// (tested to 1e-9 relative in double). qr{} is math/triangular.hpp's
// Householder triangularisation and cholupdate math/cholesky_update.hpp
// (Eigen's LLT::rankUpdate allocates). Commit on success: kNonFinite, or
// kNotPositiveDefinite when a downdate would lose definiteness, Q or R is
// indefinite or Sy is singular; x and Sx are then unchanged. Equations:
// docs/filters.md, "SR-UKF and SR-CDKF".
#pragma once

#include "kestrel/filters/sigma_point_parts.hpp"
#include "kestrel/filters/sigma_points.hpp"
#include "kestrel/filters/sqrt_time_update.hpp"
#include "kestrel/math/cholesky_update.hpp"
#include "kestrel/math/eigen.hpp"
#include "kestrel/math/finite.hpp"
#include "kestrel/math/triangular.hpp"
#include "kestrel/models/concepts.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"

namespace kestrel {

/// PointSet<Scalar, n> is a point set of sigma_points.hpp (UnscentedPoints,
/// CentralDifferencePoints); the names, models, weights, x and diagnostics
/// are sigma::FilterParts (sigma_point_parts.hpp).
template <MotionModel Motion, MeasurementModelFor<Motion> Measurement, template <class, int> class PointSet>
class SrSigmaPointFilter : public sigma::FilterParts<Motion, Measurement, PointSet> {
  using Base = sigma::FilterParts<Motion, Measurement, PointSet>;
  using Base::motion_, Base::measurement_, Base::w_, Base::x_, Base::diag_, Base::fail;

 public:
  using typename Base::Scalar, typename Base::State, typename Base::Cov, typename Base::MeasVec,
      typename Base::MeasCov, typename Base::Innov, typename Base::Config;
  using Base::kStateDim, Base::kMeasDim, Base::kAffinePredict;

  SrSigmaPointFilter() : SrSigmaPointFilter(Motion{}, Measurement{}) {}
  SrSigmaPointFilter(const Motion& motion, const Measurement& measurement, const Config& params = Config{})
      : Base(motion, measurement, params), Sx_(Cov::Identity()), P_(Cov::Identity()) {}

  /// Set the state and covariance (factorised once here).
  /// @return kOk; kNonFinite; kNotPositiveDefinite (filter unchanged on error).
  [[nodiscard]] Status reset(const State& x, const Cov& P) {
    if (!all_finite(x) || !all_finite(P)) return Status::kNonFinite;
    const Eigen::LLT<Cov> llt(symmetrised(P));
    if (llt.info() != Eigen::Success) return Status::kNotPositiveDefinite;
    commit(x, llt.matrixL());
    return Status::kOk;
  }

  /// Predict by dt seconds with the model's process noise Q(dt).
  /// @return kOk; kNonFinite; kNotPositiveDefinite (filter unchanged on error).
  [[nodiscard]] Status predict(Scalar dt) {
    if constexpr (kAffinePredict) {
      // Q = blkdiag(Q1, ...): its factor from one d x d Cholesky of Q1
      // (sqrt_time_update.hpp), never the n x n Q.
      if (!ScalarTraits<Scalar>::is_finite(dt)) return Status::kNonFinite;
      Cov Sq;
      KESTREL_TRY(sigma::block_sqrt_process_noise(motion_, dt, Sq));
      return predict_affine(dt, Sq);
    } else {
      return predict(dt, motion_.process_noise(dt));
    }
  }

  /// Predict by dt seconds with an explicit process noise Q.
  /// @return kOk; kNonFinite; kNotPositiveDefinite (filter unchanged on error).
  [[nodiscard]] Status predict(Scalar dt, const Cov& Q) {
    if (!ScalarTraits<Scalar>::is_finite(dt) || !all_finite(Q)) return Status::kNonFinite;
    Cov Sq;
    KESTREL_TRY(cholesky_semidefinite<Scalar, kStateDim>(Q, Sq));
    if constexpr (kAffinePredict) {
      return predict_affine(dt, Sq);
    } else {
      const auto X = sigma::draw<Scalar, kStateDim>(x_, Sx_, w_.spread);
      const auto Y = sigma::propagate(motion_, X, dt);
      const State x = sigma::state_mean(Y, w_.wi);
      Cov S;
      KESTREL_TRY(w_.sqrt_covariance(Y, x, Sq, S));
      if (!all_finite(x) || !all_finite(S)) return Status::kNonFinite;
      commit(x, S);
      return Status::kOk;
    }
  }

  /// Innovation of z against the current (predicted) state with the model's R.
  Innov innovation(const MeasVec& z) const { return innovation(z, measurement_.noise()); }

  /// Innovation of z with an explicit measurement noise R (S = Sy Sy^T).
  Innov innovation(const MeasVec& z, const MeasCov& R) const {
    Innov out{MeasVec::Zero(), MeasCov::Zero(), Scalar(0), Status::kOk};
    Moments m;
    out.status = moments(z, R, m);
    if (out.status != Status::kOk) return out;
    out.nu = m.nu;
    out.S = m.Sy * m.Sy.transpose();
    out.d2 = solve_lower<Scalar, kMeasDim, 1>(m.Sy, m.nu).squaredNorm();
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
    // K^T = Sy^-T (Sy^-1 Pxz^T).
    const Mat<Scalar, kMeasDim, kStateDim> Kt = solve_lower_transposed<Scalar, kMeasDim, kStateDim>(
        m.Sy, solve_lower<Scalar, kMeasDim, kStateDim>(m.Sy, m.Pxz.transpose()));
    const Mat<Scalar, kStateDim, kMeasDim> K = Kt.transpose();
    const State x = x_ + K * m.nu;
    Cov S = Sx_;
    const Mat<Scalar, kStateDim, kMeasDim> U = K * m.Sy;
    KESTREL_TRY_OR(fail, cholesky_rank_update<Scalar, kStateDim, kMeasDim>(S, U, Scalar(-1)));
    if (!all_finite(x)) return fail(Status::kNonFinite);
    commit(x, S);
    diag_.fused_all(m.nu, (m.Sy * m.Sy.transpose()).diagonal(), solve_lower<Scalar, kMeasDim, 1>(m.Sy, m.nu).squaredNorm());
    return Status::kOk;
  }

  /// P = Sx Sx^T, formed once per committed step.
  const Cov& P() const { return P_; }
  /// Lower-triangular square root of P carried by the filter.
  const Cov& sqrt_P() const { return Sx_; }

 private:
  struct Moments {
    MeasVec nu;
    MeasCov Sy;  ///< Lower-triangular square root of S.
    Mat<Scalar, kStateDim, kMeasDim> Pxz;
  };

  /// Closed-form time update of an affine motion, Sq = sqrt(Q) lower
  /// triangular: x- = f(x), Sx- = qr{[F Sx, Sq]} on its block profile
  /// (sqrt_time_update.hpp), a factor of F P F^T + Q; the point forms'
  /// extra terms vanish for such a model (the unscented rank-1 update by
  /// Y_0 - x- = 0, the central-difference D2 = 0: sigma_points.hpp).
  /// No points drawn.
  Status predict_affine(Scalar dt, const Cov& Sq) {
    const State x = motion_.propagate(x_, dt);
    const Cov S = sigma::affine_sqrt_time_update(motion_, Sx_, Sq, dt);
    if (!all_finite(x) || !all_finite(S)) return Status::kNonFinite;
    commit(x, S);
    return Status::kOk;
  }

  Status moments(const MeasVec& z, const MeasCov& R, Moments& m) const {
    if (!all_finite(z) || !all_finite(R)) return Status::kNonFinite;
    MeasCov Sr;
    KESTREL_TRY(cholesky_semidefinite<Scalar, kMeasDim>(symmetrised(R), Sr));
    const auto X = sigma::draw<Scalar, kStateDim>(x_, Sx_, w_.spread);
    const auto Z = sigma::measure_drawn(measurement_, X, Sx_);
    const MeasVec z_mean = sigma::measurement_mean(measurement_, Z, w_.wi);
    KESTREL_TRY(w_.sqrt_moments(measurement_, X, x_, Sx_, Z, z_mean, Sr, m.Sy, m.Pxz));
    for (int i = 0; i < kMeasDim; ++i) {
      if (!(m.Sy(i, i) > Scalar(0))) return Status::kNotPositiveDefinite;
    }
    m.nu = measurement_.residual(z, z_mean);
    if (!all_finite(m.Sy) || !all_finite(m.Pxz) || !all_finite(m.nu)) return Status::kNonFinite;
    return Status::kOk;
  }

  void commit(const State& x, const Cov& S) {
    x_ = x;
    Sx_ = S;
    P_ = symmetrised(Sx_ * Sx_.transpose());
  }

  Cov Sx_;
  Cov P_;
};

/// Square-root UKF (algorithm 10), the Ukf's parameters.
template <MotionModel Motion, MeasurementModelFor<Motion> Measurement>
using SrUkf = SrSigmaPointFilter<Motion, Measurement, UnscentedPoints>;

/// Square-root CDKF (algorithm 11), the Cdkf's parameter.
template <MotionModel Motion, MeasurementModelFor<Motion> Measurement>
using SrCdkf = SrSigmaPointFilter<Motion, Measurement, CentralDifferencePoints>;

}  // namespace kestrel
