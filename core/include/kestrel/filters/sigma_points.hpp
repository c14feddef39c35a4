// SPDX-License-Identifier: Apache-2.0
// Sigma points, their weights and their statistics (paper 001 sections
// 3.2-3.3 and tables 2-5, after van der Merwe 2004, "Sigma-point Kalman
// filters for probabilistic inference in dynamic state-space models",
// sections 3.2-3.4 and algorithms 8-11): the point sets the plain and the
// square-root sigma-point filters take as a template parameter. A point set
// owns its weights and how the covariance, cross-covariance and their square
// roots are formed from the symmetric 2n + 1 points; the filters own drawing,
// propagation, gains and commit-on-success. Every mean is taken in reference
// form through the model's residual(), so bearings are wrap-safe; with an
// affine (block-diagonal) motion model the time update has a closed form.
// Why and how: docs/filters.md, "Sigma points and angles", "One filter per
// form, one point set per rule" and "Why the affine time update is exact".
#pragma once

#include "kestrel/assert.hpp"
#include "kestrel/filters/structure.hpp"
#include "kestrel/math/cholesky_update.hpp"
#include "kestrel/math/eigen.hpp"
#include "kestrel/math/finite.hpp"
#include "kestrel/math/triangular.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"

namespace kestrel {

/// Number of points of a symmetric sigma-point set in n dimensions.
template <int kN>
inline constexpr int kSigmaPointCount = 2 * kN + 1;

/// Scaled unscented transform parameters (Julier 2002; van der Merwe 2004
/// eq. 3.11-3.12). Defaults (docs/filters.md): alpha = 1, beta = 2 (optimal for a
/// Gaussian prior), kappa = 3 - n.
template <class S, int kN>
struct UnscentedConfig {
  S alpha = S(1);       ///< Spread of the points around the mean, (0, 1].
  S beta = S(2);        ///< Prior knowledge of the distribution (2: Gaussian).
  S kappa = S(3 - kN);  ///< Secondary scaling; 3 - n matches the 4th moment of a Gaussian.
};

/// Central difference (Stirling interpolation) parameter (Norgaard, Poulsen,
/// Ravn 2000; van der Merwe 2004 section 3.4.1): h^2 = 3 is optimal for a
/// Gaussian prior (it matches the fourth moment). Default h = sqrt(3) (docs/filters.md).
template <class S>
struct CentralDifferenceConfig {
  S h = lit<S>(1.7320508075688772935);  ///< Half-width of the central difference, h >= 1.
};

namespace sigma {

template <class S, int kN>
using Points = Mat<S, kN, kSigmaPointCount<kN>>;

/// True when the time update takes the closed form of an affine motion (the
/// header note): a block-diagonal model, structure not hidden (Dense<M>
/// keeps the point form, the oracle and the baseline), floating point.
template <class Motion>
inline constexpr bool kAffineTimeUpdate =
    BlockDiagonalMotion<Motion> && !ScalarTraits<typename Motion::Scalar>::kIsFixedPoint;

/// F P F^T + (Q + Q^T) / 2 for an affine (block-diagonal) motion, per axis
/// block (structure.hpp), exactly symmetric: the unscented and the
/// central-difference transforms of P for such a model.
template <BlockDiagonalMotion M>
typename M::Cov affine_covariance(const M& motion, const typename M::Cov& P, const typename M::Cov& Q,
                                  typename M::Scalar dt) {
  typename M::Cov out = structure::transform_covariance(motion, P, dt);
  structure::add_symmetrised(out, Q);
  return out;
}

/// F P F^T + blkdiag(Q1, ..., Q1) with the model's own Q1 =
/// axis_process_noise(dt), per axis block (structure.hpp): the same matrix
/// as affine_covariance(motion, P, process_noise(dt), dt), bit for bit, with
/// no n x n Q formed and no zero block of it added.
template <BlockDiagonalMotion M>
typename M::Cov affine_covariance(const M& motion, const typename M::Cov& P, typename M::Scalar dt) {
  typename M::Cov out = structure::transform_covariance(motion, P, dt);
  structure::add_process_noise(motion, out, dt);
  return out;
}

/// F Sx for F = blkdiag(F1, ..., F1), row block by row block
/// (F1 = axis_transition(dt)); with a unit upper triangular F1 its
/// structural zeros and ones are skipped. (F Sx)(F Sx)^T = F P F^T.
template <BlockDiagonalMotion M>
typename M::Cov affine_sqrt(const M& motion, const typename M::Cov& Sx, typename M::Scalar dt) {
  using S = typename M::Scalar;
  constexpr int d = M::kAxisDim;
  constexpr int kAxes = M::kStateDim / d;
  constexpr bool kUnitUpper = UnitUpperAxisTransition<M>;
  const Mat<S, d, d> F1 = motion.axis_transition(dt);
  typename M::Cov out;
  structure::static_for<0, kAxes>([&](auto ia) {
    constexpr int i = decltype(ia)::value;
    structure::static_for<0, d>([&](auto ra) {
      constexpr int r = decltype(ra)::value;
      if constexpr (kUnitUpper) {
        out.row(i * d + r) = Sx.row(i * d + r);
      } else {
        out.row(i * d + r) = F1(r, r) * Sx.row(i * d + r);
      }
      structure::static_for<(kUnitUpper ? r + 1 : 0), d>([&](auto ka) {
        constexpr int k = decltype(ka)::value;
        if constexpr (k != r) out.row(i * d + r) += F1(r, k) * Sx.row(i * d + k);
      });
    });
  });
  return out;
}

/// X = [x, x + c L, x - c L] (columns), L lower triangular with P = L L^T.
template <class S, int kN>
Points<S, kN> draw(const Vec<S, kN>& x, const Mat<S, kN, kN>& L, S spread) {
  Points<S, kN> X;
  X.col(0) = x;
  for (int i = 0; i < kN; ++i) {
    const Vec<S, kN> d = L.col(i) * spread;
    X.col(1 + i) = x + d;
    X.col(1 + kN + i) = x - d;
  }
  return X;
}

/// Each point through the motion model: Y_i = f(X_i, dt).
template <class Motion>
Points<typename Motion::Scalar, Motion::kStateDim> propagate(
    const Motion& motion, const Points<typename Motion::Scalar, Motion::kStateDim>& X,
    typename Motion::Scalar dt) {
  Points<typename Motion::Scalar, Motion::kStateDim> Y;
  for (int i = 0; i < kSigmaPointCount<Motion::kStateDim>; ++i) {
    Y.col(i) = motion.propagate(X.col(i), dt);
  }
  return Y;
}

/// Each point through the measurement model: Z_i = h(X_i).
template <class Measurement>
Mat<typename Measurement::Scalar, Measurement::kMeasDim, kSigmaPointCount<Measurement::kStateDim>> measure(
    const Measurement& measurement,
    const Points<typename Measurement::Scalar, Measurement::kStateDim>& X) {
  Mat<typename Measurement::Scalar, Measurement::kMeasDim, kSigmaPointCount<Measurement::kStateDim>> Z;
  for (int i = 0; i < kSigmaPointCount<Measurement::kStateDim>; ++i) {
    Z.col(i) = measurement.predict(X.col(i));
  }
  return Z;
}

/// Each point of X = draw(x, L, c) through the measurement model,
/// Z_i = h(X_i), skipping the points h cannot tell from x: a measurement
/// whose Jacobian is zero outside the state columns kJacobianColumns
/// (SparseJacobianMeasurement, structure.hpp) reads only those entries, so
/// where column j of L is exactly zero in all of them, X_(1+j) and
/// X_(1+n+j) equal x there (x +- c 0 = x) and their Z is Z_0, the same
/// h(x) bit for bit. With L lower triangular that is every column past
/// the last measured state (polar radar on CA-2D: 4 of the 13 points; on
/// CV-2D: 2 of 9). Without the structure (Dense<H>) every point is
/// measured, the same result.
template <class Measurement>
Mat<typename Measurement::Scalar, Measurement::kMeasDim, kSigmaPointCount<Measurement::kStateDim>> measure_drawn(
    const Measurement& measurement, const Points<typename Measurement::Scalar, Measurement::kStateDim>& X,
    const Mat<typename Measurement::Scalar, Measurement::kStateDim, Measurement::kStateDim>& L) {
  using S = typename Measurement::Scalar;
  if constexpr (SparseJacobianMeasurement<Measurement> && !ScalarTraits<S>::kIsFixedPoint) {
    constexpr int n = Measurement::kStateDim;
    Mat<S, Measurement::kMeasDim, kSigmaPointCount<n>> Z;
    Z.col(0) = measurement.predict(X.col(0));
    for (int j = 0; j < n; ++j) {
      bool moves = false;
      for (const auto c : Measurement::kJacobianColumns) {
        const S l = L(static_cast<int>(c), j);  // != 0 without -Wfloat-equal; NaN counts as moving
        moves = moves || l < S(0) || l > S(0) || !ScalarTraits<S>::is_finite(l);
      }
      if (moves) {
        Z.col(1 + j) = measurement.predict(X.col(1 + j));
        Z.col(1 + n + j) = measurement.predict(X.col(1 + n + j));
      } else {
        Z.col(1 + j) = Z.col(0);
        Z.col(1 + n + j) = Z.col(0);
      }
    }
    return Z;
  } else {
    static_cast<void>(L);
    return measure(measurement, X);
  }
}

/// Weighted state mean in reference form X_0 + w_i sum (X_i - X_0) (equal to
/// sum_i w_i X_i since the weights sum to one; better conditioned when W_0
/// is negative and the state is far from the origin).
template <class S, int kN, int kL>
Vec<S, kN> state_mean(const Mat<S, kN, kL>& X, S wi) {
  Vec<S, kN> acc = Vec<S, kN>::Zero();
  for (int i = 1; i < kL; ++i) acc += X.col(i) - X.col(0);
  return X.col(0) + acc * wi;
}

/// Weighted measurement mean Z_0 + w_i sum residual(Z_i, Z_0): wrap-safe for
/// any channel the model's residual() wraps (see the header note).
template <class Measurement, class S, int kM, int kL>
Vec<S, kM> measurement_mean(const Measurement& measurement, const Mat<S, kM, kL>& Z, S wi) {
  Vec<S, kM> acc = Vec<S, kM>::Zero();
  const Vec<S, kM> z0 = Z.col(0);
  for (int i = 1; i < kL; ++i) acc += measurement.residual(Z.col(i), z0);
  return z0 + acc * wi;
}

/// Deviations of every point from a reference: D_i = residual(Z_i, z_ref).
template <class Measurement, class S, int kM, int kL>
Mat<S, kM, kL> measurement_deviations(const Measurement& measurement, const Mat<S, kM, kL>& Z,
                                      const Vec<S, kM>& z_ref) {
  Mat<S, kM, kL> D;
  for (int i = 0; i < kL; ++i) D.col(i) = measurement.residual(Z.col(i), z_ref);
  return D;
}

/// Central-difference terms of a point set (van der Merwe 2004 eq. 3.90-3.91):
/// first-order D1_i = Y_i - Y_(n+i) and second-order
/// D2_i = (Y_i - Y_0) + (Y_(n+i) - Y_0), i = 1..n, with `diff(a, b)` the
/// space's difference (a - b for states, residual() for measurements).
template <int kN, class S, int kM, class Diff>
void central_differences(const Mat<S, kM, kSigmaPointCount<kN>>& Y, Diff diff, Mat<S, kM, kN>& D1,
                         Mat<S, kM, kN>& D2) {
  const Vec<S, kM> y0 = Y.col(0);
  for (int i = 0; i < kN; ++i) {
    const Vec<S, kM> yp = Y.col(1 + i);
    const Vec<S, kM> ym = Y.col(1 + kN + i);
    D1.col(i) = diff(yp, ym);
    D2.col(i) = diff(yp, y0) + diff(ym, y0);
  }
}

/// Kalman gain K = Pxz S^-1, computed as (S^-1 Pxz^T)^T (S symmetric) from
/// S's Cholesky factor, one column of Pxz^T at a time: a matrix right-hand
/// side sends Eigen to its blocked triangular solver, which may allocate
/// (the same reason as in ekf.hpp); the fixed-size vector solve does not.
template <class S, int kN, int kM>
Mat<S, kN, kM> gain(const Eigen::LLT<Mat<S, kM, kM>>& llt_S, const Mat<S, kN, kM>& Pxz) {
  Mat<S, kM, kN> SinvPzx;
  for (int c = 0; c < kN; ++c) SinvPzx.col(c) = llt_S.solve(Pxz.row(c).transpose());
  return SinvPzx.transpose();
}

}  // namespace sigma

/// The scaled unscented transform (Julier 2002; van der Merwe 2004 eq.
/// 3.11-3.12; the UKF, algorithm 8 / paper 001 table 2, and the SR-UKF,
/// algorithm 10 / table 4): its weights,
///   lambda = alpha^2 (n + kappa) - n, spread c = sqrt(n + lambda),
///   Wm_0 = lambda / (n + lambda), Wc_0 = Wm_0 + 1 - alpha^2 + beta,
///   W_i = 1 / (2 (n + lambda)) for i >= 1 (mean and covariance alike),
/// and its statistics: weighted outer products of the deviations from the
/// mean. Wc_0 may be negative (n > 3 with the default parameters), so the square
/// root form leaves X_0 out of the QR and adds it by a rank-1 update.
template <class Scalar, int kN>
struct UnscentedPoints {
  using Config = UnscentedConfig<Scalar, kN>;
  static constexpr int kCount = kSigmaPointCount<kN>;
  using State = Vec<Scalar, kN>;
  using Cov = Mat<Scalar, kN, kN>;
  using Points = sigma::Points<Scalar, kN>;

