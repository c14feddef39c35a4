// SPDX-License-Identifier: Apache-2.0
// A per-channel gate in front of the EKF (paper 003 section 3.3.3): the
// measurement model declares every channel it can know (kMeasDim, a
// compile-time maximum), a frame says which it carries with a ChannelMask,
// the gate drops channels whose |nu_i| exceeds k sqrt(S_ii) (and optionally
// the worst ones until the ellipsoidal test passes), and Ekf fuses exactly
// the channels left (Ekf::update(z, R, keep)). A dropped channel is removed,
// not set to zero as the paper's "replace it with 0" would, which still
// shrinks P as if something had been measured. update_channels() may also
// widen P for what the gate dropped and keep one component within bounds
// (the sonar's depth). Same contract as Ekf: kNonFinite and
// kNotPositiveDefinite leave x and P unchanged. Details: docs/sonar.md,
// "Filter: a variable subset of channels".
#pragma once

#include <cmath>
#include <cstdint>

#include "kestrel/association/chi_square.hpp"
#include "kestrel/filters/channels.hpp"
#include "kestrel/filters/ekf.hpp"
#include "kestrel/filters/innovation.hpp"
#include "kestrel/math/eigen.hpp"
#include "kestrel/models/concepts.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"

namespace kestrel {

/// Which gates update_gated() applies.
template <class Scalar>
struct ChannelGateConfig {
  bool per_channel = true;      ///< Drop channel i when |nu_i| > k_sigma * sqrt(S_ii) (paper 003).
  Scalar k_sigma = lit<Scalar>(2.0);  ///< k, the per-channel gate multiplier (2 in the paper).
  bool ellipsoidal = false;     ///< Also test the kept set on nu^T S^-1 nu (peeling the worst channel).
  GateProbability ellipsoid_probability = GateProbability::k99;  ///< Chi-square probability of that test.
  /// update_channels(): widen P for the channels the per-channel gate
  /// dropped (add_gate_truncation()).
  bool widen_for_dropped = false;
};

/// A box on one state component, kept by projection (constrain()).
template <class Scalar>
struct StateBound {
  int index = -1;  ///< State component; -1: no bound.
  Scalar lo{};     ///< Smallest value.
  Scalar hi{};     ///< Largest value.
};

template <MotionModel Motion, MeasurementModelFor<Motion> Measurement>
class ChannelGatedEkf {
 public:
  using Base = Ekf<Motion, Measurement>;
  using Scalar = typename Motion::Scalar;
  static constexpr int kStateDim = Motion::kStateDim;
  static constexpr int kMeasDim = Measurement::kMeasDim;
  static_assert(kMeasDim <= 32, "a ChannelMask holds 32 channels");
  static_assert(kMeasDim <= kChiSquareMaxDim, "the ellipsoidal gate needs a chi-square row per subset size");
  using MotionModel = Motion;
  using MeasurementModel = Measurement;
  using Layout = typename Motion::Layout;
  using State = typename Motion::State;
  using Cov = typename Motion::Cov;
  using MeasVec = typename Measurement::Measurement;
  using MeasCov = typename Measurement::NoiseCov;
  using Innov = Innovation<Scalar, kMeasDim>;
  using Diagnostics = FusionDiagnostics<Scalar, kMeasDim>;
  using GateConfig = ChannelGateConfig<Scalar>;
  static constexpr ChannelMask kAllChannels = all_channels(kMeasDim);

  ChannelGatedEkf() : ChannelGatedEkf(Motion{}, Measurement{}) {}
  /// @param gate  the gate of update_channels() (update_gated() takes its own).
  /// @param bound the state bound of update_channels() and constrain().
  ChannelGatedEkf(const Motion& motion, const Measurement& measurement, const GateConfig& gate = GateConfig{},
                  const StateBound<Scalar>& bound = StateBound<Scalar>{})
      : ekf_(motion, measurement), gate_(gate), bound_(bound) {
    if (gate.per_channel && gate.widen_for_dropped) {
      // Once, in double: tail = Pr(|u| > k) = erfc(k / sqrt 2) for
      // u ~ N(0, 1) and excess = E[u^2 | |u| > k] - 1 = k phi(k) / Q(k),
      // Q(k) = tail / 2 (0.0455 and 4.75 at k = 2; 0.0027 and 9.85 at k = 3).
      const double k = ScalarTraits<Scalar>::to_double(gate.k_sigma);
      const double tail = std::erfc(k / std::sqrt(2.0));
      const double phi = std::exp(-0.5 * k * k) / std::sqrt(2.0 * 3.14159265358979323846);
      gate_tail_ = ScalarTraits<Scalar>::from_double(tail);
      gate_excess_ = ScalarTraits<Scalar>::from_double(tail > 0.0 ? 2.0 * k * phi / tail : 0.0);
    }
  }

