// SPDX-License-Identifier: Apache-2.0
// Single-point initiation from a multilateration fix (paper 003, section
// 3.3; docs/tracking.md and docs/scenarios.md, UW-003): one sonar frame, whose arrivals are
// labelled by beacon and path, fixes the position by robust
// multilateration (tracking/multilateration.hpp); the track's filter then
// starts from a wide prior centred on the fix and takes one update with the
// fix's inliers, which gives P the correlation of position with sound
// speed that the fix alone does not have. The outliers the fix rejected
// are recorded in the filter's diagnostics as present and rejected.
#pragma once

#include "kestrel/filters/channels.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"
#include "kestrel/tracking/multilateration.hpp"

namespace kestrel {

/// The filter's prior around the fix.
template <class Scalar>
struct MultilaterationStart {
  MultilaterationConfig<Scalar> fix{};                     ///< The fix; its sound speed is the initial c.
  Scalar position_sigma_m = lit<Scalar>(100.0);            ///< Prior sigma around the fix before the update, m.
  Scalar velocity_sigma_mps = lit<Scalar>(2.0);            ///< Initial velocity sigma (velocity starts at 0), m/s.
  Scalar sound_speed_sigma_mps = lit<Scalar>(1.0);         ///< Initial c sigma, m/s.
};

/// For a ChannelGatedEkf over a motion model with a position, a velocity
/// and a sound-speed component (Layout kPos, kVel, kC; e.g.
/// ConstantVelocity3DSoundSpeed) and a MultipathToa measurement.
template <class Scalar>
class MultilaterationInitiator {
 public:
  /// Tracker: one plot (one frame) starts an initialised track.
  static constexpr bool kSinglePoint = true;
  using Config = MultilaterationStart<Scalar>;

  MultilaterationInitiator() = default;
  explicit MultilaterationInitiator(const Config& config) : config_(config) {}

  /// Fix the `present` channels of z, then start `f` from it: reset to the
  /// prior around the fix, update with the inliers (no gate), record the
  /// rejected channels, keep the filter's state bound.
  /// @return kOk; the fix's status (kUnderdetermined, kNonFinite,
  ///         kNotPositiveDefinite, kNoConvergence, kAmbiguous); a filter
  ///         failure (kNonFinite, kNotPositiveDefinite). `f` is meaningful
  ///         only on kOk.
  template <class Filter>
  [[nodiscard]] Status start(Filter& f, const typename Filter::MeasVec& z, ChannelMask present) {
    using L = typename Filter::Layout;
    fix_ = multilaterate(f.measurement(), z, present, config_.fix);
    KESTREL_TRY(fix_.status);
    typename Filter::State x0 = Filter::State::Zero();
    for (int a = 0; a < 3; ++a) x0(L::kPos + a) = fix_.position_m(a);
    x0(L::kC) = config_.fix.sound_speed_mps;
    typename Filter::Cov P0 = Filter::Cov::Zero();
    const Scalar sp = config_.position_sigma_m;
    const Scalar sv = config_.velocity_sigma_mps;
    const Scalar sc = config_.sound_speed_sigma_mps;
    for (int a = 0; a < 3; ++a) {
      P0(L::kPos + a, L::kPos + a) = sp * sp;
      P0(L::kVel + a, L::kVel + a) = sv * sv;
    }
    P0(L::kC, L::kC) = sc * sc;
    KESTREL_TRY(f.reset(x0, P0));
    KESTREL_TRY(f.update(z, fix_.inliers));
    f.note_refused(present, fix_.rejected);
    return f.constrain();
  }

  /// The last fix attempted.
  const MultilaterationResult<Scalar>& last_fix() const { return fix_; }
  const Config& config() const { return config_; }

 private:
  Config config_{};
  MultilaterationResult<Scalar> fix_{};
};

}  // namespace kestrel