  Scalar spread{};   ///< sqrt(n + lambda).
  Scalar wm0{};      ///< Mean weight of X_0 (negative for n > 3 with the defaults).
  Scalar wc0{};      ///< Covariance weight of X_0.
  Scalar wi{};       ///< Weight of X_1 .. X_2n (positive).
  Scalar sqrt_wi{};  ///< sqrt(W_i), the column scale of the SR-UKF compound matrix.

  static UnscentedPoints from(const Config& p) {
    using T = ScalarTraits<Scalar>;
    const Scalar n = Scalar(kN);
    const Scalar n_lambda = p.alpha * p.alpha * (n + p.kappa);  // n + lambda
    KESTREL_ASSERT(n_lambda > Scalar(0));  // programmer error: alpha^2 (n + kappa) must be > 0
    UnscentedPoints w;
    w.spread = T::sqrt(n_lambda);
    w.wm0 = (n_lambda - n) / n_lambda;
    w.wc0 = w.wm0 + Scalar(1) - p.alpha * p.alpha + p.beta;
    w.wi = Scalar(1) / (Scalar(2) * n_lambda);
    w.sqrt_wi = T::sqrt(w.wi);
    return w;
  }

  /// Time update, algorithm 8: P- = sum Wc_i (Y_i - x-)(Y_i - x-)^T + Q,
  /// symmetrised.
  Cov covariance(const Points& Y, const State& x, const Cov& Q) const {
    const State d0 = Y.col(0) - x;
    Cov P = d0 * d0.transpose() * wc0;
    for (int i = 1; i < kCount; ++i) {
      const State d = Y.col(i) - x;
      P += d * d.transpose() * wi;
    }
    return symmetrised(P + Q);
  }

