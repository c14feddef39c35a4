// SPDX-License-Identifier: Apache-2.0
// A per-channel gate in front of the EKF (SPEC sections 5 and 6; paper 003
// section 3.3.3): the measurement model declares every channel it can know
// (kMeasDim, a compile-time maximum); a frame says which of them it carries
// with a ChannelMask, the gate drops more, and Ekf fuses exactly the
// channels left (Ekf::update(z, R, keep): a dropped channel is removed, not
// set to zero as the paper's "replace it with 0" would, which still shrinks
// P as if something had been measured). The gate only chooses rows; the
// predict, the update and their checks are Ekf's, in every form Ekf has.
// With every channel removed the step is predict-only.
//
// Gates, applied in this order to the present channels:
//   per-channel (paper 003): drop channel i when |nu_i| > k sqrt(S_ii),
//     S_ii = (H P H^T + R)_ii from the prediction; k configurable, default 2;
//   ellipsoidal (option): test the kept set on nu^T S^-1 nu against the
//     chi-square quantile of its dimension; while it fails, drop the kept
//     channel with the largest |nu_i| / sqrt(S_ii) and test again (at most
//     kMeasDim rounds).
//
// Same contract as Ekf: kNonFinite / kNotPositiveDefinite leave x and P
// unchanged. update(z) with every channel makes it a drop-in TrackingFilter;
// with all channels present and no gate it is Ekf's dense update.
#pragma once

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
  ChannelGatedEkf(const Motion& motion, const Measurement& measurement) : ekf_(motion, measurement) {}

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
    present &= kAllChannels;
    diag_ = Diagnostics{};
    diag_.present = present;
    diag_.status = Status::kOk;
    const Innov lin = ekf_.innovation(z, R, present);
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
        const Innov set = ekf_.innovation(z, R, kept);
        if (set.status != Status::kOk) return fail(set.status);
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
    if (const Status s = ekf_.update(z, R, kept); s != Status::kOk) return fail(s);
    diag_.fused_channels = kept;
    diag_.nis = ekf_.diagnostics().nis;
    diag_.fused = true;
    return Status::kOk;
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

 private:
  Status fail(Status s) {
    diag_.status = s;
    diag_.fused_channels = 0;
    diag_.fused = false;
    return s;
  }

  Base ekf_;
  Diagnostics diag_{};
};

}  // namespace kestrel
