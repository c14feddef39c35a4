// SPDX-License-Identifier: Apache-2.0
// R2-AEKF: the range/bearing-rescaled, anisotropic-Q adaptive EKF of paper
// 000 (Park et al., section 2-2, eqs. 7-18), on top of kestrel::Ekf with
// explicit Q and R (no copy of the EKF). Per step it rescales the
// measurement noise per channel from the innovation statistics (eqs. 8-12,
// with robust gating) and shapes the process noise along and across the
// estimated velocity from manoeuvre indicators (eqs. 13-18). Two modes share
// one implementation: kPaper follows the printed equations, kDefault carries
// the corrections a simulation check found necessary. Fixed-size storage, no
// allocation, no exceptions; any scalar with ScalarTraits. The step order,
// the modes and why: docs/r2aekf.md, "Equations, step by step" and "What the
// default mode corrects, and why".
#pragma once

#include <concepts>
#include <cstdint>
#include <utility>

#include "kestrel/association/chi_square.hpp"
#include "kestrel/filters/ekf.hpp"
#include "kestrel/filters/innovation.hpp"
#include "kestrel/math/eigen.hpp"
#include "kestrel/math/finite.hpp"
#include "kestrel/models/concepts.hpp"
#include "kestrel/models/measurement/polar_radar.hpp"
#include "kestrel/models/motion/constant_acceleration_2d.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"

namespace kestrel {

/// Which form of the R2-AEKF equations to run (docs/r2aekf.md).
enum class R2AekfMode : std::uint8_t {
  kPaper,    ///< The printed equations of paper 000 section 2-2, literally.
  kDefault,  ///< With the corrections of docs/r2aekf.md (spread R law, velocity-frame indicators).
};

/// How the axial/lateral Q scales become a process noise (eqs. 17-18).
enum class R2AekfQForm : std::uint8_t {
  kDiagonal,     ///< Eq. 17-18: blkdiag(sQx Q1D, sQy Q1D), the diagonal of the rotated scaling.
  kFullRotated,  ///< kron(M, Q1D), M = sQax a a^T + sQlat t t^T (keeps the x-y coupling).
};

/// Every R2-AEKF parameter, unitless unless stated. The defaults are the documented
/// starting point (docs/r2aekf.md) (beta 0.2, alphaR 0.5, delta 0.5, R scale in [1, 5], uR 1.3,
/// dR 0.9, alphaQ 50, Q scale in [1, 400], uQ 2, dQ 0.9) in default mode;
/// values neither the paper nor that starting point gives are marked "(Kestrel)" and explained in
/// docs/r2aekf.md. paper() gives the paper-mode preset.
template <class Scalar>
struct R2AekfConfig {
  R2AekfMode mode = R2AekfMode::kDefault;  ///< Equations to run.

  // --- Measurement-noise law, eqs. 8-12 ---
  Scalar beta_r = lit<Scalar>(0.2);   ///< EWMA rate of the range channel (eq. 9), in (0, 1].
  Scalar beta_b = lit<Scalar>(0.2);   ///< EWMA rate of the bearing channel (eq. 9), in (0, 1].
  Scalar alpha_r = lit<Scalar>(0.5);  ///< Sensitivity alphaR of the R target scale (eq. 10).
  Scalar delta = lit<Scalar>(0.5);    ///< Deadband delta above NIS 1 (eq. 10).
  Scalar r_min = lit<Scalar>(1.0);    ///< Lower clamp Rmin of an R scale (a std-dev factor).
  Scalar r_max = lit<Scalar>(5.0);    ///< Upper clamp Rmax of an R scale.
  Scalar u_r = lit<Scalar>(1.3);      ///< Rise limit uR per update (eq. 11), >= 1.
  Scalar d_r = lit<Scalar>(0.9);      ///< Fall limit dR per update (eq. 11), in (0, 1].