  /// Measurement update, algorithm 8: S = sum Wc_i dZ_i dZ_i^T + R
  /// (symmetrised) and Pxz = sum Wc_i (X_i - x) dZ_i^T, dZ_i =
  /// residual(Z_i, z-), for X = draw(x, L, spread) and Z_i = h(X_i).
  template <class Measurement, int kM>
  void moments(const Measurement& h, const Points& X, const State& x, const Cov& /*L*/,
               const Mat<Scalar, kM, kCount>& Z, const Vec<Scalar, kM>& z_mean, const Mat<Scalar, kM, kM>& R,
               Mat<Scalar, kM, kM>& S, Mat<Scalar, kN, kM>& Pxz) const {
    const auto dZ = sigma::measurement_deviations(h, Z, z_mean);
    // X_0 - x = 0 exactly (the points are redrawn about x), so only
    // X_1..X_2n contribute to Pxz.
    Mat<Scalar, kM, kM> Szz = dZ.col(0) * dZ.col(0).transpose() * wc0;
    Pxz.setZero();
    for (int i = 1; i < kCount; ++i) {
      Szz += dZ.col(i) * dZ.col(i).transpose() * wi;
      Pxz += (X.col(i) - x) * dZ.col(i).transpose() * wi;
    }
    S = symmetrised(Szz + R);
  }

