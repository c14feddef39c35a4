// SPDX-License-Identifier: Apache-2.0
// Extended Kalman filter on fixed-size storage (paper 000 section 2-1 and
// paper 001 section 2); with a linear motion and measurement model it is
// exactly the linear Kalman filter. Every operation computes into locals and
// commits only on success: kNonFinite or kNotPositiveDefinite (a failed
// Cholesky of S, or a P that math/positive_definite.hpp refuses) leave x and
// P unchanged. The update form is chosen at compile time (kForm): the batch
// Joseph form, or the sequential whitened channels a fixed-point scalar needs;
// models that expose structure (filters/structure.hpp) take P - U U^T through
// the Cholesky factor of S instead. The explicit-Q/R and channel-subset
// (paper 003) overloads are what the adaptive and channel-gated filters build
// on. Forms and why: docs/filters.md, "EKF: update forms and model
// structure"; docs/performance.md, "Update form".
#pragma once

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "kestrel/filters/innovation.hpp"
#include "kestrel/filters/structure.hpp"
#include "kestrel/math/eigen.hpp"
#include "kestrel/math/finite.hpp"
#include "kestrel/math/positive_definite.hpp"
#include "kestrel/models/concepts.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"

namespace kestrel {

/// How Ekf folds a measurement in (equal results up to round-off).
enum class EkfUpdateForm : std::uint8_t {
  kBatch,               ///< Cholesky of S; Joseph form (dense) or P - U U^T (structured).
  kSequentialWhitened,  ///< Whitened scalar channel updates, every divisor >= 1.
};

/// Sequential whitened for fixed point (S^-1 is out of its range), batch for
/// float and double.
template <class Scalar>
inline constexpr EkfUpdateForm kDefaultEkfUpdateForm =
    ScalarTraits<Scalar>::kIsFixedPoint ? EkfUpdateForm::kSequentialWhitened : EkfUpdateForm::kBatch;

template <MotionModel Motion, MeasurementModelFor<Motion> Measurement,
          EkfUpdateForm kForm = kDefaultEkfUpdateForm<typename Motion::Scalar>>
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
  using Jacobian = Mat<Scalar, kMeasDim, kStateDim>;
  static constexpr EkfUpdateForm kUpdateForm = kForm;
  static constexpr ChannelMask kAllChannels = all_channels(kMeasDim);
  /// Model structure in use (structure.hpp), in every scalar.
  static constexpr bool kBlockPredict = BlockDiagonalMotion<Motion>;
  static constexpr bool kSparseUpdate = SparseJacobianMeasurement<Measurement>;
  /// The sparse path of the sequential whitened form (header comment).
  static constexpr bool kWhitenedSparse = kSparseUpdate && kForm == EkfUpdateForm::kSequentialWhitened;
  using Innov = Innovation<Scalar, kMeasDim>;
  using Diagnostics = FusionDiagnostics<Scalar, kMeasDim>;

  Ekf() : Ekf(Motion{}, Measurement{}) {}
  Ekf(const Motion& motion, const Measurement& measurement)
      : motion_(motion), measurement_(measurement), x_(State::Zero()), P_(Cov::Identity()) {
    diag_ = Diagnostics{};
  }

  /// Set the state and covariance.
  /// @return kOk; kNonFinite if any entry is NaN/Inf, kNotPositiveDefinite
  ///         if P is not (filter unchanged in both cases).
  [[nodiscard]] Status reset(const State& x, const Cov& P) {
    if (!all_finite(x) || !all_finite(P)) return Status::kNonFinite;
    const Cov Ps = symmetrised(P);
    KESTREL_TRY(state_status(x, Ps));
    x_ = x;
    P_ = Ps;
    invalidate_linearisation();
    return Status::kOk;
  }

  /// Predict by dt seconds with the model's process noise Q(dt).
  /// @return kOk; kNonFinite or kNotPositiveDefinite (filter unchanged).
  [[nodiscard]] Status predict(Scalar dt) { return predict_checked<true>(dt); }

  /// predict(dt) committed without its covariance check, for a caller that
  /// checks P once per frame (Tracker, VerifiesPredictionLater): every update
  /// commits P+ = P - K S K^T with S positive definite, so P+ passes its
  /// check only if the predicted P does (to rounding), and a P no update
  /// follows is checked by verify_prediction(). update_pda(), whose P+ is
  /// not below P, checks P first.
  /// @return kOk (a non-finite or indefinite result is found later).
  [[nodiscard]] Status predict_unverified(Scalar dt) { return predict_checked<false>(dt); }

  /// The check predict() makes, of the current x and P.
  /// @return kOk; kNonFinite or kNotPositiveDefinite.
  [[nodiscard]] Status verify_prediction() const { return state_status(x_, P_); }

  /// Predict by dt seconds with an explicit process noise Q (adaptive filters).
  /// @return kOk; kNonFinite or kNotPositiveDefinite (filter unchanged).
  [[nodiscard]] Status predict(Scalar dt, const Cov& Q) {
    if constexpr (kBlockPredict) {
      Cov P = structure::transform_covariance(motion_, P_, dt);
      structure::add_symmetrised(P, Q);
      return commit_prediction(motion_.propagate(x_, dt), P);
    } else {
      const Cov F = motion_.jacobian(x_, dt);
      return commit_prediction(motion_.propagate(x_, dt), symmetrised(F * P_ * F.transpose() + Q));
    }
  }

