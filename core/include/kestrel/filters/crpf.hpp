// SPDX-License-Identifier: Apache-2.0
// Cost-reference particle filter (paper 001 section 3.4, eq. 4-8 and table
// 6, after Miguez, Bugallo and Djuric 2004, "A new class of particle filters
// for random dynamic systems with unknown statistics", and Xu 2006). It needs
// scales, not noise distributions: particles carry a cost (eq. 5) instead of
// a likelihood weight, and are selected by their risk (eq. 6) through the
// PMF of eq. 8 and systematic resampling. kParticles is a template parameter
// and the filter owns a seeded PRNG (math/prng.hpp), so the same seed gives
// the same bits. update() writes into a second particle buffer and swaps only
// when every particle and cost is finite, restoring the PRNG otherwise
// (kNonFinite; kNotPositiveDefinite for a scale <= 0 in R or an indefinite P0
// at reset). The steps and the choices beyond the paper: docs/filters.md,
// "CRPF" and "Choices beyond the paper".
#pragma once

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <utility>

#include "kestrel/assert.hpp"
#include "kestrel/filters/innovation.hpp"
#include "kestrel/math/cholesky_update.hpp"
#include "kestrel/math/eigen.hpp"
#include "kestrel/math/finite.hpp"
#include "kestrel/math/positive_definite.hpp"
#include "kestrel/math/prng.hpp"
#include "kestrel/models/concepts.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"

namespace kestrel {

/// CRPF tuning; the defaults are those of docs/filters.md.
template <class S>
struct CrpfConfig {
  S lambda = lit<S>(0.8);      ///< Forgetting factor of the cost, (0, 1].
  int beta = 2;                ///< PMF exponent, integer 1..8.
  S delta = S(1);              ///< PMF offset, normalised-cost units (> 0).
  S kick_sigma = S(2);         ///< sj, sigma of the acceleration kick, m/s^2 (models with noise_gain()).
  std::uint64_t seed = 0;      ///< PRNG seed.
  /// Refuse a reset, predict or update whose cloud covariance (what P()
  /// hands a tracker to gate with and report) is not positive definite in
  /// this scalar. A cloud selected down to a few ancestors and kicked in a
  /// subspace (CV-2D's G a) is singular, so paper 001's evaluation, which
  /// scores the estimate alone, turns this off (MC-001).
  bool refuse_indefinite = true;
};

/// A motion model that says how a unit noise input enters the state.
template <class M>
concept HasNoiseGain = requires(const M& m, typename M::Scalar dt) {
  { m.noise_gain(dt) };
};

/// A measurement model that prepares the residuals of many particles
/// against one z about a reference state (PolarRadar: the bearing as a
/// small angle from the reference's, not an atan2 per particle).
template <class H>
concept HasParticleResiduals = requires(const H& h, const typename H::Measurement& z, const typename H::State& x) {
  { h.particle_residuals(z, x)(x) } -> std::same_as<typename H::Measurement>;
};

namespace detail {
template <class Motion>
constexpr int kick_dim() {
  if constexpr (HasNoiseGain<Motion>) {
    return decltype(std::declval<const Motion&>().noise_gain(typename Motion::Scalar{}))::ColsAtCompileTime;
  } else {
    return Motion::kStateDim;
  }
}
}  // namespace detail

template <MotionModel Motion, MeasurementModelFor<Motion> Measurement, int kParticles>
class Crpf {
 public:
  static_assert(kParticles >= 2, "a particle filter needs at least two particles");
  using Scalar = typename Motion::Scalar;
  static constexpr int kStateDim = Motion::kStateDim;
  static constexpr int kMeasDim = Measurement::kMeasDim;
  static constexpr int kParticleCount = kParticles;
  static constexpr int kKickDim = detail::kick_dim<Motion>();
  static constexpr int kMaxBeta = 8;
  using MotionModel = Motion;
  using MeasurementModel = Measurement;
  using Layout = typename Motion::Layout;
  using State = typename Motion::State;
  using Cov = typename Motion::Cov;
  using MeasVec = typename Measurement::Measurement;
  using MeasCov = typename Measurement::NoiseCov;
  using Innov = Innovation<Scalar, kMeasDim>;
  using Diagnostics = FusionDiagnostics<Scalar, kMeasDim>;
  using Config = CrpfConfig<Scalar>;
  using KickFactor = Mat<Scalar, kStateDim, kKickDim>;