  // --- Robust gating (section 2-2-1, after eq. 12) ---
  Scalar rho = lit<Scalar>(1.0);  ///< Extra R factor for one update when d2 > nis_threshold (1 = off).
  /// d2 threshold: chi-square, 2 degrees of freedom, 99 % (Kestrel; the paper gives none).
  Scalar nis_threshold = lit<Scalar>(chi_square_quantile<2>(GateProbability::k99));

  // --- Manoeuvre indicators, paper mode (eqs. 13-16) ---
  /// Reference turn tau0 of eq. 14 in units of sb/T (so |nu_b| > tau0*sb triggers).
  Scalar tau0 = lit<Scalar>(3.0);
  /// Use eq. 16 as printed (phi_ax drives the lateral scale too) instead of
  /// the text's phi_lat. Paper mode only.
  bool printed_eq16 = false;

  // --- Manoeuvre indicators, default mode ---
  Scalar beta_q = lit<Scalar>(0.2);   ///< EWMA rate of the squared velocity-frame innovations (Kestrel).
  Scalar delta_q = lit<Scalar>(0.5);  ///< Deadband deltaQ of phi = sqrt(mean) - (1 + deltaQ) (Kestrel).

  // --- Process-noise law, eqs. 16-18 ---
  Scalar alpha_q_ax = lit<Scalar>(50.0);   ///< Sensitivity alphaQax (eq. 16).
  Scalar alpha_q_lat = lit<Scalar>(50.0);  ///< Sensitivity alphaQlat (eq. 16).
  Scalar q_min = lit<Scalar>(1.0);         ///< Lower clamp Qmin of a Q scale (a variance factor).
  Scalar q_max = lit<Scalar>(400.0);       ///< Upper clamp Qmax of a Q scale.
  Scalar u_q = lit<Scalar>(2.0);           ///< Rise limit uQ per update, >= 1.
  Scalar d_q = lit<Scalar>(0.9);           ///< Fall limit dQ per update, in (0, 1].
  R2AekfQForm q_form = R2AekfQForm::kDiagonal;  ///< Eq. 17-18 diagonal, or the full rotated form.
  /// Below this speed (m/s) the velocity frame is undefined: Q is scaled
  /// isotropically by max(sQax, sQlat) (Kestrel).
  Scalar min_speed_mps = lit<Scalar>(1.0);

  /// The paper-mode preset: the printed equations, robust gating on with
  /// rho = 2 (Kestrel: the paper only says rho > 1), everything else as default.
  static constexpr R2AekfConfig paper() {
    R2AekfConfig c;
    c.mode = R2AekfMode::kPaper;
    c.rho = lit<Scalar>(2.0);
    return c;
  }

  /// true when every parameter is in its documented range.
  constexpr bool valid() const {
    const Scalar zero(0);
    const Scalar one(1);
    return beta_r > zero && beta_r <= one && beta_b > zero && beta_b <= one && alpha_r >= zero &&
           delta >= zero && r_min > zero && r_min <= r_max && u_r >= one && d_r > zero && d_r <= one &&
           rho >= one && nis_threshold > zero && tau0 > zero && beta_q > zero && beta_q <= one &&
           delta_q >= zero && alpha_q_ax >= zero && alpha_q_lat >= zero && q_min > zero && q_min <= q_max &&
           u_q >= one && d_q > zero && d_q <= one && min_speed_mps > zero;
  }
};

/// The adaptation state and everything observable about the last step
/// (paper fig. 4). Scales start at 1 and are rewritten by every successful
/// update; a refused update leaves them unchanged.
template <class Scalar>
struct R2AekfAdaptation {
  // The four scales (paper fig. 4).
  Scalar s_r_range = Scalar(1);    ///< sRr: range sigma factor of R_k (eq. 11-12).
  Scalar s_r_bearing = Scalar(1);  ///< sRb: bearing sigma factor of R_k (eq. 11-12).
  Scalar s_q_axial = Scalar(1);    ///< sQax: along-velocity Q factor (eq. 16).
  Scalar s_q_lateral = Scalar(1);  ///< sQlat: across-velocity Q factor (eq. 16).
  /// Process-noise mixing M (2x2): Q_k = kron(M, Q1D). Diagonal form: diag(sQx, sQy) of eq. 17.
  Mat<Scalar, 2, 2> q_mix = Mat<Scalar, 2, 2>::Identity();