  /// Predict by dt seconds with the process noise kron(M, Q1(dt)): axis
  /// block (i, j) of Q is M(i, j) times the model's per-axis Q1 (per-axis
  /// shaping of adaptive filters, R2-AEKF eq. 18), added per axis block.
  /// Block-diagonal motion models only (the dense path builds the full Q
  /// and calls predict(dt, Q)).
  /// @return kOk; kNonFinite (filter unchanged).
  template <class M = Motion>
    requires kBlockPredict && std::same_as<M, Motion>
  [[nodiscard]] Status predict_axis_mixed(Scalar dt,
                                          const Mat<Scalar, M::kStateDim / M::kAxisDim, M::kStateDim / M::kAxisDim>& mix) {
    if (!all_finite(mix)) return Status::kNonFinite;
    Cov P = structure::transform_covariance(motion_, P_, dt);
    structure::add_mixed_process_noise(motion_, P, dt, mix);
    return commit_prediction(motion_.propagate(x_, dt), P);
  }

  /// Innovation of z against the current (predicted) state with the model's R.
  /// Pure: the gate uses it before deciding to update. On the structured
  /// batch path S and its factor come from the shared linearisation, so
  /// each further plot costs its residual and one forward substitution.
  Innov innovation(const MeasVec& z) const {
    if constexpr (kSparseUpdate) {
      Innov out{MeasVec::Zero(), MeasCov::Zero(), Scalar(0), Status::kOk};
      if (!all_finite(z)) {
        out.status = Status::kNonFinite;
        return out;
      }
      const auto& lin = factored_linearisation();
      out.nu = measurement_.residual(z, lin.z_hat);
      out.S = lin.S;
      if (lin.factor_status == Status::kNonFinite || !all_finite(out.nu)) {
        out.status = Status::kNonFinite;
      } else if (lin.factor_status != Status::kOk) {
        out.status = lin.factor_status;
      } else {
        out.d2 = whitened_residual(lin, out.nu).squaredNorm();
      }
      return out;
    } else {
      return innovation(z, measurement_.noise());
    }
  }

  /// innovation(z) of a plot whose distance was taken from this state's
  /// predicted_measurement() (the plot a track takes after its gate): the
  /// same nu, S, d2 and status, without whitening nu a second time.
  template <bool kEnabled = kSparseUpdate>
    requires kEnabled
  Innov innovation(const MeasVec& z, const PlotDistance<Scalar>& d) const {
    if (d.status != Status::kOk) return innovation(z);
    const auto& lin = factored_linearisation();
    return Innov{measurement_.residual(z, lin.z_hat), lin.S, d.d2, Status::kOk};
  }

  /// What a plot's distance needs besides h(x), per form: the lower factor
  /// L of S (nu -> L^-1 nu), or the factors of R and of the whitened S_w
  /// with their reciprocal diagonals (nu -> Ls^-1 Lr^-1 nu, no division).
  struct BatchFactor {
    MeasCov L;
    MeasVec whiten(const MeasVec& nu) const { return structure::forward_substitute(L, nu); }
  };
  struct WhitenedFactor {
    MeasCov Lr;
    MeasVec inv_lr;
    MeasCov Ls;
    MeasVec inv_ls;
    MeasVec whiten(const MeasVec& nu) const {
      return structure::forward_substitute_reciprocal(Ls, inv_ls, structure::forward_substitute_reciprocal(Lr, inv_lr, nu));
    }
  };
  using FactorOfS = std::conditional_t<kWhitenedSparse, WhitenedFactor, BatchFactor>;

  /// What every plot is measured against until x or P changes: h(x) and
  /// the factor of S = H P H^T + R (structured paths). A gate takes it
  /// once per track and frame; each plot then costs its residual and one
  /// forward substitution. A snapshot: it reads the filter's measurement
  /// model, so it lives no longer than the filter.
  class PredictedMeasurement {
   public:
    /// nu^T S^-1 nu of z with its status, equal to innovation(z)'s d2 and
    /// status at the state the snapshot was taken.
    PlotDistance<Scalar> distance(const MeasVec& z) const {
      if (!all_finite(z)) return {Scalar(0), Status::kNonFinite};
      const MeasVec nu = measurement_->residual(z, z_hat_);
      if (status_ == Status::kNonFinite || !all_finite(nu)) return {Scalar(0), Status::kNonFinite};
      if (status_ != Status::kOk) return {Scalar(0), status_};
      return {factor_.whiten(nu).squaredNorm(), Status::kOk};
    }

   private:
    friend class Ekf;
    PredictedMeasurement(const Measurement& h, const MeasVec& z_hat, const FactorOfS& f, Status s)
        : measurement_(&h), z_hat_(z_hat), factor_(f), status_(s) {}
    const Measurement* measurement_;
    MeasVec z_hat_;
    FactorOfS factor_;
    Status status_;
  };

  template <bool kEnabled = kSparseUpdate>
    requires kEnabled
  PredictedMeasurement predicted_measurement() const {
    const auto& lin = factored_linearisation();
    return PredictedMeasurement(measurement_, lin.z_hat, factor_of(lin), lin.factor_status);
  }