  /// Square-root time update, algorithm 10: Sx- = qr{[sqrt(W_i)(Y_(1..2n) -
  /// x-), Sq]}, then cholupdate(Sx-, Y_0 - x-, Wc_0) (a downdate if Wc_0 < 0).
  /// @return kOk; kNotPositiveDefinite or kNonFinite from the rank-1 update.
  Status sqrt_covariance(const Points& Y, const State& x, const Cov& Sq, Cov& Sx) const {
    Mat<Scalar, kN, 2 * kN + kN> A;
    for (int i = 1; i < kCount; ++i) A.col(i - 1) = (Y.col(i) - x) * sqrt_wi;
    A.template rightCols<kN>() = Sq;
    Sx = triangularise(A);
    return cholesky_rank1_update<Scalar, kN>(Sx, Y.col(0) - x, wc0);
  }

  /// Square-root measurement update, algorithm 10: Sy = qr{[sqrt(W_i)
  /// dZ_(1..2n), Sr]}, Sy = cholupdate(Sy, dZ_0, Wc_0), and Pxz as in
  /// moments(), for X = draw(x, Sx, spread).
  /// @return kOk; kNotPositiveDefinite or kNonFinite from the rank-1 update.
  template <class Measurement, int kM>
  Status sqrt_moments(const Measurement& h, const Points& X, const State& x, const Cov& /*Sx*/,
                      const Mat<Scalar, kM, kCount>& Z, const Vec<Scalar, kM>& z_mean,
                      const Mat<Scalar, kM, kM>& Sr, Mat<Scalar, kM, kM>& Sy, Mat<Scalar, kN, kM>& Pxz) const {
    const auto dZ = sigma::measurement_deviations(h, Z, z_mean);
    Mat<Scalar, kM, 2 * kN + kM> A;
    Pxz.setZero();
    for (int i = 1; i < kCount; ++i) {
      A.col(i - 1) = dZ.col(i) * sqrt_wi;
      Pxz += (X.col(i) - x) * dZ.col(i).transpose() * wi;
    }
    A.template rightCols<kM>() = Sr;
    Sy = triangularise(A);
    return cholesky_rank1_update<Scalar, kM>(Sy, dZ.col(0), wc0);
  }
};

/// Central difference (Stirling interpolation) in place of the Taylor
/// series (Norgaard, Poulsen, Ravn 2000; Ito and Xiong 2000; van der Merwe
/// 2004 section 3.4.1; the CDKF, algorithm 9 / paper 001 table 3, and the
/// SR-CDKF, algorithm 11 / table 5). Weights (eq. 3.85-3.88):
///   spread c = h, Wm_0 = (h^2 - n) / h^2, Wm_i = 1 / (2 h^2),
///   Wc1 = 1 / (4 h^2), Wc2 = (h^2 - 1) / (4 h^4),
/// and statistics from the first-order differences D1_i = Y_i - Y_(n+i)
/// and the second-order ones D2_i = Y_i + Y_(n+i) - 2 Y_0 (eq. 3.90-3.91;
/// measurement differences through residual()). Wc1 and Wc2 are never
/// negative, so the square-root form needs no rank-1 update.
template <class Scalar, int kN>
struct CentralDifferencePoints {
  using Config = CentralDifferenceConfig<Scalar>;
  static constexpr int kCount = kSigmaPointCount<kN>;
  using State = Vec<Scalar, kN>;
  using Cov = Mat<Scalar, kN, kN>;
  using Points = sigma::Points<Scalar, kN>;

