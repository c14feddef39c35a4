// Extended Kalman filter that updates with a variable subset of a fixed set
// of measurement channels, with a per-channel gate (SPEC sections 5 and 6;
// paper 003 section 3.3.3). The measurement model declares every channel it
// can know (kMeasDim, a compile-time maximum); a frame says which of them it
// carries with a ChannelMask, and the gate may drop more.
//
// A channel that is absent or gated out is removed from the update, not set
// to zero (the paper "replaces it with 0", which would still shrink P as if
// something had been measured). Removal is exact on fixed-size storage: the
// channel's row of H and entry of nu are zeroed and its row and column of S
// become a unit vector, so S is block-diagonal [S_kept, 0; 0, I] up to a
// permutation, the gain K = P H^T S^-1 has an exactly zero column for it and
// the Joseph update equals the update with only the kept channels
// (tests/core/filters/channel_gated_ekf_test.cpp checks this against a
// reduced-dimension reference). With every channel removed the step is
// predict-only.
//
// Gates, applied in this order to the present channels:
//   per-channel (paper 003): drop channel i when |nu_i| > k sqrt(S_ii),
//     S_ii = (H P H^T + R)_ii from the prediction; k configurable, default 2;
//   ellipsoidal (option): test the kept set on nu^T S^-1 nu against the
//     chi-square quantile of its dimension; while it fails, drop the kept
//     channel with the largest |nu_i| / sqrt(S_ii) and test again (at most
//     kMeasDim rounds).
//
// Same contract as Ekf (filters/ekf.hpp): every operation computes into
// locals and commits only on success; kNonFinite / kNotPositiveDefinite leave
// x and P unchanged. update(z) with every channel makes it a drop-in
// TrackingFilter; with all channels present and no gate it is Ekf.
#pragma once

#include <cstdint>

#include "kestrel/association/chi_square.hpp"
#include "kestrel/filters/innovation.hpp"
#include "kestrel/math/eigen.hpp"
#include "kestrel/math/finite.hpp"
#include "kestrel/math/positive_definite.hpp"
#include "kestrel/models/concepts.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"

namespace kestrel {

/// Set of channels of a measurement vector: bit i is channel i.
using ChannelMask = std::uint32_t;

/// Mask with channels 0 .. n-1 set.
constexpr ChannelMask all_channels(int n) {
  return n >= 32 ? ~ChannelMask{0} : ((ChannelMask{1} << n) - 1u);
}
constexpr bool has_channel(ChannelMask m, int ch) { return ((m >> ch) & 1u) != 0u; }
constexpr ChannelMask with_channel(ChannelMask m, int ch) { return m | (ChannelMask{1} << ch); }
constexpr ChannelMask without_channel(ChannelMask m, int ch) { return m & ~(ChannelMask{1} << ch); }
/// Number of set bits (bounded loop over the 32 bits).
constexpr int channel_count(ChannelMask m) {
  int n = 0;
  for (int i = 0; i < 32; ++i) n += static_cast<int>((m >> i) & 1u);
  return n;
}

/// Which gates update_gated() applies.
template <class Scalar>
struct ChannelGateConfig {
  bool per_channel = true;      ///< Drop channel i when |nu_i| > k_sigma * sqrt(S_ii) (paper 003).
  Scalar k_sigma = lit<Scalar>(2.0);  ///< k, the per-channel gate multiplier (2 in the paper).
  bool ellipsoidal = false;     ///< Also test the kept set on nu^T S^-1 nu (peeling the worst channel).
  GateProbability ellipsoid_probability = GateProbability::k99;  ///< Chi-square probability of that test.
};

/// What the last update said about each channel (PX4 aid-source style).
template <class Scalar, int kN>
struct ChannelDiagnostics {
  Vec<Scalar, kN> innovation;           ///< nu_i = z_i - h_i(x_pred) of present channels, 0 elsewhere (z units).
  Vec<Scalar, kN> innovation_variance;  ///< S_ii of present channels, 0 elsewhere (z units squared).
  Vec<Scalar, kN> test_ratio;           ///< |nu_i| / (k sqrt(S_ii)); > 1 fails the per-channel gate.
  ChannelMask present;                  ///< Channels the frame carried.
  ChannelMask gated_channel;            ///< Dropped by the per-channel gate.
  ChannelMask gated_ellipsoid;          ///< Dropped by the ellipsoidal gate.
  ChannelMask fused;                    ///< Channels that went into the update.
  Scalar nis;                           ///< nu^T S^-1 nu over the fused channels (0 if none).
  bool state_changed;                   ///< true if x and P were updated (at least one channel fused).
  Status status;                        ///< Outcome of the last update.
};

template <MotionModel Motion, MeasurementModelFor<Motion> Measurement>
class ChannelGatedEkf {
 public:
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
  using Jacobian = typename Measurement::Jacobian;
  using Innov = Innovation<Scalar, kMeasDim>;
  using Diagnostics = ChannelDiagnostics<Scalar, kMeasDim>;
  using GateConfig = ChannelGateConfig<Scalar>;
  static constexpr ChannelMask kAllChannels = all_channels(kMeasDim);