  /// Innovation of z with an explicit measurement noise R.
  Innov innovation(const MeasVec& z, const MeasCov& R) const {
    Innov out{MeasVec::Zero(), MeasCov::Zero(), Scalar(0), Status::kOk};
    if (!all_finite(z) || !all_finite(R)) {
      out.status = Status::kNonFinite;
      return out;
    }
    if constexpr (kSparseUpdate) {
      const auto& lin = linearisation();
      out.nu = measurement_.residual(z, lin.z_hat);
      out.S = lin.HPHt;
      structure::add_symmetrised(out.S, R);
      if (!all_finite(lin.J.Hc) || !all_finite(out.nu) || !all_finite(out.S)) {
        out.status = Status::kNonFinite;
      } else if constexpr (kWhitenedSparse) {
        WhitenedFactor f;
        auto Jw = lin.J;  // Hw, written by whitened_factor_for()
        out.status = whitened_factor_for(lin.J, R, f, Jw);
        if (out.status == Status::kOk) out.d2 = f.whiten(out.nu).squaredNorm();
      } else {
        if (!structure::nis(out.S, out.nu, out.d2)) out.status = Status::kNotPositiveDefinite;
      }
      return out;
    }
    const auto H = measurement_.jacobian(x_);
    out.nu = measurement_.residual(z, measurement_.predict(x_));
    out.S = symmetrised(H * P_ * H.transpose() + R);
    if (!all_finite(H) || !all_finite(out.nu) || !all_finite(out.S)) {
      out.status = Status::kNonFinite;
      return out;
    }
    if constexpr (kForm == EkfUpdateForm::kSequentialWhitened) {
      if (!whitened_nis(H, out.nu, R, out.d2)) out.status = Status::kNotPositiveDefinite;
    } else {
      const Eigen::LLT<MeasCov> llt(out.S);
      if (llt.info() != Eigen::Success) {
        out.status = Status::kNotPositiveDefinite;
        return out;
      }
      out.d2 = out.nu.dot(llt.solve(out.nu));
    }
    return out;
  }

  /// Update with z and the model's R.
  /// @return kOk; kNonFinite or kNotPositiveDefinite (filter unchanged).
  [[nodiscard]] Status update(const MeasVec& z) {
    if constexpr (kSparseUpdate) {
      diag_.fused = false;
      if (!all_finite(z)) return fail(Status::kNonFinite);
      const auto& lin = factored_linearisation();
      const MeasVec nu = measurement_.residual(z, lin.z_hat);
      if (lin.factor_status == Status::kNonFinite || !all_finite(nu)) return fail(Status::kNonFinite);
      KESTREL_TRY_OR(fail, lin.factor_status);
      if constexpr (kWhitenedSparse) {
        return fold_in_whitened(nu, lin.S, lin.Jw, factor_of(lin));
      } else {
        return fold_in(nu, lin.S, lin.L);
      }
    } else {
      return update(z, measurement_.noise());
    }
  }

  /// update(z) given in = innovation(z) taken at this state (the plot a
  /// tracker's gate passed): the residual is not formed again. An `in` of
  /// another state or plot gives a wrong update, not a refused one.
  /// @return as update(z); a status of `in` other than kOk, as is.
  template <bool kEnabled = kSparseUpdate>
    requires kEnabled
  [[nodiscard]] Status update_innovation(const Innov& in) {
    diag_.fused = false;
    if (in.status != Status::kOk) return fail(in.status);
    const auto& lin = factored_linearisation();
    KESTREL_TRY_OR(fail, lin.factor_status);
    if constexpr (kWhitenedSparse) {
      return fold_in_whitened(in.nu, lin.S, lin.Jw, factor_of(lin));
    } else {
      return fold_in(in.nu, lin.S, lin.L);
    }
  }

  /// Innovation of z with the model's R scaled by `scale` (lambda R: the
  /// adaptive noise of association/adaptive_noise.hpp). Pure.
  /// @param scale lambda, > 0 and finite (status kOutOfRange or kNonFinite otherwise).
  Innov innovation_scaled(const MeasVec& z, Scalar scale) const {
    if (!ScalarTraits<Scalar>::is_finite(scale)) return Innov{MeasVec::Zero(), MeasCov::Zero(), Scalar(0), Status::kNonFinite};
    if (!(scale > Scalar(0))) return Innov{MeasVec::Zero(), MeasCov::Zero(), Scalar(0), Status::kOutOfRange};
    return innovation(z, MeasCov(scale * measurement_.noise()));
  }

  /// Update with z and the model's R scaled by `scale` (lambda R).
  /// @param scale lambda, > 0 and finite.
  /// @return kOk; kOutOfRange (scale not > 0); kNonFinite or
  ///         kNotPositiveDefinite (filter unchanged).
  [[nodiscard]] Status update_scaled(const MeasVec& z, Scalar scale) {
    if (!ScalarTraits<Scalar>::is_finite(scale)) return fail(Status::kNonFinite);
    if (!(scale > Scalar(0))) return fail(Status::kOutOfRange);
    return update(z, MeasCov(scale * measurement_.noise()));
  }

  /// Update with z and an explicit R (see kForm and the header comment).
  /// @return kOk; kNonFinite or kNotPositiveDefinite (filter unchanged).
  [[nodiscard]] Status update(const MeasVec& z, const MeasCov& R) {
    if constexpr (kForm == EkfUpdateForm::kSequentialWhitened) {
      return update_sequential(z, R);
    } else {
      return update_batch(z, R);
    }
  }

  /// Update with only the channels in `keep` of z (bit i: channel i) and an
  /// explicit R. Every other channel is removed, not zeroed: its row of H
  /// and entry of nu are zero and its row and column of R, so of S, a unit
  /// vector, so S is block-diagonal [S_kept, 0; 0, I] up to a permutation,
  /// the gain has an exactly zero column for it and the update equals one
  /// with the kept channels only (paper 003 drops gated channels this way;
  /// filters/channel_gated_ekf.hpp). Channels outside `keep` are not read
  /// (NaN allowed). The dense arithmetic of kForm (batch Joseph form, or
  /// sequential whitened, where a removed channel is a no-op), whatever
  /// structure the models expose.
  /// @return kOk (an empty `keep` fuses nothing and changes nothing);
  ///         kNonFinite or kNotPositiveDefinite (filter unchanged).
  [[nodiscard]] Status update(const MeasVec& z, const MeasCov& R, ChannelMask keep) {
    return update(linearise_channels(z, R, keep));
  }