  // R law, per channel (index 0 range, 1 bearing).
  Vec<Scalar, 2> e = Vec<Scalar, 2>::Zero();          ///< nu_c / sqrt(S_pre_cc) (sqrt of eq. 8, signed).
  Vec<Scalar, 2> nis_bar = Vec<Scalar, 2>::Ones();    ///< EWMA of e^2 (eq. 9).
  Vec<Scalar, 2> e_bar = Vec<Scalar, 2>::Zero();      ///< EWMA of e (default mode; 0 in paper mode).
  Vec<Scalar, 2> spread = Vec<Scalar, 2>::Ones();     ///< What eq. 10 used: nis_bar (paper) or nis_bar - e_bar^2.
  Scalar d2 = Scalar(0);        ///< nu^T S^-1 nu with R_k (before rho).
  bool robust_gated = false;    ///< rho was applied to this update's R.

  // Manoeuvre indicators.
  Scalar tau = Scalar(0);          ///< |nu_b| / T, rad/s (eq. 13; both modes report it).
  Scalar phi_axial = Scalar(0);    ///< phi_ax (eq. 15 or the default-mode form).
  Scalar phi_lateral = Scalar(0);  ///< phi_lat (eq. 14 or the default-mode form).
  Scalar w_axial = Scalar(1);      ///< Default mode: EWMA of the squared normalised axial innovation.
  Scalar w_lateral = Scalar(1);    ///< Default mode: EWMA of the squared normalised lateral innovation.
  Vec<Scalar, 2> axial_unit = Vec<Scalar, 2>(Scalar(1), Scalar(0));  ///< a = v/|v| of the last update.