  /// Set the state and covariance (Ekf::reset).
  [[nodiscard]] Status reset(const State& x, const Cov& P) { return ekf_.reset(x, P); }
  /// Predict by dt seconds with the model's process noise (Ekf::predict).
  [[nodiscard]] Status predict(Scalar dt) { return ekf_.predict(dt); }
  /// Predict by dt seconds with an explicit process noise Q.
  [[nodiscard]] Status predict(Scalar dt, const Cov& Q) { return ekf_.predict(dt, Q); }

  /// Innovation over every channel (TrackingFilter compatibility).
  Innov innovation(const MeasVec& z) const { return innovation(z, kAllChannels); }

  /// Innovation of the `present` channels of z against the current state.
  /// Pure. nu and S are padded (absent channels: nu_i = 0, S row/column =
  /// unit vector), so d2 is over present channels.
  Innov innovation(const MeasVec& z, ChannelMask present) const {
    return ekf_.innovation(z, ekf_.measurement().noise(), present);
  }

  /// Update with every channel of z, no gate.
  /// @return kOk; kNonFinite or kNotPositiveDefinite (filter unchanged).
  [[nodiscard]] Status update(const MeasVec& z) { return update(z, kAllChannels); }

  /// Update with exactly the `present` channels of z and the model's R, no gate.
  /// @return kOk (also when `present` is empty: nothing fused, filter
  ///         unchanged); kNonFinite or kNotPositiveDefinite (filter unchanged).
  [[nodiscard]] Status update(const MeasVec& z, ChannelMask present) {
    GateConfig none;
    none.per_channel = false;
    none.ellipsoidal = false;
    return update_gated(z, present, none, ekf_.measurement().noise());
  }

  /// The configured step: gate the `present` channels of z with the
  /// constructor's gate, update with the ones that pass, widen P for what
  /// the per-channel gate dropped (if configured), then constrain().
  /// @return kOk (also when nothing was fused: diagnostics().fused);
  ///         kNonFinite or kNotPositiveDefinite (filter and totals unchanged).
  [[nodiscard]] Status update_channels(const MeasVec& z, ChannelMask present) {
    const ChannelGatedEkf before = *this;
    const Linearisation lin = ekf_.linearise_channels(z, ekf_.measurement().noise(), present);
    Status s = update_gated(lin, gate_);
    const ChannelMask dropped = dropped_by_channel_gate();
    if (s == Status::kOk && gate_.widen_for_dropped && dropped != 0) {
      s = add_gate_truncation(lin, dropped);
    }
    if (s == Status::kOk) s = constrain();
    if (s != Status::kOk) {
      const Diagnostics d = diag_;
      *this = before;
      diag_ = d;
      return fail(s);
    }
    offered_ += static_cast<std::uint32_t>(channel_count(diag_.present));
    dropped_ += static_cast<std::uint32_t>(channel_count(diag_.rejected));
    return Status::kOk;
  }

  /// Record channels that were present but refused before the update (a
  /// multilateration's outliers): they show as present and rejected in
  /// diagnostics() and count in the gate's totals as dropped.
  void note_refused(ChannelMask present, ChannelMask refused) {
    present &= kAllChannels;
    refused &= present;
    diag_.present |= present;
    diag_.rejected |= refused;
    offered_ += static_cast<std::uint32_t>(channel_count(present));
    dropped_ += static_cast<std::uint32_t>(channel_count(refused));
  }