  /// Innovation of the channels in `keep` of z with an explicit R, the
  /// others removed as in update(z, R, keep) (nu_i 0, a unit row and column
  /// of S), so d2 is over the kept channels. Pure.
  Innov innovation(const MeasVec& z, const MeasCov& R, ChannelMask keep) const {
    return innovation(linearise_channels(z, R, keep));
  }

  /// nu, H, R and S = H P H^T + R at the current state with every channel
  /// outside `channels` removed as update(z, R, keep) removes them; status
  /// kOk or kNonFinite. A channel gate forms it once per plot, tests its
  /// channels, and updates with narrowed() to the ones it keeps.
  struct ChannelLinearisation {
    MeasVec nu;
    Jacobian H;
    MeasCov R;
    MeasCov S;
    ChannelMask channels;
    Status status;

    /// The channels outside `keep` removed as well. Bit for bit what
    /// linearise_channels() gives for `channels & keep`: a removed row of H
    /// is zero, so it adds exact zeros to every kept entry of S.
    ChannelLinearisation narrowed(ChannelMask keep) const {
      ChannelLinearisation k = *this;
      k.channels = channels & keep;
      for (int i = 0; i < kMeasDim; ++i) {
        if (has_channel(k.channels, i)) continue;
        k.nu(i) = Scalar(0);
        k.H.row(i).setZero();
        k.R.row(i).setZero();
        k.R.col(i).setZero();
        k.R(i, i) = Scalar(1);
        k.S.row(i).setZero();
        k.S.col(i).setZero();
        k.S(i, i) = Scalar(1);
      }
      return k;
    }
  };

  /// The channels `keep` of z linearised at the current state with R
  /// (channels outside `keep`, and non-finite values there, are not read).
  ChannelLinearisation linearise_channels(const MeasVec& z, const MeasCov& R, ChannelMask keep) const {
    ChannelLinearisation k{MeasVec::Zero(), Jacobian::Zero(), MeasCov::Zero(), MeasCov::Identity(),
                           static_cast<ChannelMask>(keep & kAllChannels), Status::kOk};
    for (int i = 0; i < kMeasDim; ++i) {
      if (has_channel(k.channels, i) && !ScalarTraits<Scalar>::is_finite(z(i))) {
        k.status = Status::kNonFinite;
        return k;
      }
    }
    if (!all_finite(R)) {
      k.status = Status::kNonFinite;
      return k;
    }
    const Jacobian H = measurement_.jacobian(x_);
    const MeasVec nu = measurement_.residual(z, measurement_.predict(x_));
    for (int i = 0; i < kMeasDim; ++i) {
      if (!has_channel(k.channels, i)) {
        k.R(i, i) = Scalar(1);
        continue;
      }
      k.nu(i) = nu(i);
      k.H.row(i) = H.row(i);
      for (int j = 0; j < kMeasDim; ++j) {
        if (has_channel(k.channels, j)) k.R(i, j) = R(i, j);
      }
    }
    if (!all_finite(k.H) || !all_finite(k.nu)) {
      k.status = Status::kNonFinite;
      return k;
    }
    k.S = symmetrised(k.H * P_ * k.H.transpose() + k.R);
    if (!all_finite(k.S)) k.status = Status::kNonFinite;
    return k;
  }

  /// The innovation of a linearisation of this state (d2 over its channels).
  Innov innovation(const ChannelLinearisation& k) const {
    Innov out{k.nu, k.S, Scalar(0), k.status};
    if (k.status != Status::kOk) return out;
    if constexpr (kForm == EkfUpdateForm::kSequentialWhitened) {
      if (!whitened_nis(k.H, k.nu, k.R, out.d2)) out.status = Status::kNotPositiveDefinite;
    } else {
      const Eigen::LLT<MeasCov> llt(k.S);
      if (llt.info() != Eigen::Success) {
        out.status = Status::kNotPositiveDefinite;
        return out;
      }
      out.d2 = k.nu.dot(llt.solve(k.nu));
    }
    return out;
  }

  /// Update with a linearisation of this state (linearise_channels(),
  /// perhaps narrowed()): what update(z, R, keep) does after forming it.
  /// One formed before the state last changed gives a wrong update, not a
  /// refusal; the caller keeps them together (ChannelGatedEkf).
  /// @return kOk (no channels: nothing fused, filter unchanged); kNonFinite
  ///         or kNotPositiveDefinite (filter unchanged).
  [[nodiscard]] Status update(const ChannelLinearisation& k) {
    diag_.fused = false;
    diag_.fused_channels = 0;
    if (k.channels == 0) {
      diag_ = Diagnostics{};
      diag_.status = Status::kOk;
      return Status::kOk;
    }
    KESTREL_TRY_OR(fail, k.status);
    Status s;
    if constexpr (kForm == EkfUpdateForm::kSequentialWhitened) {
      s = fold_in_sequential(k.nu, k.H, k.R);
    } else {
      s = fold_in_batch(k.nu, k.H, k.R, k.S);
    }
    if (s == Status::kOk) {
      diag_.present = k.channels;
      diag_.fused_channels = k.channels;
      for (int i = 0; i < kMeasDim; ++i) {
        if (!has_channel(k.channels, i)) diag_.innovation_variance(i) = Scalar(0);  // the padding's 1
      }
    }
    return s;
  }