  ChannelGatedEkf() : ChannelGatedEkf(Motion{}, Measurement{}) {}
  ChannelGatedEkf(const Motion& motion, const Measurement& measurement)
      : motion_(motion), measurement_(measurement), x_(State::Zero()), P_(Cov::Identity()) {
    clear_diagnostics(0);
    diag_.status = Status::kNotInitialised;
  }

  /// Set the state and covariance.
  /// @return kOk; kNonFinite if any entry is NaN/Inf, kNotPositiveDefinite
  ///         if P is not (filter unchanged in both cases).
  [[nodiscard]] Status reset(const State& x, const Cov& P) {
    const Cov Ps = symmetrised(P);
    if (const Status c = state_status(x, Ps); c != Status::kOk) return c;
    x_ = x;
    P_ = Ps;
    return Status::kOk;
  }

  /// Predict by dt seconds with the model's process noise Q(dt).
  /// @return kOk; kNonFinite (filter unchanged).
  [[nodiscard]] Status predict(Scalar dt) { return predict(dt, motion_.process_noise(dt)); }

  /// Predict by dt seconds with an explicit process noise Q.
  /// @return kOk; kNonFinite (filter unchanged).
  [[nodiscard]] Status predict(Scalar dt, const Cov& Q) {
    const Cov F = motion_.jacobian(x_, dt);
    const State x = motion_.propagate(x_, dt);
    const Cov P = symmetrised(F * P_ * F.transpose() + Q);
    if (const Status c = state_status(x, P); c != Status::kOk) return c;
    x_ = x;
    P_ = P;
    return Status::kOk;
  }

  /// Innovation over every channel (TrackingFilter compatibility).
  Innov innovation(const MeasVec& z) const { return innovation(z, kAllChannels); }

  /// Innovation of the `present` channels of z against the current state.
  /// Pure. nu and S are padded as in the header comment (absent channels:
  /// nu_i = 0, S row/column = unit vector), so d2 is over present channels.
  Innov innovation(const MeasVec& z, ChannelMask present) const {
    Innov out{MeasVec::Zero(), MeasCov::Identity(), Scalar(0), Status::kOk};
    const Lin lin = linearise(z, measurement_.noise(), present & kAllChannels);
    out.nu = lin.nu;
    out.S = lin.S;
    out.status = lin.status;
    if (lin.status != Status::kOk) return out;
    const Eigen::LLT<MeasCov> llt(lin.S);
    if (llt.info() != Eigen::Success) {
      out.status = Status::kNotPositiveDefinite;
      return out;
    }
    out.d2 = lin.nu.dot(llt.solve(lin.nu));
    return out;
  }

  /// Update with every channel of z, no gate (as Ekf::update).
  /// @return kOk; kNonFinite or kNotPositiveDefinite (filter unchanged).
  [[nodiscard]] Status update(const MeasVec& z) { return update(z, kAllChannels); }

  /// Update with exactly the `present` channels of z and the model's R, no gate.
  /// @return kOk (also when `present` is empty: nothing fused, filter
  ///         unchanged); kNonFinite or kNotPositiveDefinite (filter unchanged).
  [[nodiscard]] Status update(const MeasVec& z, ChannelMask present) {
    GateConfig none;
    none.per_channel = false;
    none.ellipsoidal = false;
    return update_gated(z, present, none, measurement_.noise());
  }

  /// Gate the `present` channels of z (header comment) and update with the
  /// ones that pass, using the model's R.
  /// @return kOk (also when every channel was gated out: predict-only, see
  ///         diagnostics().state_changed); kNonFinite or kNotPositiveDefinite
  ///         (filter unchanged).
  [[nodiscard]] Status update_gated(const MeasVec& z, ChannelMask present, const GateConfig& gate) {
    return update_gated(z, present, gate, measurement_.noise());
  }