  /// Project the state onto the bound, if it is outside: x -= P e (e^T x -
  /// b) / P_ee, e the bounded axis (the estimate projection of a linear
  /// inequality constraint, which moves the correlated components too); P
  /// is kept, which is conservative. The sonar's use: a linearised update
  /// can put the target above the surface, at the mirror image the direct
  /// arrivals cannot tell apart.
  /// @return kOk; kNotPositiveDefinite (P_ee not positive; unchanged).
  [[nodiscard]] Status constrain() {
    if (bound_.index < 0 || bound_.index >= kStateDim) return Status::kOk;
    const int e = bound_.index;
    const Scalar v = x()(e);
    if (!(v < bound_.lo) && !(v > bound_.hi)) return Status::kOk;
    const Scalar b = v < bound_.lo ? bound_.lo : bound_.hi;
    const Cov& P = this->P();
    const Scalar pee = P(e, e);
    if (!(pee > Scalar(0))) return Status::kNotPositiveDefinite;
    State xc = x() - P.col(e) * ((v - b) / pee);
    xc(e) = b;  // exact, whatever the rounding
    return ekf_.reset(xc, P);
  }

  /// Gate the `present` channels of z (header comment) and update with the
  /// ones that pass, using the model's R.
  /// @return kOk (also when every channel was gated out: predict-only, see
  ///         diagnostics().fused); kNonFinite or kNotPositiveDefinite
  ///         (filter unchanged).
  [[nodiscard]] Status update_gated(const MeasVec& z, ChannelMask present, const GateConfig& gate) {
    return update_gated(z, present, gate, ekf_.measurement().noise());
  }

  /// As above with an explicit measurement noise R (off-diagonal terms
  /// between a kept and a dropped channel are ignored).
  [[nodiscard]] Status update_gated(const MeasVec& z, ChannelMask present, const GateConfig& gate,
                                    const MeasCov& R) {
    return update_gated(ekf_.linearise_channels(z, R, present), gate);
  }

  const State& x() const { return ekf_.x(); }
  const Cov& P() const { return ekf_.P(); }
  const Motion& motion() const { return ekf_.motion(); }
  const Measurement& measurement() const { return ekf_.measurement(); }
  Motion& motion() { return ekf_.motion(); }
  Measurement& measurement() { return ekf_.measurement(); }
  /// Diagnostics of the last update attempt, per channel.
  const Diagnostics& diagnostics() const { return diag_; }
  /// The EKF that does the arithmetic.
  const Base& ekf() const { return ekf_; }
  const GateConfig& gate() const { return gate_; }
  const StateBound<Scalar>& bound() const { return bound_; }
  /// Channels offered to update_channels() (and note_refused()) so far, and
  /// of them dropped: the gate's running totals.
  std::uint32_t channels_offered() const { return offered_; }
  std::uint32_t channels_dropped() const { return dropped_; }

 private:
  using Linearisation = typename Base::ChannelLinearisation;

  /// The gate and the update on one linearisation of the predicted state:
  /// every test and the update of the kept channels read it, none forms it
  /// again.
  Status update_gated(const Linearisation& lin, const GateConfig& gate) {
    const ChannelMask present = lin.channels;
    diag_ = Diagnostics{};
    diag_.present = present;
    diag_.status = Status::kOk;
    if (lin.status == Status::kNonFinite) return fail(lin.status);
    for (int i = 0; i < kMeasDim; ++i) {
      if (!has_channel(present, i)) continue;
      diag_.innovation(i) = lin.nu(i);
      diag_.innovation_variance(i) = lin.S(i, i);
    }

    ChannelMask kept = present;
    // Paper 003, section 3.3.3: each channel against its own k-sigma bound.
    if (gate.per_channel) {
      for (int i = 0; i < kMeasDim; ++i) {
        if (!has_channel(present, i)) continue;
        const Scalar sd = ScalarTraits<Scalar>::sqrt(lin.S(i, i));
        diag_.test_ratio(i) = ScalarTraits<Scalar>::abs(lin.nu(i)) / (gate.k_sigma * sd);
        if (diag_.test_ratio(i) > Scalar(1)) {
          kept = without_channel(kept, i);
          diag_.rejected = with_channel(diag_.rejected, i);
        }
      }
    }

    // Optional ellipsoidal test of the kept set; peel the worst channel
    // while it fails. Each round removes one channel, so kMeasDim bounds it.
    if (gate.ellipsoidal) {
      for (int round = 0; round < kMeasDim; ++round) {
        const int m = channel_count(kept);
        if (m == 0) break;
        const Innov set = ekf_.innovation(lin.narrowed(kept));
        KESTREL_TRY_OR(fail, set.status);
        const Scalar threshold = ScalarTraits<Scalar>::from_double(
            chi_square_quantile(m, gate.ellipsoid_probability));
        if (set.d2 <= threshold) break;
        int worst = -1;
        Scalar worst_ratio{};
        for (int i = 0; i < kMeasDim; ++i) {
          if (!has_channel(kept, i)) continue;
          const Scalar r2 = lin.nu(i) * lin.nu(i) / lin.S(i, i);
          if (worst < 0 || r2 > worst_ratio) {
            worst = i;
            worst_ratio = r2;
          }
        }
        kept = without_channel(kept, worst);
        diag_.rejected = with_channel(diag_.rejected, worst);
      }
    }

    if (kept == 0) return Status::kOk;  // every channel gated or absent: predict-only
    KESTREL_TRY_OR(fail, ekf_.update(lin.narrowed(kept)));
    diag_.fused_channels = kept;
    diag_.nis = ekf_.diagnostics().nis;
    diag_.fused = true;
    return Status::kOk;
  }