  Crpf() : Crpf(Motion{}, Measurement{}) {}
  Crpf(const Motion& motion, const Measurement& measurement, const Config& params = Config{})
      : motion_(motion), measurement_(measurement), params_(params), normal_(params.seed) {
    KESTREL_ASSERT(params.beta >= 1 && params.beta <= kMaxBeta);
    KESTREL_ASSERT(params.delta > Scalar(0));
    x_hat_ = State::Zero();
    P_ = Cov::Identity();
    diag_ = Diagnostics{};
    for (int i = 0; i < kParticles; ++i) {
      xs_[0][i] = State::Zero();
      xs_[1][i] = State::Zero();
      xp_[i] = State::Zero();
      cost_[0][i] = Scalar(0);
      cost_[1][i] = Scalar(0);
      w_[i] = Scalar(1) / Scalar(kParticles);
      cum_[i] = Scalar(0);
    }
  }

  /// Restart the PRNG stream (e.g. one seed per Monte Carlo run).
  void seed(std::uint64_t seed) {
    params_.seed = seed;
    normal_.seed(seed);
  }

  /// Draw the initial cloud x_i ~ N(x, P) with zero costs.
  /// @return kOk; kNonFinite; kNotPositiveDefinite (P indefinite, or the
  ///         drawn cloud's covariance not positive definite). Unchanged on error.
  [[nodiscard]] Status reset(const State& x, const Cov& P) {
    if (!all_finite(x) || !all_finite(P)) return Status::kNonFinite;
    Cov L;
    KESTREL_TRY(cholesky_semidefinite<Scalar, kStateDim>(symmetrised(P), L));
    const NormalGenerator<Scalar> normal_before = normal_;
    State* next = xs_[1 - cur_];
    for (int i = 0; i < kParticles; ++i) {
      State w;
      for (int k = 0; k < kStateDim; ++k) w(k) = normal_();
      next[i] = x + L * w;
      cum_[i] = Scalar(1) / Scalar(kParticles);
    }
    State x_hat;
    Cov P_cloud;
    moments(next, cum_, KickFactor::Zero(), x_hat, P_cloud);
    if (const Status cloud = cloud_status(x_hat, P_cloud); cloud != Status::kOk) {
      normal_ = normal_before;
      return cloud;
    }
    cur_ = 1 - cur_;
    for (int i = 0; i < kParticles; ++i) {
      cost_[cost_cur_][i] = Scalar(0);
      w_[i] = cum_[i];
    }
    pending_dt_ = Scalar(0);
    predicted_ = false;
    x_hat_ = x_hat;
    P_ = P_cloud;
    return Status::kOk;
  }

  /// Noise-free prediction of every particle over dt seconds (accumulated
  /// with any earlier predict() not yet followed by an update()); x() and
  /// P() become the predicted cloud's mean and covariance plus the kick's.
  /// @return kOk; kNonFinite; kNotPositiveDefinite (that covariance is not
  ///         positive definite in this scalar). x() and P() unchanged on error.
  [[nodiscard]] Status predict(Scalar dt) {
    if (!ScalarTraits<Scalar>::is_finite(dt)) return Status::kNonFinite;
    const Scalar total_dt = pending_dt_ + dt;
    const KickFactor L = kick_factor(total_dt);
    if (!all_finite(L)) return Status::kNonFinite;
    const State* x = xs_[cur_];
    for (int i = 0; i < kParticles; ++i) xp_[i] = motion_.propagate(x[i], total_dt);
    State x_hat;
    Cov P;
    moments(xp_, w_, L, x_hat, P);
    const Status st = cloud_status(x_hat, P);
    if (st != Status::kOk) {
      // xp_ is scratch: the next update predicts again from the cloud.
      predicted_ = false;
      return st;
    }
    x_hat_ = x_hat;
    P_ = P;
    pending_dt_ = total_dt;
    predicted_ = true;
    return Status::kOk;
  }