  Scalar spread{};    ///< h.
  Scalar wm0{};       ///< Mean weight of X_0.
  Scalar wi{};        ///< Mean weight of X_1 .. X_2n.
  Scalar wc1{};       ///< Weight of the first-order terms (X_i - X_(n+i)).
  Scalar wc2{};       ///< Weight of the second-order terms (X_i + X_(n+i) - 2 X_0).
  Scalar sqrt_wc1{};  ///< sqrt(Wc1) = 1 / (2h).
  Scalar sqrt_wc2{};  ///< sqrt(Wc2) = sqrt(h^2 - 1) / (2 h^2).

  static CentralDifferencePoints from(const Config& p) {
    using T = ScalarTraits<Scalar>;
    KESTREL_ASSERT(p.h >= Scalar(1));  // programmer error: Wc2 must be >= 0
    const Scalar h2 = p.h * p.h;
    CentralDifferencePoints w;
    w.spread = p.h;
    w.wm0 = (h2 - Scalar(kN)) / h2;
    w.wi = Scalar(1) / (Scalar(2) * h2);
    w.wc1 = Scalar(1) / (Scalar(4) * h2);
    w.wc2 = (h2 - Scalar(1)) / (Scalar(4) * h2 * h2);
    w.sqrt_wc1 = T::sqrt(w.wc1);
    w.sqrt_wc2 = T::sqrt(w.wc2);
    return w;
  }

