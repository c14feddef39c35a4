// SPDX-License-Identifier: Apache-2.0
// The measurement noise a tracker's confirmed tracks fuse their plots with,
// chosen at compile time (Tracker's MeasurementNoise parameter):
// NominalMeasurementNoise uses R as the model gives it, with no state and no
// code (the default, and what every board builds); AdaptiveMeasurementNoise
// fuses each confirmed track under the robust gate with lambda R following
// its NIS (association/adaptive_noise.hpp), and needs a filter that takes a
// scaled R (ScalesMeasurementNoise: Ekf, Imm). Tracker::
// configure_measurement_noise() refuses with kOutOfRange any gain the
// tracker cannot honour (any but 0 under the nominal policy, or without the
// robust gate), so a value is never dropped silently. Nothing is decided at
// run time (docs/robustness.md, "Adaptive measurement noise").
#pragma once

#include <cstddef>
#include <cstdint>

#include "kestrel/association/adaptive_noise.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"

namespace kestrel {

/// What configure_measurement_noise() takes: the adaptive noise's rule.
template <class Scalar>
struct MeasurementNoiseConfig {
  /// alpha, the weight of each plot's NIS excess in lambda, in [0, 1]; 0: off.
  Scalar gain{};
  /// lambda's upper bound, >= 1 (1: off); R up to this factor.
  Scalar max_scale{};
};

/// R as the model gives it: the tracker calls none of this in its frame
/// (every use is under `if constexpr (kAdapts)`).
template <class Scalar, std::size_t kMaxTracks>
struct NominalMeasurementNoise {
  static constexpr bool kAdapts = false;

  /// kOk for a gain of 0 (nothing asked of it); kOutOfRange for any other
  /// gain (kNonFinite for a NaN or Inf): this tracker was built without the adaptive noise, so it cannot
  /// honour it (build it with AdaptiveMeasurementNoise).
  static Status check(const MeasurementNoiseConfig<Scalar>& p) {
    if (!ScalarTraits<Scalar>::is_finite(p.gain)) return Status::kNonFinite;
    return p.gain > Scalar(0) || p.gain < Scalar(0) ? Status::kOutOfRange : Status::kOk;
  }
};

/// Per-track lambda R under the robust gate (header comment). The tracker
/// calls start() when a slot takes a new track, scale() before fusing a
/// confirmed track's plot and after_plot() once it is fused.
template <class Scalar, std::size_t kMaxTracks>
class AdaptiveMeasurementNoise {
 public:
  static constexpr bool kAdapts = true;

  AdaptiveMeasurementNoise() {
    for (std::size_t i = 0; i < kMaxTracks; ++i) scale_[i] = Scalar(1);
  }

  /// kOk; kNonFinite (a parameter not finite); kOutOfRange (gain outside
  /// [0, 1], max_scale below 1).
  static Status check(const MeasurementNoiseConfig<Scalar>& p) {
    using T = ScalarTraits<Scalar>;
    if (!T::is_finite(p.gain) || !T::is_finite(p.max_scale)) return Status::kNonFinite;
    if (p.gain < Scalar(0) || p.gain > Scalar(1) || p.max_scale < Scalar(1)) return Status::kOutOfRange;
    return Status::kOk;
  }

  /// Takes p (after check(p)) with the chi-square gate's d2 as the NIS cap;
  /// a cap of 0 (the robust gate off) leaves the rule off.
  void configure(const MeasurementNoiseConfig<Scalar>& p, Scalar nis_cap) { rule_ = {p.gain, p.max_scale, nis_cap}; }

  /// true when the rule acts (gain in (0, 1], max_scale > 1, the robust gate on).
  bool enabled() const { return rule_.enabled(); }
  const AdaptiveNoise<Scalar>& rule() const { return rule_; }

  /// Slot `slot` holds a new (or restarted) track: lambda 1.
  void start(std::size_t slot) {
    if (slot < kMaxTracks) scale_[slot] = Scalar(1);
  }
  /// The lambda track `slot` fuses its next plot with, in [1, max_scale].
  Scalar scale(std::size_t slot) const { return slot < kMaxTracks ? rule_.clamped(scale_[slot]) : Scalar(1); }
  /// Track `slot` fused a plot of NIS `d2` (against lambda R) with `scale`.
  /// @param follows_hit the track took a plot in the previous frame: lambda
  ///        moves only then (a track that coasted, or that takes another
  ///        track's plot now and then, is not a noisy sensor).
  void after_plot(std::size_t slot, Scalar scale, Scalar d2, int channels, bool follows_hit) {
    if (scale > Scalar(1)) ++scaled_;
    if (slot < kMaxTracks && follows_hit) scale_[slot] = rule_.next(scale, d2, channels);
  }

  /// A new frame: the count of scaled updates starts again.
  void begin_frame() { scaled_ = 0; }
  /// Plots fused with lambda > 1 in the last frame (of StepStats::associated).
  std::uint16_t scaled_updates() const { return scaled_; }

 private:
  AdaptiveNoise<Scalar> rule_{};
  Scalar scale_[kMaxTracks];
  std::uint16_t scaled_ = 0;
};

}  // namespace kestrel