  /// Innovation of z against the current estimate, linearised at x() with
  /// the model's R (see the header note). Pure.
  Innov innovation(const MeasVec& z) const { return innovation(z, measurement_.noise()); }

  /// Innovation with an explicit R.
  Innov innovation(const MeasVec& z, const MeasCov& R) const {
    Innov out{MeasVec::Zero(), MeasCov::Zero(), Scalar(0), Status::kOk};
    if (!all_finite(z) || !all_finite(R)) {
      out.status = Status::kNonFinite;
      return out;
    }
    const auto H = measurement_.jacobian(x_hat_);
    out.nu = measurement_.residual(z, measurement_.predict(x_hat_));
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

  /// One CRPF step with z: risk, selection, propagation, cost, estimate.
  /// @return kOk; kNonFinite; kNotPositiveDefinite (filter unchanged).
  [[nodiscard]] Status update(const MeasVec& z) { return update(z, measurement_.noise()); }

  /// Update with the channel scales s_c = sqrt(R_cc) of an explicit R.
  /// @return kOk; kNonFinite; kNotPositiveDefinite (filter unchanged).
  [[nodiscard]] Status update(const MeasVec& z, const MeasCov& R) {
    using T = ScalarTraits<Scalar>;
    diag_.fused = false;
    if (!all_finite(z) || !all_finite(R)) return fail(Status::kNonFinite);
    MeasVec inv_scale;
    for (int c = 0; c < kMeasDim; ++c) {
      if (!(R(c, c) > Scalar(0))) return fail(Status::kNotPositiveDefinite);
      inv_scale(c) = Scalar(1) / T::sqrt(R(c, c));
    }
    if (!predicted_) {
      // Update without a predict: dt = 0, the prediction is the cloud itself.
      KESTREL_TRY_OR(fail, predict(Scalar(0)));
    }
    const Innov in = innovation(z, R);  // diagnostics: against the predicted estimate
    const KickFactor L = kick_factor(pending_dt_);
    const Scalar lambda = params_.lambda;
    const Scalar* cost = cost_[cost_cur_];

    // 2. Risk of every noise-free prediction; 3. selection PMF as a cumulative sum.
    Scalar min_risk = T::max_value();
    bool any_finite = false;
    const auto residual_of = particle_residuals(z);
    incremental_costs(xp_, residual_of, inv_scale, cum_);
    for (int i = 0; i < kParticles; ++i) {
      const Scalar r = lambda * cost[i] + cum_[i];
      cum_[i] = r;
      if (T::is_finite(r)) {
        any_finite = true;
        if (r < min_risk) min_risk = r;
      }
    }
    if (!any_finite) return fail(Status::kNonFinite);
    Scalar total = Scalar(0);
    for (int i = 0; i < kParticles; ++i) {
      const Scalar r = cum_[i];
      total += T::is_finite(r) ? pmf(r - min_risk) : Scalar(0);
      cum_[i] = total;
    }

    // 4. Systematic resampling, 5. propagation, 6. cost, into the spare buffer.
    const NormalGenerator<Scalar> normal_before = normal_;
    State* next = xs_[1 - cur_];
    Scalar* next_cost = cost_[1 - cost_cur_];
    const Scalar u0 = normal_.uniform01();
    const Scalar step = total / Scalar(kParticles);
    int j = 0;
    for (int i = 0; i < kParticles; ++i) {
      const Scalar target = (u0 + Scalar(i)) * step;
      while (j < kParticles - 1 && cum_[j] <= target) ++j;  // j only grows: N steps in all
      Vec<Scalar, kKickDim> a;
      for (int k = 0; k < kKickDim; ++k) a(k) = normal_();
      next[i] = xp_[j] + L * a;
      next_cost[i] = lambda * cost[j];
    }
    // dC of the new particles after the resampling loop (see
    // incremental_costs), into cum_, which the resampling no longer needs.
    incremental_costs(next, residual_of, inv_scale, cum_);
    for (int i = 0; i < kParticles; ++i) next_cost[i] += cum_[i];

    // 7. Estimate weighted by the updated cost (weights into the scratch
    // array until the commit). A non-finite particle or cost makes the
    // estimate non-finite (every weight is > 0), so one check covers them.
    Scalar min_cost = T::max_value();
    for (int i = 0; i < kParticles; ++i) {
      if (next_cost[i] < min_cost) min_cost = next_cost[i];
    }
    Scalar wsum = Scalar(0);
    for (int i = 0; i < kParticles; ++i) {
      cum_[i] = pmf(next_cost[i] - min_cost);
      wsum += cum_[i];
    }
    const Scalar inv_wsum = Scalar(1) / wsum;
    for (int i = 0; i < kParticles; ++i) cum_[i] *= inv_wsum;
    State x_hat;
    Cov P;
    moments(next, cum_, KickFactor::Zero(), x_hat, P);
    if (!T::is_finite(min_cost) || !T::is_finite(wsum)) {
      normal_ = normal_before;
      return fail(Status::kNonFinite);
    }
    // The cloud's covariance is what the tracker gates with and reports: a
    // cloud too narrow for it to be positive definite in this scalar is
    // refused like an EKF update that would lose positive definiteness.
    if (const Status st = cloud_status(x_hat, P); st != Status::kOk) {
      normal_ = normal_before;
      return fail(st);
    }
    for (int i = 0; i < kParticles; ++i) w_[i] = cum_[i];
    x_hat_ = x_hat;
    P_ = P;
    cur_ = 1 - cur_;
    cost_cur_ = 1 - cost_cur_;
    pending_dt_ = Scalar(0);
    predicted_ = false;

    diag_.fused_all(in.nu, in.S.diagonal(), in.d2);
    return Status::kOk;
  }

  /// Weighted mean of the cloud (after update: by the updated cost).
  const State& x() const { return x_hat_; }
  /// Weighted covariance of the cloud (after predict: plus the kick's).
  const Cov& P() const { return P_; }
  /// Particle i of the current cloud (after the last update or reset).
  const State& particle(int i) const { return xs_[cur_][i]; }
  /// Cost C_t of particle i.
  Scalar cost(int i) const { return cost_[cost_cur_][i]; }
  /// Normalised estimation weight of particle i.
  Scalar weight(int i) const { return w_[i]; }
  const Motion& motion() const { return motion_; }
  const Measurement& measurement() const { return measurement_; }
  Motion& motion() { return motion_; }
  Measurement& measurement() { return measurement_; }
  const Config& params() const { return params_; }
  /// Diagnostics of the last update attempt (innovation linearised, see above).
  const Diagnostics& diagnostics() const { return diag_; }

 private:
  /// What gives residual(z, h(x)) of a particle x, for the risk and the
  /// cost: the model's particle_residuals() prepared about the predicted
  /// mean x_hat_ when it has them (HasParticleResiduals), residual(z,
  /// predict(x)) otherwise.
  auto particle_residuals(const MeasVec& z) const {
    if constexpr (HasParticleResiduals<Measurement>) {
      return measurement_.particle_residuals(z, x_hat_);
    } else {
      return [this, z](const State& x) { return measurement_.residual(z, measurement_.predict(x)); };
    }
  }

  /// dc[i] = dC(x[i] | z) = sum_c (residual_c(z, h(x[i])) / s_c)^2 (eqs.
  /// 5-6) for every particle, in a loop of its own: no data-dependent
  /// branch (resampling pointer, minimum) between the h(x) of successive
  /// particles, so their independent evaluations overlap in the pipeline.
  /// Flattened: clang would otherwise leave the residual a call per particle.
  template <class ResidualOf>
  [[gnu::flatten]] void incremental_costs(const State* x, const ResidualOf& residual_of, const MeasVec& inv_scale,
                                          Scalar* dc) const {
    for (int i = 0; i < kParticles; ++i) dc[i] = residual_of(x[i]).cwiseProduct(inv_scale).squaredNorm();
  }

  /// (d + delta)^(-beta) for d >= 0, integer beta (bounded loop).
  Scalar pmf(Scalar d) const {
    const Scalar base = d + params_.delta;
    if (params_.beta == 2) return Scalar(1) / (base * base);  // the default: the loop below, unrolled
    Scalar p = base;
    for (int k = 1; k < kMaxBeta; ++k) {
      if (k >= params_.beta) break;
      p *= base;
    }
    return Scalar(1) / p;
  }

  /// Square root of the kick covariance over dt (see the header note).
  KickFactor kick_factor(Scalar dt) const {
    if constexpr (HasNoiseGain<Motion>) {
      return motion_.noise_gain(dt) * params_.kick_sigma;
    } else {
      Cov L;
      if (cholesky_semidefinite<Scalar, kStateDim>(motion_.process_noise(dt), L) != Status::kOk) {
        L.setConstant(ScalarTraits<Scalar>::max_value() * Scalar(2));  // caught by all_finite
      }
      return L;
    }
  }

  /// m = sum w_i x_i, P = sum w_i (x_i - m)(x_i - m)^T + L L^T (weights sum
  /// to 1). One pass about the reference x_0 (a member of the cloud, so the
  /// shifted sums lose no significant digits); P is symmetrised.
  void moments(const State* x, const Scalar* w, const KickFactor& L, State& m, Cov& P) const {
    const State ref = x[0];
    State s1 = State::Zero();
    Cov s2 = Cov::Zero();
    for (int i = 0; i < kParticles; ++i) {
      const State d = x[i] - ref;
      const State wd = d * w[i];
      s1 += wd;
      s2.noalias() += wd * d.transpose();
    }
    P = symmetrised(s2 - s1 * s1.transpose() + L * L.transpose());
    m = ref + s1;
  }

  /// state_status of the cloud's moments, or finiteness alone when the
  /// params do not ask for positive definiteness.
  Status cloud_status(const State& m, const Cov& P) const {
    if (params_.refuse_indefinite) return state_status(m, P);
    return all_finite(m) && all_finite(P) ? Status::kOk : Status::kNonFinite;
  }

  Status fail(Status s) {
    diag_.status = s;
    return s;
  }

  Motion motion_;
  Measurement measurement_;
  Config params_;
  NormalGenerator<Scalar> normal_;
  static constexpr std::size_t kSize = static_cast<std::size_t>(kParticles);
  State xs_[2][kSize];   ///< Double-buffered cloud; xs_[cur_] is current.
  State xp_[kSize];      ///< Noise-free predictions f(x_i, pending_dt_).
  Scalar cost_[2][kSize];
  Scalar w_[kSize];      ///< Estimation weights of the current cloud.
  Scalar cum_[kSize];    ///< Scratch of update(): dC, risks, their cumulative PMF, dC, weights.
  int cur_ = 0;
  int cost_cur_ = 0;
  Scalar pending_dt_ = Scalar(0);
  bool predicted_ = false;
  State x_hat_;
  Cov P_;
  Diagnostics diag_;
};

}  // namespace kestrel