  std::uint32_t updates = 0;       ///< Successful updates since reset.
  Status status = Status::kNotInitialised;  ///< Outcome of the last update attempt.
};

/// A motion model whose process noise is the same per-axis block on two
/// consecutive position/velocity/... axes (CA-2D), so Q can be scaled per axis.
template <class M>
concept AxisBlockMotion = MotionModel<M> && requires(const M& m, typename M::Scalar dt) {
  { m.axis_process_noise(dt) } -> std::same_as<typename M::AxisMat>;
  requires M::kAxisDim * 2 == M::kStateDim;
  requires M::Layout::kY == M::Layout::kX + M::kAxisDim;
  requires M::Layout::kVy == M::Layout::kVx + M::kAxisDim;
};

/// A 2D range/bearing sensor with per-channel sigmas (eq. 12 rescales them).
template <class H, class Motion>
concept RangeBearingSensor = MeasurementModelFor<H, Motion> && (H::kMeasDim == 2) && requires(const H& h) {
  { h.sigma_range_m } -> std::convertible_to<typename H::Scalar>;
  { h.sigma_bearing_rad } -> std::convertible_to<typename H::Scalar>;
  requires H::kRange == 0 && H::kBearing == 1;
};

namespace r2aekf {

/// Eq. 11 after clamping the target to [lo, hi]: the scale moves toward the
/// target by at most a factor `up` or `down` per step. With prev in [lo, hi],
/// up >= 1 and down <= 1 the result stays in [lo, hi].
template <class Scalar>
Scalar rate_limited(Scalar target, Scalar prev, Scalar lo, Scalar hi, Scalar up, Scalar down) {
  const Scalar t = target < lo ? lo : (target > hi ? hi : target);
  const Scalar lowest = prev * down;
  const Scalar highest = prev * up;
  const Scalar s = t > lowest ? t : lowest;
  return s < highest ? s : highest;
}

/// Eq. 10: 1 + alpha * max(0, x - (1 + delta)).
template <class Scalar>
Scalar deadband_target(Scalar x, Scalar alpha, Scalar delta) {
  const Scalar excess = x - (Scalar(1) + delta);
  return Scalar(1) + alpha * (excess > Scalar(0) ? excess : Scalar(0));
}

/// Eqs. 17-18 mixing matrix M for Q_k = kron(M, Q1D) from the axial and
/// lateral scales and the unit velocity a = v/|v| (t = [-a_y, a_x]).
/// kDiagonal keeps diag(sQx, sQy) of eq. 17; kFullRotated is
/// sQax a a^T + sQlat t t^T. Without a velocity frame (speed below
/// min_speed_mps) the direction is undefined and M = max(sQax, sQlat) I.
template <class Scalar>
Mat<Scalar, 2, 2> q_mixing(Scalar s_ax, Scalar s_lat, const Vec<Scalar, 2>& a, bool have_frame,
                           R2AekfQForm form) {
  Mat<Scalar, 2, 2> M = Mat<Scalar, 2, 2>::Zero();
  if (!have_frame) {
    const Scalar s = s_ax > s_lat ? s_ax : s_lat;
    M(0, 0) = s;
    M(1, 1) = s;
    return M;
  }
  const Scalar ax = a(0);
  const Scalar ay = a(1);
  // t = [-vy, vx]/|v|: tx = -ay, ty = ax.
  M(0, 0) = ax * ax * s_ax + ay * ay * s_lat;  // eq. 17, sQx
  M(1, 1) = ay * ay * s_ax + ax * ax * s_lat;  // eq. 17, sQy
  if (form == R2AekfQForm::kFullRotated) {
    const Scalar off = ax * ay * (s_ax - s_lat);  // a_x a_y sQax + t_x t_y sQlat
    M(0, 1) = off;
    M(1, 0) = off;
  }
  return M;
}

}  // namespace r2aekf

template <AxisBlockMotion Motion, RangeBearingSensor<Motion> Measurement>
class R2Aekf {
 public:
  using Base = Ekf<Motion, Measurement>;
  using Scalar = typename Base::Scalar;
  static constexpr int kStateDim = Base::kStateDim;
  static constexpr int kMeasDim = Base::kMeasDim;
  using MotionModel = Motion;
  using MeasurementModel = Measurement;
  using Layout = typename Base::Layout;
  using State = typename Base::State;
  using Cov = typename Base::Cov;
  using MeasVec = typename Base::MeasVec;
  using MeasCov = typename Base::MeasCov;
  using Innov = typename Base::Innov;
  using Diagnostics = typename Base::Diagnostics;
  using Config = R2AekfConfig<Scalar>;
  using Adaptation = R2AekfAdaptation<Scalar>;

  R2Aekf() : R2Aekf(Motion{}, Measurement{}, Config{}) {}
  /// @param config must be valid() (programmer error otherwise: KESTREL_ASSERT).
  R2Aekf(const Motion& motion, const Measurement& measurement, const Config& config = Config{})
      : ekf_(motion, measurement), config_(config) {
    KESTREL_ASSERT(config.valid());
  }

  /// Set the state and covariance and restart the adaptation (scales 1).
  /// @return kOk; kNonFinite (filter unchanged).
  [[nodiscard]] Status reset(const State& x, const Cov& P) {
    cache_valid_ = false;
    const Status s = ekf_.reset(x, P);
    if (s == Status::kOk) {
      ad_ = Adaptation{};
      R_applied_ = measurement_noise();
    }
    return s;
  }

  /// Predict by dt seconds with Q_(k-1) of eq. 18 (docs/r2aekf.md step 1).
  /// @return kOk; kNonFinite (filter unchanged).
  [[nodiscard]] Status predict(Scalar dt) {
    cache_valid_ = false;
    Status s;
    if constexpr (Base::kBlockPredict) {
      s = ekf_.predict_axis_mixed(dt, ad_.q_mix);  // kron(M, Q1D) per axis block
    } else {
      s = ekf_.predict(dt, process_noise(dt));
    }
    if (s == Status::kOk) dt_ = dt;
    return s;
  }