  /// As above with an explicit measurement noise R (off-diagonal terms
  /// between a kept and a dropped channel are ignored).
  [[nodiscard]] Status update_gated(const MeasVec& z, ChannelMask present, const GateConfig& gate,
                                    const MeasCov& R) {
    present &= kAllChannels;
    clear_diagnostics(present);
    const Lin lin = linearise(z, R, present);
    if (lin.status != Status::kOk) return fail(lin.status);
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
          diag_.gated_channel = with_channel(diag_.gated_channel, i);
        }
      }
    }

    // Optional ellipsoidal test of the kept set; peel the worst channel
    // while it fails. Each round removes one channel, so kMeasDim bounds it.
    if (gate.ellipsoidal) {
      for (int round = 0; round < kMeasDim; ++round) {
        const int m = channel_count(kept);
        if (m == 0) break;
        const Reduced red = reduce(lin, R, kept);
        const Eigen::LLT<MeasCov> llt(red.S);
        if (llt.info() != Eigen::Success) return fail(Status::kNotPositiveDefinite);
        const Scalar d2 = red.nu.dot(llt.solve(red.nu));
        const Scalar threshold = ScalarTraits<Scalar>::from_double(
            chi_square_quantile(m, gate.ellipsoid_probability));
        if (d2 <= threshold) break;
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
        diag_.gated_ellipsoid = with_channel(diag_.gated_ellipsoid, worst);
      }
    }

    if (kept == 0) {
      diag_.status = Status::kOk;  // every channel gated or absent: predict-only
      return Status::kOk;
    }
    return fuse(lin, R, kept);
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
  /// Linearisation at the current state, every channel.
  struct Lin {
    MeasVec nu;
    Jacobian H;
    MeasCov S;  ///< Padded over `present` (header comment).
    Status status;
  };
  /// The quantities of one update restricted to a channel set (padded).
  struct Reduced {
    MeasVec nu;
    Jacobian H;
    MeasCov R;
    MeasCov S;
  };

  Lin linearise(const MeasVec& z, const MeasCov& R, ChannelMask present) const {
    Lin lin{MeasVec::Zero(), Jacobian::Zero(), MeasCov::Identity(), Status::kOk};
    for (int i = 0; i < kMeasDim; ++i) {
      // Absent channels may hold anything (NaN included): only present ones are read.
      if (has_channel(present, i) && !ScalarTraits<Scalar>::is_finite(z(i))) {
        lin.status = Status::kNonFinite;
        return lin;
      }
    }
    if (!all_finite(R)) {
      lin.status = Status::kNonFinite;
      return lin;
    }
    const Jacobian H = measurement_.jacobian(x_);
    const MeasVec nu = measurement_.residual(z, measurement_.predict(x_));
    for (int i = 0; i < kMeasDim; ++i) {
      if (!has_channel(present, i)) continue;
      lin.nu(i) = nu(i);
      lin.H.row(i) = H.row(i);
    }
    if (!all_finite(lin.H) || !all_finite(lin.nu)) {
      lin.status = Status::kNonFinite;
      return lin;
    }
    lin.S = reduce(lin, R, present).S;
    if (!all_finite(lin.S)) lin.status = Status::kNonFinite;
    return lin;
  }

  /// nu, H, R and S = H P H^T + R with every channel outside `keep` removed
  /// (zero row in H, zero in nu, unit row/column in R and S).
  Reduced reduce(const Lin& lin, const MeasCov& R, ChannelMask keep) const {
    Reduced red{MeasVec::Zero(), Jacobian::Zero(), MeasCov::Zero(), MeasCov::Zero()};
    for (int i = 0; i < kMeasDim; ++i) {
      if (!has_channel(keep, i)) {
        red.R(i, i) = Scalar(1);
        continue;
      }
      red.nu(i) = lin.nu(i);
      red.H.row(i) = lin.H.row(i);
      for (int j = 0; j < kMeasDim; ++j) {
        if (has_channel(keep, j)) red.R(i, j) = R(i, j);
      }
    }
    red.S = symmetrised(red.H * P_ * red.H.transpose() + red.R);
    return red;
  }

  /// Joseph-form update with the channels in `keep` (non-empty).
  Status fuse(const Lin& lin, const MeasCov& R, ChannelMask keep) {
    const Reduced red = reduce(lin, R, keep);
    const Eigen::LLT<MeasCov> llt(red.S);
    if (llt.info() != Eigen::Success) return fail(Status::kNotPositiveDefinite);
    // K = P H^T S^-1 = (S^-1 H P)^T; removed channels give zero columns.
    const Mat<Scalar, kMeasDim, kStateDim> HP = red.H * P_;
    // One vector solve per column: a matrix right-hand side sends Eigen to
    // its blocked triangular solver, which references malloc (a board's
    // link-time heap guard rejects it); vector solves stay on the stack.
    Mat<Scalar, kMeasDim, kStateDim> SinvHP;
    for (int c = 0; c < kStateDim; ++c) SinvHP.col(c) = llt.solve(HP.col(c));
    const Mat<Scalar, kStateDim, kMeasDim> K = SinvHP.transpose();
    const State x = x_ + K * red.nu;
    const Cov A = Cov::Identity() - K * red.H;
    const Cov P = symmetrised(A * P_ * A.transpose() + K * red.R * K.transpose());
    if (const Status c = state_status(x, P); c != Status::kOk) return fail(c);
    x_ = x;
    P_ = P;
    diag_.fused = keep;
    diag_.nis = red.nu.dot(llt.solve(red.nu));
    diag_.state_changed = true;
    diag_.status = Status::kOk;
    return Status::kOk;
  }

  void clear_diagnostics(ChannelMask present) {
    diag_.innovation = MeasVec::Zero();
    diag_.innovation_variance = MeasVec::Zero();
    diag_.test_ratio = MeasVec::Zero();
    diag_.present = present;
    diag_.gated_channel = 0;
    diag_.gated_ellipsoid = 0;
    diag_.fused = 0;
    diag_.nis = Scalar(0);
    diag_.state_changed = false;
    diag_.status = Status::kOk;
  }

  Status fail(Status s) {
    diag_.status = s;
    diag_.fused = 0;
    diag_.state_changed = false;
    return s;
  }

  Motion motion_;
  Measurement measurement_;
  State x_;
  Cov P_;
  Diagnostics diag_{};
};

}  // namespace kestrel