  /// The channels the per-channel gate dropped in the last update (its
  /// test ratio over 1), not those the ellipsoidal gate peeled.
  ChannelMask dropped_by_channel_gate() const {
    ChannelMask m = 0;
    for (int i = 0; i < kMeasDim; ++i) {
      if (has_channel(diag_.rejected, i) && diag_.test_ratio(i) > Scalar(1)) m = with_channel(m, i);
    }
    return m;
  }

  /// The per-channel gate drops channel i when |nu_i| > k sqrt(S_ii) and the
  /// update then treats it as never received. But had the arrival been a
  /// good one, the truth lies where channel i's innovation is beyond k sigma:
  /// with u = nu_i / sqrt(S_ii) ~ N(0, 1), E[u^2 | |u| > k] = 1 + excess
  /// (5.75 at k = 2), so along g = P h_i^T the spread is larger than P says
  /// by excess g g^T / s_i, s_i = h_i P h_i^T + R_ii. That term is added,
  /// with P the covariance after the update with the kept channels (an
  /// approximation: the gate tested the predicted innovation) and h_i at the
  /// predicted state, weighted by the probability that a dropped channel is
  /// good, Pr(good, dropped) / Pr(dropped) <= tail / (dropped fraction so
  /// far, this frame included) (1 when nothing but noise is dropped, about
  /// 0.45 with 5 % outliers), capped at 1. The mean is left alone (a
  /// two-sided gate says nothing about the sign). The kept channels need no
  /// correction: the update conditions on their values.
  Status add_gate_truncation(const Linearisation& lin, ChannelMask dropped) {
    const auto& H = lin.H;  // at the predicted state
    const auto& R = lin.R;
    const std::int64_t offered = static_cast<std::int64_t>(offered_) + channel_count(lin.channels);
    const std::int64_t gated = static_cast<std::int64_t>(dropped_) + channel_count(dropped);
    Scalar good = gate_tail_ * ScalarTraits<Scalar>::from_ratio(offered, gated);
    if (good > Scalar(1)) good = Scalar(1);
    const Scalar w = good * gate_excess_;
    const Cov& P = ekf_.P();
    Cov widened = P;
    for (int i = 0; i < kMeasDim; ++i) {
      if (!has_channel(dropped, i)) continue;
      const State g = P * H.row(i).transpose();
      const Scalar s_i = H.row(i).dot(g) + R(i, i);
      widened += (w / s_i) * (g * g.transpose());
    }
    return ekf_.reset(ekf_.x(), widened);
  }

  Status fail(Status s) {
    diag_.status = s;
    diag_.fused_channels = 0;
    diag_.fused = false;
    return s;
  }

  Base ekf_;
  Diagnostics diag_{};
  GateConfig gate_{};
  StateBound<Scalar> bound_{};
  Scalar gate_tail_{};          ///< Pr(|u| > k), u ~ N(0, 1), k = gate_.k_sigma.
  Scalar gate_excess_{};        ///< E[u^2 | |u| > k] - 1.
  std::uint32_t offered_ = 0;   ///< Channels offered to the gate so far.
  std::uint32_t dropped_ = 0;   ///< Of them dropped (by a gate or note_refused()).
};

}  // namespace kestrel