  /// Innovation of z with the current R_k (the one the next update starts
  /// from, docs/r2aekf.md step 1). Observably pure: the gate uses it. It remembers
  /// its result so that update() of the same z can reuse it (one object is
  /// not to be used from two threads at once, like any filter here).
  Innov innovation(const MeasVec& z) const {
    cached_ = ekf_.innovation(z, measurement_noise());
    cached_z_ = z;
    cache_valid_ = true;
    return cached_;
  }

  /// One adaptive update, docs/r2aekf.md steps 1-7 (eqs. 7-18).
  /// @return kOk; kNonFinite or kNotPositiveDefinite, with x, P and the
  ///         adaptation unchanged (adaptation().status records it).
  [[nodiscard]] Status update(const MeasVec& z) {
    using T = ScalarTraits<Scalar>;
    constexpr int kR = Measurement::kRange;
    constexpr int kB = Measurement::kBearing;
    const Config& c = config_;
    const bool paper = c.mode == R2AekfMode::kPaper;
    // Through the const accessor: Ekf's mutable measurement() drops its
    // shared linearisation, which the update below reuses.
    const Measurement& meas = std::as_const(ekf_).measurement();

    // Step 1, eq. 7: innovation and S_pre with the previous step's R. The
    // tracker's gate has usually just computed exactly this (innovation(z)
    // on the same state and z): reuse it rather than pay for it twice.
    const MeasCov R_prev = measurement_noise();
    const Innov pre = cache_valid_ && (cached_z_.array() == z.array()).all() ? cached_ : ekf_.innovation(z, R_prev);
    cache_valid_ = false;
    KESTREL_TRY_OR(fail, pre.status);

    Adaptation a = ad_;
    // Step 2, eq. 8: per-channel normalised innovation; n_c = e_c^2.
    a.e(kR) = pre.nu(kR) / T::sqrt(pre.S(kR, kR));
    a.e(kB) = pre.nu(kB) / T::sqrt(pre.S(kB, kB));

    // Step 3, eqs. 9-11. Default mode subtracts the squared mean so a
    // steady bias (manoeuvre lag) does not read as sensor noise.
    const Scalar beta[2] = {c.beta_r, c.beta_b};
    Scalar* const scale[2] = {&a.s_r_range, &a.s_r_bearing};
    for (int ch = 0; ch < 2; ++ch) {
      const Scalar b = beta[ch];
      a.nis_bar(ch) = (Scalar(1) - b) * a.nis_bar(ch) + b * a.e(ch) * a.e(ch);  // eq. 9
      if (paper) {
        a.spread(ch) = a.nis_bar(ch);
      } else {
        a.e_bar(ch) = (Scalar(1) - b) * a.e_bar(ch) + b * a.e(ch);
        a.spread(ch) = a.nis_bar(ch) - a.e_bar(ch) * a.e_bar(ch);
      }
      const Scalar target = r2aekf::deadband_target(a.spread(ch), c.alpha_r, c.delta);         // eq. 10
      *scale[ch] = r2aekf::rate_limited(target, *scale[ch], c.r_min, c.r_max, c.u_r, c.d_r);  // eq. 11
    }

    // Step 4, eq. 12: R_k; S = H P H^T + R_k from S_pre (R is diagonal);
    // robust gating multiplies R_k by rho for this update only.
    const MeasCov R_k = noise_for(a);
    MeasCov S = pre.S;
    S(kR, kR) += R_k(kR, kR) - R_prev(kR, kR);
    S(kB, kB) += R_k(kB, kB) - R_prev(kB, kB);
    // d2 = nu^T S^-1 nu in closed form for the 2x2 S (positive definite iff
    // S_rr > 0 and det > 0).
    const Scalar det = S(kR, kR) * S(kB, kB) - S(kR, kB) * S(kB, kR);
    if (!(S(kR, kR) > Scalar(0)) || !(det > Scalar(0))) return fail(Status::kNotPositiveDefinite);
    a.d2 = (S(kB, kB) * pre.nu(kR) * pre.nu(kR) - Scalar(2) * S(kR, kB) * pre.nu(kR) * pre.nu(kB) +
            S(kR, kR) * pre.nu(kB) * pre.nu(kB)) / det;
    a.robust_gated = a.d2 > c.nis_threshold && c.rho > Scalar(1);
    const MeasCov R_used = a.robust_gated ? MeasCov(R_k * c.rho) : R_k;
    if (a.robust_gated) S += R_k * (c.rho - Scalar(1));

    // The EKF update with the final R.
    const Scalar px = ekf_.x()(Layout::kX);
    const Scalar py = ekf_.x()(Layout::kY);
    KESTREL_TRY_OR(fail, ekf_.update(z, R_used));

    // Step 5: manoeuvre indicators, with the velocity frame of the update.
    const Vec<Scalar, 2> v(ekf_.x()(Layout::kVx), ekf_.x()(Layout::kVy));
    const Scalar speed = T::sqrt(v(0) * v(0) + v(1) * v(1));
    const bool have_frame = speed >= c.min_speed_mps;
    if (have_frame) a.axial_unit = v / speed;
    a.tau = dt_ > Scalar(0) ? T::abs(pre.nu(kB)) / dt_ : Scalar(0);  // eq. 13
    if (paper) {
      // Eq. 14 with tau0 in units of sb/T: tau/tau0 = |nu_b| / (tau0 sb).
      a.phi_lateral = positive(T::abs(pre.nu(kB)) / (c.tau0 * meas.sigma_bearing_rad) - Scalar(1));
      a.phi_axial = positive(T::sqrt(a.nis_bar(kR)) - Scalar(1));  // eq. 15
    } else {
      velocity_frame_indicators(pre.nu, S, px, py, a);
    }

    // Step 6, eq. 16 (the print has phi_ax in both; the text means phi_lat).
    const Scalar phi_lat_used = (paper && c.printed_eq16) ? a.phi_axial : a.phi_lateral;
    a.s_q_axial = r2aekf::rate_limited(Scalar(1) + c.alpha_q_ax * a.phi_axial, a.s_q_axial, c.q_min, c.q_max,
                                       c.u_q, c.d_q);
    a.s_q_lateral = r2aekf::rate_limited(Scalar(1) + c.alpha_q_lat * phi_lat_used, a.s_q_lateral, c.q_min,
                                         c.q_max, c.u_q, c.d_q);
    // Step 7, eqs. 17-18: mixing for Q_k, used by the next prediction.
    a.q_mix = r2aekf::q_mixing(a.s_q_axial, a.s_q_lateral, a.axial_unit, have_frame, c.q_form);

    ++a.updates;
    a.status = Status::kOk;
    ad_ = a;
    R_applied_ = R_used;
    return Status::kOk;
  }