  /// Time update, algorithm 9: P- = sum_(i=1..n) [Wc1 D1_i D1_i^T +
  /// Wc2 D2_i D2_i^T] + Q, symmetrised.
  Cov covariance(const Points& Y, const State& /*x*/, const Cov& Q) const {
    Cov D1, D2;
    state_differences(Y, D1, D2);
    return symmetrised(D1 * D1.transpose() * wc1 + D2 * D2.transpose() * wc2 + Q);
  }

  /// Measurement update, algorithm 9: S = the same two sums over Z + R
  /// (symmetrised) and Pxz = sqrt(Wc1) L D1^T, for X = draw(x, L, h).
  template <class Measurement, int kM>
  void moments(const Measurement& h, const Points& /*X*/, const State& /*x*/, const Cov& L,
               const Mat<Scalar, kM, kCount>& Z, const Vec<Scalar, kM>& /*z_mean*/, const Mat<Scalar, kM, kM>& R,
               Mat<Scalar, kM, kM>& S, Mat<Scalar, kN, kM>& Pxz) const {
    Mat<Scalar, kM, kN> D1, D2;
    measurement_differences(h, Z, D1, D2);
    S = symmetrised(D1 * D1.transpose() * wc1 + D2 * D2.transpose() * wc2 + R);
    Pxz = L * D1.transpose() * sqrt_wc1;
  }

  /// Square-root time update, algorithm 11: Sx- = qr{[sqrt(Wc1) D1,
  /// sqrt(Wc2) D2, Sq]}.
  /// @return kOk (the weights are non-negative: no downdate to fail).
  Status sqrt_covariance(const Points& Y, const State& /*x*/, const Cov& Sq, Cov& Sx) const {
    Cov D1, D2;
    state_differences(Y, D1, D2);
    Mat<Scalar, kN, 3 * kN> A;
    A.template leftCols<kN>() = D1 * sqrt_wc1;
    A.template middleCols<kN>(kN) = D2 * sqrt_wc2;
    A.template rightCols<kN>() = Sq;
    Sx = triangularise(A);
    return Status::kOk;
  }

  /// Square-root measurement update, algorithm 11: Sy = qr{[sqrt(Wc1) D1,
  /// sqrt(Wc2) D2, Sr]} over Z and Pxz = sqrt(Wc1) Sx D1^T, for
  /// X = draw(x, Sx, h).
  /// @return kOk.
  template <class Measurement, int kM>
  Status sqrt_moments(const Measurement& h, const Points& /*X*/, const State& /*x*/, const Cov& Sx,
                      const Mat<Scalar, kM, kCount>& Z, const Vec<Scalar, kM>& /*z_mean*/,
                      const Mat<Scalar, kM, kM>& Sr, Mat<Scalar, kM, kM>& Sy, Mat<Scalar, kN, kM>& Pxz) const {
    Mat<Scalar, kM, kN> D1, D2;
    measurement_differences(h, Z, D1, D2);
    Mat<Scalar, kM, 2 * kN + kM> A;
    A.template leftCols<kN>() = D1 * sqrt_wc1;
    A.template middleCols<kN>(kN) = D2 * sqrt_wc2;
    A.template rightCols<kM>() = Sr;
    Sy = triangularise(A);
    Pxz = Sx * D1.transpose() * sqrt_wc1;
    return Status::kOk;
  }

 private:
  static void state_differences(const Points& Y, Cov& D1, Cov& D2) {
    sigma::central_differences<kN>(Y, [](const State& a, const State& b) -> State { return a - b; }, D1, D2);
  }

  template <class Measurement, int kM>
  static void measurement_differences(const Measurement& h, const Mat<Scalar, kM, kCount>& Z,
                                      Mat<Scalar, kM, kN>& D1, Mat<Scalar, kM, kN>& D2) {
    using MeasVec = Vec<Scalar, kM>;
    sigma::central_differences<kN>(
        Z, [&h](const MeasVec& a, const MeasVec& b) -> MeasVec { return h.residual(a, b); }, D1, D2);
  }
};

}  // namespace kestrel