  /// Probabilistic data association update (Bar-Shalom and Tse, 1975; Bar-Shalom,
  /// Willett and Tian, Tracking and Data Fusion, 2011, section 3.4): the
  /// plots z[0..count) with association weights beta[j], and beta_none for
  /// "none of them is the target". With w_j = L^-1 nu_j (S = L L^T),
  /// w = sum beta_j w_j and U = P H^T L^-T:
  ///   x+ = x + U w,
  ///   P+ = P - U M U^T,  M = (1 - beta_none) I - (sum beta_j w_j w_j^T - w w^T),
  /// which is the textbook beta_none P + (1 - beta_none) P_c + K (spread) K^T
  /// written through the factor of S. The weights are the caller's
  /// (association/pda.hpp). Batch form only (float and double).
  /// @return kOk; kOutOfRange (count 0 or over kMax, a weight outside
  ///         [0, 1]); kNonFinite or kNotPositiveDefinite (filter unchanged).
  template <std::size_t kMax>
    requires(kForm == EkfUpdateForm::kBatch)
  [[nodiscard]] Status update_pda(const MeasVec (&z)[kMax], const Scalar (&beta)[kMax], std::size_t count,
                                  Scalar beta_none) {
    diag_.fused = false;
    if (count == 0 || count > kMax) return fail(Status::kOutOfRange);
    if (!(beta_none >= Scalar(0)) || !(beta_none <= Scalar(1))) return fail(Status::kOutOfRange);
    KESTREL_TRY_OR(fail, state_status(x_, P_));  // P+ is not below P: its check cannot cover an unchecked prediction
    MeasVec z_hat;
    MeasCov S;
    MeasCov L = MeasCov::Zero();
    Mat<Scalar, kStateDim, kMeasDim> PHt;
    if constexpr (kSparseUpdate) {
      const auto& lin = factored_linearisation();
      KESTREL_TRY_OR(fail, lin.factor_status);
      z_hat = lin.z_hat;
      S = lin.S;
      L = lin.L;
      PHt = lin.J.p_ht(P_);
    } else {
      const auto H = measurement_.jacobian(x_);
      const MeasCov R = measurement_.noise();
      z_hat = measurement_.predict(x_);
      S = symmetrised(H * P_ * H.transpose() + R);
      if (!all_finite(H) || !all_finite(S) || !all_finite(z_hat)) return fail(Status::kNonFinite);
      if (!structure::cholesky_lower(S, L)) return fail(Status::kNotPositiveDefinite);
      PHt = P_ * H.transpose();
    }
    MeasVec w_mean = MeasVec::Zero();
    MeasCov spread = MeasCov::Zero();  // sum beta_j w_j w_j^T
    MeasVec nu_best = MeasVec::Zero();
    Scalar beta_best(-1);
    Scalar nis_best(0);
    for (std::size_t j = 0; j < kMax; ++j) {
      if (j >= count) break;
      if (!(beta[j] >= Scalar(0)) || !(beta[j] <= Scalar(1))) return fail(Status::kOutOfRange);
      if (!all_finite(z[j])) return fail(Status::kNonFinite);
      const MeasVec nu = measurement_.residual(z[j], z_hat);
      if (!all_finite(nu)) return fail(Status::kNonFinite);
      const MeasVec w = structure::forward_substitute(L, nu);
      w_mean += beta[j] * w;
      spread += beta[j] * (w * w.transpose());
      if (beta[j] > beta_best) {
        beta_best = beta[j];
        nu_best = nu;
        nis_best = w.squaredNorm();
      }
    }
    MeasCov M = -(spread - w_mean * w_mean.transpose());
    for (int i = 0; i < kMeasDim; ++i) M(i, i) += Scalar(1) - beta_none;
    Mat<Scalar, kStateDim, kMeasDim> U;
    MeasVec unused;
    structure::whitened_gain_factored(PHt, L, MeasVec::Zero().eval(), U, unused);
    const State x = x_ + U * w_mean;
    const Cov P = symmetrised(P_ - U * M * U.transpose());
    KESTREL_TRY_OR(fail, state_status(x, P));

    x_ = x;
    P_ = P;
    invalidate_linearisation();
    diag_.fused_all(nu_best, S.diagonal(), nis_best);
    return Status::kOk;
  }

 private:
  /// Batch form: Cholesky of S, Joseph form, then symmetrised.
  [[nodiscard]] Status update_batch(const MeasVec& z, const MeasCov& R) {
    diag_.fused = false;
    if (!all_finite(z) || !all_finite(R)) return fail(Status::kNonFinite);
    if constexpr (kSparseUpdate) {
      return update_structured(z, R);
    }
    const Jacobian H = measurement_.jacobian(x_);
    const MeasVec nu = measurement_.residual(z, measurement_.predict(x_));
    const MeasCov S = symmetrised(H * P_ * H.transpose() + R);
    if (!all_finite(H) || !all_finite(nu) || !all_finite(S)) return fail(Status::kNonFinite);
    return fold_in_batch(nu, H, R, S);
  }

  /// The batch update from nu, H, R and S = H P H^T + R (finite).
  [[nodiscard]] Status fold_in_batch(const MeasVec& nu, const Jacobian& H, const MeasCov& R, const MeasCov& S) {
    const Eigen::LLT<MeasCov> llt(S);
    if (llt.info() != Eigen::Success) return fail(Status::kNotPositiveDefinite);

    // K = P H^T S^-1, computed as (S^-1 H P)^T since S and P are symmetric.
    // One vector solve per column: a matrix right-hand side sends Eigen to
    // its blocked triangular solver (alloca, plus a malloc branch for large
    // sizes that a board's link-time heap guard rejects); the fixed-size
    // vector solve is unrolled and allocation-free.
    const Mat<Scalar, kMeasDim, kStateDim> HP = H * P_;
    Mat<Scalar, kMeasDim, kStateDim> SinvHP;
    for (int c = 0; c < kStateDim; ++c) SinvHP.col(c) = llt.solve(HP.col(c));
    const Mat<Scalar, kStateDim, kMeasDim> K = SinvHP.transpose();
    const State x = x_ + K * nu;
    const Cov A = Cov::Identity() - K * H;
    const Cov P = symmetrised(A * P_ * A.transpose() + K * R * K.transpose());
    KESTREL_TRY_OR(fail, state_status(x, P));

    x_ = x;
    P_ = P;
    invalidate_linearisation();
    diag_.fused_all(nu, S.diagonal(), nu.dot(llt.solve(nu)));
    return Status::kOk;
  }