  /// Q_k(dt) of eq. 18: kron(M, Q1D(dt)) with the current mixing M.
  Cov process_noise(Scalar dt) const {
    constexpr int kA = Motion::kAxisDim;
    constexpr int kX = Layout::kX;
    constexpr int kY = Layout::kY;
    const typename Motion::AxisMat Q1 = ekf_.motion().axis_process_noise(dt);
    const Mat<Scalar, 2, 2>& M = ad_.q_mix;
    Cov Q = Cov::Zero();
    Q.template block<kA, kA>(kX, kX) = Q1 * M(0, 0);
    Q.template block<kA, kA>(kY, kY) = Q1 * M(1, 1);
    if (config_.q_form == R2AekfQForm::kFullRotated) {
      Q.template block<kA, kA>(kX, kY) = Q1 * M(0, 1);
      Q.template block<kA, kA>(kY, kX) = Q1 * M(1, 0);
    }
    return Q;
  }

  /// R_k of eq. 12 with the current scales (no rho): the R the next update starts from.
  MeasCov measurement_noise() const { return noise_for(ad_); }
  /// The R the last successful update used (R_k, times rho if robust gating fired).
  const MeasCov& applied_measurement_noise() const { return R_applied_; }

  const State& x() const { return ekf_.x(); }
  const Cov& P() const { return ekf_.P(); }
  /// Scales, indicators and per-channel statistics after the last update.
  const Adaptation& adaptation() const { return ad_; }
  const Config& config() const { return config_; }
  /// The underlying EKF (its diagnostics() describe the last update).
  const Base& ekf() const { return ekf_; }
  const Diagnostics& diagnostics() const { return ekf_.diagnostics(); }
  const Motion& motion() const { return ekf_.motion(); }
  const Measurement& measurement() const { return ekf_.measurement(); }

 private:
  static Scalar positive(Scalar v) { return v > Scalar(0) ? v : Scalar(0); }

  MeasCov noise_for(const Adaptation& a) const {
    const Measurement& m = ekf_.measurement();
    const Scalar sr = a.s_r_range * m.sigma_range_m;
    const Scalar sb = a.s_r_bearing * m.sigma_bearing_rad;
    MeasCov R = MeasCov::Zero();
    R(Measurement::kRange, Measurement::kRange) = sr * sr;
    R(Measurement::kBearing, Measurement::kBearing) = sb * sb;
    return R;
  }

  /// Default-mode step 5: dp = J nu with J = d(x, y)/d(r, b) at the predicted
  /// position, its covariance J S J^T, both in the velocity frame (a, t);
  /// each component normalised by its predicted sigma, squared, EWMA'd, and
  /// phi = max(0, sqrt(mean) - (1 + deltaQ)).
  void velocity_frame_indicators(const MeasVec& nu, const MeasCov& S, Scalar px, Scalar py, Adaptation& a) const {
    using T = ScalarTraits<Scalar>;
    const Config& c = config_;
    const Scalar r = T::sqrt(px * px + py * py);
    Mat<Scalar, 2, 2> J;  // columns: d/dr = (x, y)/r, d/db = (-y, x)
    J << px / r, -py,
         py / r, px;
    // Rows: a^T and t^T, t = [-a_y, a_x].
    Mat<Scalar, 2, 2> Rot;
    Rot << a.axial_unit(0), a.axial_unit(1),
          -a.axial_unit(1), a.axial_unit(0);
    const Mat<Scalar, 2, 2> G = Rot * J;
    const Vec<Scalar, 2> d = G * nu;
    const Mat<Scalar, 2, 2> C = G * S * G.transpose();
    const Scalar b = c.beta_q;
    if (C(0, 0) > Scalar(0) && C(1, 1) > Scalar(0)) {
      a.w_axial = (Scalar(1) - b) * a.w_axial + b * d(0) * d(0) / C(0, 0);
      a.w_lateral = (Scalar(1) - b) * a.w_lateral + b * d(1) * d(1) / C(1, 1);
    }
    a.phi_axial = positive(T::sqrt(a.w_axial) - (Scalar(1) + c.delta_q));
    a.phi_lateral = positive(T::sqrt(a.w_lateral) - (Scalar(1) + c.delta_q));
  }

  Status fail(Status s) {
    ad_.status = s;
    return s;
  }

  Base ekf_;
  Config config_;
  Adaptation ad_{};
  MeasCov R_applied_ = MeasCov::Zero();
  Scalar dt_ = Scalar(0);  ///< T of the last prediction, s (eq. 13).
  // The last innovation() result, valid until x, P or R change (any
  // predict, update or reset): update() of the same z reuses it.
  mutable Innov cached_{};
  mutable MeasVec cached_z_ = MeasVec::Zero();
  mutable bool cache_valid_ = false;
};

/// Paper 000's R2-AEKF on CA-2D with the polar radar.
template <class Scalar>
using R2AekfCa = R2Aekf<ConstantAcceleration2D<Scalar>, PolarRadar<ConstantAcceleration2D<Scalar>>>;

}  // namespace kestrel