  /// Batch form on the non-zero Jacobian columns (structure.hpp): the
  /// shared linearisation, then the update through the Cholesky factor of
  /// S (structure::whitened_gain): x + U w and P - U U^T on the upper
  /// triangle, with U = P H^T L^-T and w = L^-1 nu (header comment).
  /// (Member templates, so that clang 14 instantiates neither body for a
  /// filter without the structure.)
  template <bool kEnabled = kSparseUpdate>
    requires kEnabled
  [[nodiscard]] Status update_structured(const MeasVec& z, const MeasCov& R) {
    const auto& lin = linearisation();
    const MeasVec nu = measurement_.residual(z, lin.z_hat);
    MeasCov S = lin.HPHt;
    structure::add_symmetrised(S, R);
    if (!all_finite(lin.J.Hc) || !all_finite(nu) || !all_finite(S)) return fail(Status::kNonFinite);
    MeasCov L = MeasCov::Zero();
    if (!structure::cholesky_lower(S, L)) return fail(Status::kNotPositiveDefinite);
    return fold_in(nu, S, L);
  }

  /// x + U w and P - U U^T from the residual and S = L L^T (structured path).
  template <bool kEnabled = kSparseUpdate>
    requires kEnabled
  [[nodiscard]] Status fold_in(const MeasVec& nu, const MeasCov& S, const MeasCov& L) {
    const auto& lin = linearisation();
    const Mat<Scalar, kStateDim, kMeasDim> PHt = lin.J.p_ht(P_);
    Mat<Scalar, kStateDim, kMeasDim> U;
    MeasVec w;
    structure::whitened_gain_factored(PHt, L, nu, U, w);
    const State x = x_ + U * w;
    const Cov P = structure::symmetric_downdate(P_, U);
    KESTREL_TRY_OR(fail, state_status(x, P));

    x_ = x;
    P_ = P;
    invalidate_linearisation();
    diag_.fused_all(nu, S.diagonal(), w.squaredNorm());
    return Status::kOk;
  }

  /// Sequential whitened form (header comment): scalar channel updates.
  [[nodiscard]] Status update_sequential(const MeasVec& z, const MeasCov& R) {
    diag_.fused = false;
    if (!all_finite(z) || !all_finite(R)) return fail(Status::kNonFinite);
    if constexpr (kWhitenedSparse) {
      return update_whitened(z, R);
    }
    const Jacobian H = measurement_.jacobian(x_);
    const MeasVec nu = measurement_.residual(z, measurement_.predict(x_));
    if (!all_finite(H) || !all_finite(nu)) return fail(Status::kNonFinite);
    return fold_in_sequential(nu, H, R);
  }

  /// Sequential whitened form on the non-zero Jacobian columns with an
  /// explicit R: the shared linearisation, R's factor and the whitened
  /// factor for this R, then fold_in_whitened().
  template <bool kEnabled = kWhitenedSparse>
    requires kEnabled
  [[nodiscard]] Status update_whitened(const MeasVec& z, const MeasCov& R) {
    const auto& lin = linearisation();
    const MeasVec nu = measurement_.residual(z, lin.z_hat);
    MeasCov S = lin.HPHt;
    structure::add_symmetrised(S, R);
    if (!all_finite(lin.J.Hc) || !all_finite(nu) || !all_finite(S)) return fail(Status::kNonFinite);
    WhitenedFactor f;
    auto Jw = lin.J;  // Hw, written by whitened_factor_for()
    KESTREL_TRY_OR(fail, whitened_factor_for(lin.J, R, f, Jw));
    return fold_in_whitened(nu, S, Jw, f);
  }

  /// R = Lr Lr^T, Hw = Lr^-1 H and S_w = Hw P Hw^T + I = Ls Ls^T for an
  /// explicit R (structure::whitened_factor()).
  template <bool kEnabled = kWhitenedSparse>
    requires kEnabled
  Status whitened_factor_for(const auto& J, const MeasCov& R, WhitenedFactor& f, auto& Jw) const {
    f.Lr = MeasCov::Zero();
    if (!structure::cholesky_lower_reciprocal(R, f.Lr, f.inv_lr) || !all_finite(f.inv_lr)) {
      return Status::kNotPositiveDefinite;
    }
    f.Ls = MeasCov::Zero();
    return structure::whitened_factor(J, f.Lr, f.inv_lr, P_, Jw, f.Ls, f.inv_ls);
  }

  /// The whitened channels folded in through the factor of S_w (the
  /// sequential form written with U = P Hw^T Ls^-T: WhitenedLinearisation):
  /// x + U w and P - U U^T on the upper triangle, mirrored, with
  /// w = Ls^-1 Lr^-1 nu; NIS |w|^2. S (unwhitened) is for the diagnostics.
  template <bool kEnabled = kWhitenedSparse>
    requires kEnabled
  [[nodiscard]] Status fold_in_whitened(const MeasVec& nu, const MeasCov& S, const auto& Jw, const WhitenedFactor& f) {
    const MeasVec nuw = structure::forward_substitute_reciprocal(f.Lr, f.inv_lr, nu);
    const Mat<Scalar, kStateDim, kMeasDim> PHt = Jw.p_ht(P_);
    Mat<Scalar, kStateDim, kMeasDim> U;
    MeasVec w;
    structure::whitened_gain_reciprocal(PHt, f.Ls, f.inv_ls, nuw, U, w);
    const State x = x_ + U * w;
    const Cov P = structure::symmetric_downdate(P_, U);
    const Scalar nis = w.squaredNorm();
    if (!ScalarTraits<Scalar>::is_finite(nis)) return fail(Status::kNonFinite);
    KESTREL_TRY_OR(fail, state_status(x, P));

    x_ = x;
    P_ = P;
    invalidate_linearisation();
    diag_.fused_all(nu, S.diagonal(), nis);
    return Status::kOk;
  }

  /// The sequential whitened update from nu, H and R (finite).
  [[nodiscard]] Status fold_in_sequential(const MeasVec& nu, const Jacobian& H, const MeasCov& R) {
    Jacobian Hw = H;
    MeasVec nuw = nu;
    if (!whiten(R, Hw, nuw)) return fail(Status::kNotPositiveDefinite);

    State dx = State::Zero();
    Cov P = P_;
    Scalar nis(0);
    for (int i = 0; i < kMeasDim; ++i) {
      const State h = Hw.row(i).transpose();
      // Channel i linearised at the prediction, seen from the state the
      // earlier channels produced: the batch update's residual.
      const Scalar nu_i = nuw(i) - h.dot(dx);
      const State PHt = P * h;
      const Scalar s = h.dot(PHt) + Scalar(1);  // >= 1 up to round-off
      if (!(s > Scalar(0)) || !ScalarTraits<Scalar>::is_finite(s)) {
        return fail(Status::kNotPositiveDefinite);
      }
      const State K = PHt / s;
      dx += K * nu_i;
      nis += nu_i * nu_i / s;
      // Joseph form of one scalar channel with unit noise:
      // (I - K h^T) P (I - K h^T)^T + K K^T = P - K PHt^T - PHt K^T + s K K^T,
      // upper triangle computed and mirrored, so P is exactly symmetric.
      for (int c = 0; c < kStateDim; ++c) {
        const Scalar sKc = s * K(c);
        for (int r = 0; r <= c; ++r) {
          const Scalar v = P(r, c) - K(r) * PHt(c) - PHt(r) * K(c) + K(r) * sKc;
          P(r, c) = v;
          P(c, r) = v;
        }
      }
    }
    const State x = x_ + dx;
    if (!ScalarTraits<Scalar>::is_finite(nis)) return fail(Status::kNonFinite);
    KESTREL_TRY_OR(fail, state_status(x, P));
    MeasVec s_diag;  // diag(H P H^T + R) before the update, for diagnostics
    for (int i = 0; i < kMeasDim; ++i) {
      const Eigen::Matrix<Scalar, 1, kStateDim> hP = H.row(i) * P_;
      s_diag(i) = hP.dot(H.row(i)) + R(i, i);
    }

    x_ = x;
    P_ = P;
    invalidate_linearisation();
    diag_.fused_all(nu, s_diag, nis);
    return Status::kOk;
  }

  /// R = L L^T (lower Cholesky, fixed loops), then H <- L^-1 H and
  /// nu <- L^-1 nu by forward substitution: unit, independent channel noise.
  /// @return false if R is not positive definite.
  static bool whiten(const MeasCov& R, Jacobian& H, MeasVec& nu) {
    MeasCov L = MeasCov::Zero();
    for (int j = 0; j < kMeasDim; ++j) {
      Scalar d = R(j, j);
      for (int k = 0; k < j; ++k) d -= L(j, k) * L(j, k);
      if (!(d > Scalar(0))) return false;
      L(j, j) = ScalarTraits<Scalar>::sqrt(d);
      for (int i = j + 1; i < kMeasDim; ++i) {
        Scalar v = R(i, j);
        for (int k = 0; k < j; ++k) v -= L(i, k) * L(j, k);
        L(i, j) = v / L(j, j);
      }
    }
    for (int i = 0; i < kMeasDim; ++i) {
      for (int k = 0; k < i; ++k) {
        H.row(i) -= L(i, k) * H.row(k);
        nu(i) -= L(i, k) * nu(k);
      }
      H.row(i) /= L(i, i);
      nu(i) /= L(i, i);
    }
    return all_finite(H) && all_finite(nu);
  }

  /// nu^T S^-1 nu, S = H P H^T + R, from the whitened channels: S_w = H_w P
  /// H_w^T + I = L D L^T (unit lower L, fixed loops, every D_j >= 1 up to
  /// round-off), then the sum of y_j^2 / D_j with y = L^-1 nu_w.
  /// @return false if R or S_w is not positive definite.
  bool whitened_nis(Jacobian Hw, MeasVec nuw, const MeasCov& R, Scalar& d2) const {
    if (!whiten(R, Hw, nuw)) return false;
    MeasCov Sw = Hw * P_ * Hw.transpose();
    for (int j = 0; j < kMeasDim; ++j) Sw(j, j) += Scalar(1);
    for (int j = 0; j < kMeasDim; ++j) {  // L below the diagonal, D on it
      Scalar D = Sw(j, j);
      for (int k = 0; k < j; ++k) D -= Sw(j, k) * Sw(j, k) * Sw(k, k);
      if (!(D > Scalar(0)) || !ScalarTraits<Scalar>::is_finite(D)) return false;
      Sw(j, j) = D;
      for (int i = j + 1; i < kMeasDim; ++i) {
        Scalar v = Sw(i, j);
        for (int k = 0; k < j; ++k) v -= Sw(i, k) * Sw(j, k) * Sw(k, k);
        Sw(i, j) = v / D;
      }
    }
    Scalar sum(0);
    for (int i = 0; i < kMeasDim; ++i) {
      for (int k = 0; k < i; ++k) nuw(i) -= Sw(i, k) * nuw(k);
      sum += nuw(i) * nuw(i) / Sw(i, i);
    }
    if (!ScalarTraits<Scalar>::is_finite(sum)) return false;
    d2 = sum;
    return true;
  }

 public:
  const State& x() const { return x_; }
  const Cov& P() const { return P_; }
  const Motion& motion() const { return motion_; }
  const Measurement& measurement() const { return measurement_; }
  Motion& motion() { return motion_; }
  /// Mutable model access drops the shared linearisation (its parameters may change).
  Measurement& measurement() {
    invalidate_linearisation();
    if constexpr (kWhitenedSparse) lin_.noise_valid = false;
    return measurement_;
  }
  /// Diagnostics of the last update attempt.
  const Diagnostics& diagnostics() const { return diag_; }

 private:
  template <bool kVerify>
  [[nodiscard]] Status predict_checked(Scalar dt) {
    if constexpr (kBlockPredict) {
      // F P F^T and Q per axis block.
      Cov P = structure::transform_covariance(motion_, P_, dt);
      structure::add_process_noise(motion_, P, dt);
      return commit_prediction<kVerify>(motion_.propagate(x_, dt), P);
    } else {
      const Cov F = motion_.jacobian(x_, dt);
      return commit_prediction<kVerify>(motion_.propagate(x_, dt),
                                        symmetrised(F * P_ * F.transpose() + motion_.process_noise(dt)));
    }
  }

  template <bool kVerify = true>
  [[nodiscard]] Status commit_prediction(const State& x, const Cov& P) {
    if constexpr (kVerify) KESTREL_TRY(state_status(x, P));
    x_ = x;
    P_ = P;
    invalidate_linearisation();
    return Status::kOk;
  }

  /// h(x), the Jacobian columns and H P H^T at the current x and P,
  /// computed on first use after any change.
  template <bool kEnabled = kSparseUpdate>
    requires kEnabled
  const auto& linearisation() const {
    if (!lin_.valid) {
      lin_.z_hat = measurement_.predict(x_);
      if constexpr (requires { measurement_.jacobian_columns(x_, lin_.z_hat); }) {
        lin_.J.Hc = measurement_.jacobian_columns(x_, lin_.z_hat);  // reuses h(x)'s range
      } else {
        lin_.J.Hc = measurement_.jacobian_columns(x_);
      }
      lin_.HPHt = lin_.J.hpht(P_);
      lin_.factor_valid = false;
      lin_.valid = true;
    }
    return lin_;
  }

  /// The linearisation with S = H P H^T + R for the model's own R and its
  /// factor, computed on first use (an explicit-R caller such as R2-AEKF
  /// never pays for them).
  /// The sequential whitened form factors R once (it does not depend on x
  /// or P) and S_w per linearisation (WhitenedLinearisation).
  template <bool kEnabled = kSparseUpdate>
    requires kEnabled
  const auto& factored_linearisation() const {
    linearisation();
    if (!lin_.factor_valid) {
      const MeasCov R = measurement_.noise();
      lin_.S = lin_.HPHt;
      structure::add_symmetrised(lin_.S, R);
      if (!all_finite(R) || !all_finite(lin_.J.Hc) || !all_finite(lin_.S)) {
        lin_.factor_status = Status::kNonFinite;
      } else if constexpr (kWhitenedSparse) {
        if (!lin_.noise_valid) {
          lin_.Lr = MeasCov::Zero();
          const bool ok = structure::cholesky_lower_reciprocal(R, lin_.Lr, lin_.inv_lr) && all_finite(lin_.inv_lr);
          lin_.noise_status = ok ? Status::kOk : Status::kNotPositiveDefinite;
          lin_.noise_valid = true;
        }
        lin_.factor_status = lin_.noise_status;
        if (lin_.factor_status == Status::kOk) {
          lin_.factor_status = structure::whitened_factor(lin_.J, lin_.Lr, lin_.inv_lr, P_, lin_.Jw, lin_.Ls, lin_.inv_ls);
        }
      } else {
        lin_.factor_status = structure::cholesky_lower(lin_.S, lin_.L) ? Status::kOk : Status::kNotPositiveDefinite;
      }
      lin_.factor_valid = true;
    }
    return lin_;
  }

  /// The factor of S a plot's distance uses (FactorOfS), from the factored linearisation.
  template <class Lin>
  static FactorOfS factor_of(const Lin& lin) {
    if constexpr (kWhitenedSparse) {
      return WhitenedFactor{lin.Lr, lin.inv_lr, lin.Ls, lin.inv_ls};
    } else {
      return BatchFactor{lin.L};
    }
  }

  /// factor_of(lin).whiten(nu) without the copy.
  template <class Lin>
  static MeasVec whitened_residual(const Lin& lin, const MeasVec& nu) {
    if constexpr (kWhitenedSparse) {
      return structure::forward_substitute_reciprocal(
          lin.Ls, lin.inv_ls, structure::forward_substitute_reciprocal(lin.Lr, lin.inv_lr, nu));
    } else {
      return structure::forward_substitute(lin.L, nu);
    }
  }

  void invalidate_linearisation() {
    if constexpr (kSparseUpdate) lin_.valid = false;
  }

  Status fail(Status s) {
    diag_.fused = false;
    diag_.fused_channels = 0;
    diag_.status = s;
    return s;
  }

  Motion motion_;
  Measurement measurement_;
  State x_;
  Cov P_;
  Diagnostics diag_;
  // Shared linearisation (sparse-Jacobian models only); like any filter
  // here, one object is not to be used from two threads at once.
  mutable std::conditional_t<
      kSparseUpdate,
      std::conditional_t<kWhitenedSparse, typename structure::WhitenedLinearisationFor<Measurement>::type,
                         typename structure::LinearisationFor<Measurement>::type>,
      structure::NoLinearisation>
      lin_{};
};

}  // namespace kestrel
