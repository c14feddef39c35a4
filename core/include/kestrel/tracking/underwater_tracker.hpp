// SPDX-License-Identifier: Apache-2.0
// The underwater tracker of paper 003 (SPEC sections 3, 4, 6 and 9, UW-003):
// one target, a few beacons, each frame a set of TOA arrivals labelled by
// beacon and path (direct or seabed-reflected). The generic Tracker
// (tracking/tracker.hpp) associates unlabelled plots to many tracks; here
// the labels already say which channel each arrival is, so the front end is
// a small single-target step(frame) in the same style:
//
//   step(scan): validate -> not yet initialised: robust multilateration of
//   the frame (tracking/multilateration.hpp), then an EKF update with its
//   inliers from a wide prior (which gives P its position / sound-speed
//   correlation) -> initialised: predict to the frame time, per-channel gate
//   k*sqrt(S_ii) (and the optional ellipsoidal gate), update with the
//   channels that pass (predict-only when none does), widen P for what the
//   per-channel gate dropped -> keep the depth in the water -> report.
//
// State [x y z vx vy vz c] (models/motion/constant_velocity_3d_sound_speed.hpp),
// measurement models/measurement/multipath_toa.hpp, filter
// filters/channel_gated_ekf.hpp. Every non-kOk status leaves the tracker as
// it was (the step works on a copy of the 7-state filter and commits at the
// end); only the per-status counters move. No allocation, bounded loops.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>

#include "kestrel/filters/channel_gated_ekf.hpp"
#include "kestrel/math/finite.hpp"
#include "kestrel/models/measurement/multipath_toa.hpp"
#include "kestrel/models/motion/constant_velocity_3d_sound_speed.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"
#include "kestrel/tracking/elapsed.hpp"
#include "kestrel/tracking/frame_clock.hpp"
#include "kestrel/tracking/multilateration.hpp"
#include "kestrel/tracking/toa_scan.hpp"
#include "kestrel/tracking/track.hpp"

namespace kestrel {

/// Configuration of an UnderwaterTracker, in its scalar.
template <class Scalar, int kMaxBeacons>
struct UnderwaterTrackerConfig {
  ConstantVelocity3DSoundSpeed<Scalar> motion{};   ///< Process noise (accel sigma, c random walk).
  MultipathToaConfig<Scalar, kMaxBeacons> toa{};   ///< Beacons, seabed depth D, TOA sigma.
  ChannelGateConfig<Scalar> gate{};                ///< Per-channel k (default 2) and ellipsoidal option.
  MultilaterationConfig<Scalar> init{};            ///< First fix; its sound speed is the initial c.
  Scalar initial_position_sigma_m = lit<Scalar>(100.0);    ///< Prior sigma around the fix before its EKF update, m.
  Scalar initial_velocity_sigma_mps = lit<Scalar>(2.0);    ///< Initial velocity sigma (velocity starts at 0), m/s.
  Scalar initial_sound_speed_sigma_mps = lit<Scalar>(1.0); ///< Initial c sigma, m/s.
  Scalar max_toa_s = lit<Scalar>(10.0);            ///< Arrival times outside (0, max_toa_s] are out of range, s.
  /// Re-run the multilateration after this many frames in a row that carried
  /// at least init.min_arrivals arrivals but fused at most half of them
  /// (0: never). A track that is on the target gates out an arrival with
  /// probability about 0.05 at k = 2 (more with outliers), so half a frame
  /// gated out, frame after frame, means the gate has locked onto a wrong
  /// estimate and is throwing the data away.
  std::uint16_t reacquire_after_lost_frames = 3;
  /// Widen P for the channels the per-channel gate dropped (add_gate_truncation()).
  /// Without it the k = 2 gate, which drops the ~5 % of good arrivals with
  /// the largest innovations, leaves P too small (uw003-clean, 200 runs:
  /// position NEES 3.66 without, 2.99 with, for 3 degrees of freedom) and
  /// depth drifts (docs/underwater.md).
  bool gate_truncation_covariance = true;
  /// Keep the depth estimate within [init.depth_margin_m, D - that] by
  /// projecting the state onto the bound (project_depth()).
  bool project_depth = true;
  /// A frame more than this after the last one restarts the track from a
  /// fresh fix instead of predicting across the gap, us. Default 60 s.
  std::int64_t max_predict_us = 60'000'000;
  /// A frame later than the last accepted one by more than this is refused
  /// (kTimeJumpedForward), us. Default 10 min. The same rule as Tracker's.
  std::int64_t max_forward_jump_us = 600'000'000;
  /// Frames refused for their time (backwards or a jump) that agree with
  /// each other, in a row, after which the tracker takes their clock and
  /// restarts from a fresh fix (0: never).
  std::uint8_t resync_frames = 3;
};

/// What one step did (readable after step()).
struct UnderwaterStepStats {
  Status status = Status::kOk;  ///< Return value of the step.
  std::uint8_t arrivals = 0;    ///< Arrivals in the frame.
  std::uint8_t fused = 0;       ///< Arrivals that went into the update.
  std::uint8_t gated_out = 0;   ///< Dropped by a gate (or rejected by the multilateration on a fix).
  ChannelMask present = 0;      ///< Channels the frame carried (channel = 2 beacon + path).
  ChannelMask fused_mask = 0;   ///< Channels fused.
  ChannelMask gated_mask = 0;   ///< Channels dropped by a gate or rejected by the fix.
  bool initialised = false;     ///< This frame (re)started the track from a multilateration fix.
  bool predict_only = false;    ///< Tracked frame with nothing fused.
  bool resynced = false;        ///< This frame's clock replaced the old one (resync rule).
};

/// Running totals since construction.
struct UnderwaterCounters {
  std::uint32_t frames_ok = 0;        ///< Steps that returned kOk.
  std::uint32_t initialisations = 0;  ///< Fixes that (re)started the track (first one included).
  std::uint32_t arrivals = 0;         ///< Arrivals in kOk frames.
  std::uint32_t fused = 0;            ///< Arrivals fused.
  std::uint32_t gated_out = 0;        ///< Arrivals gated out or rejected by a fix.
  std::uint32_t predict_only = 0;     ///< Tracked frames with nothing fused.
  std::uint32_t resyncs = 0;          ///< Clock changes taken by the resync rule.
  std::uint32_t rejected[kStatusCount] = {};  ///< Steps refused, per status.
};

template <class Scalar, int kMaxBeacons = 4, std::size_t kMaxArrivals = 2 * static_cast<std::size_t>(kMaxBeacons)>
class UnderwaterTracker {
 public:
  using Motion = ConstantVelocity3DSoundSpeed<Scalar>;
  using Toa = MultipathToa<Motion, kMaxBeacons>;
  using Filter = ChannelGatedEkf<Motion, Toa>;
  using Layout = typename Motion::Layout;
  using State = typename Filter::State;
  using Cov = typename Filter::Cov;
  using MeasVec = typename Filter::MeasVec;
  using Scan = ToaScan<Scalar, kMaxArrivals>;
  /// Every tracker's report (tracking/track.hpp): x = [x y z vx vy vz c]
  /// (m, m, m depth down, m/s x3, m/s); one confirmed track whose id
  /// changes at every (re)initialisation (age 0 on that frame); fusion per
  /// channel (channel = 2 beacon + path): innovation, variance, the
  /// per-channel gate's test ratio, present / rejected (by a gate, or by
  /// the fix on an initialisation) / fused; nis = fusion.nis and
  /// test_ratio 0 (the labels associate, no gate on the whole frame).
  using Report = TrackReport<Filter>;
  using Config = UnderwaterTrackerConfig<Scalar, kMaxBeacons>;
  static_assert(Motion::kStateDim == 7, "report layout");
  static_assert(kMaxArrivals <= 255, "per-frame counts are uint8");

  explicit UnderwaterTracker(const Config& config)
      : config_(config), clock_(config.max_forward_jump_us, config.resync_frames) {
    Toa toa;
    toa.config = config.toa;
    filter_ = Filter(config.motion, toa);
    // Constants of the per-channel gate's truncation, once, in double:
    // tail = Pr(|u| > k) = erfc(k / sqrt 2) for u ~ N(0, 1) and
    // excess = E[u^2 | |u| > k] - 1 = k phi(k) / Q(k), Q(k) = tail / 2
    // (0.0455 and 4.75 at k = 2; 0.0027 and 9.85 at k = 3).
    const double k = ScalarTraits<Scalar>::to_double(config.gate.k_sigma);
    const double tail = std::erfc(k / std::sqrt(2.0));
    const double phi = std::exp(-0.5 * k * k) / std::sqrt(2.0 * 3.14159265358979323846);
    gate_tail_ = ScalarTraits<Scalar>::from_double(tail);
    gate_excess_ = ScalarTraits<Scalar>::from_double(tail > 0.0 ? 2.0 * k * phi / tail : 0.0);
  }

  /// Process one frame.
  /// @return kOk (tracked, predict-only, or initialised: see last_step());
  ///   frame checks, in this order: kMalformedFrame (count over capacity,
  ///   unknown path, two arrivals on one channel), kTimeWentBackwards,
  ///   kTimeJumpedForward (later than the last frame by more than
  ///   max_forward_jump_us), kNonFinite (an arrival time), kOutOfRange
  ///   (beacon not configured, time outside (0, max_toa_s]);
  ///   before initialisation, the fix's status: kUnderdetermined,
  ///   kNotPositiveDefinite, kNoConvergence, kAmbiguous;
  ///   filter failures: kNonFinite, kNotPositiveDefinite.
  ///   On any non-kOk status the tracker is unchanged and reports() is empty;
  ///   only the count of consecutive off-clock frames moves: resync_frames
  ///   of them in a row, each at or after the previous and within
  ///   max_forward_jump_us of it, restart the track from a fix on their
  ///   clock (last_step().resynced, counters().resyncs).
  [[nodiscard]] Status step(const Scan& scan) {
    stats_ = UnderwaterStepStats{};
    report_count_ = 0;
    MeasVec z = MeasVec::Zero();
    ChannelMask present = 0;
    Status valid = validate(scan, z, present, true);
    // A frame refused only for its time counts toward the resync rule;
    // taking the new clock commits only if the frame then gives a fix.
    bool resync = false;
    if (valid == Status::kTimeWentBackwards || valid == Status::kTimeJumpedForward) {
      z.setZero();
      present = 0;
      if (validate(scan, z, present, false) == Status::kOk && clock_.off_clock(scan.t_us)) {
        resync = true;
        valid = Status::kOk;
      }
    }
    if (valid != Status::kOk) return refuse(valid);
    stats_.arrivals = static_cast<std::uint8_t>(scan.count);
    stats_.present = present;

    Filter next = filter_;
    std::uint16_t lost_frames = lost_frames_;
    const std::int64_t gap_us = initialised_ && !resync ? elapsed_us(scan.t_us, clock_.last_us()) : 0;
    if (!initialised_ || resync || gap_us > config_.max_predict_us) {
      const Status s = initialise(next, z, present);
      if (s != Status::kOk) return refuse(s);
      lost_frames = 0;
    } else {
      const Scalar dt = ScalarTraits<Scalar>::from_ratio(gap_us, 1000000);
      Status s = next.predict(dt);
      const State x_pred = next.x();
      if (s == Status::kOk) s = next.update_gated(z, present, config_.gate);
      if (s == Status::kOk && config_.gate_truncation_covariance && dropped_by_channel_gate(next) != 0) {
        s = add_gate_truncation(next, x_pred, channel_count(present));
      }
      if (s != Status::kOk) return refuse(s);
      const auto& d = next.diagnostics();
      stats_.fused_mask = d.fused_channels;
      stats_.gated_mask = d.rejected;
      stats_.fused = static_cast<std::uint8_t>(channel_count(d.fused_channels));
      stats_.gated_out = static_cast<std::uint8_t>(channel_count(stats_.gated_mask));
      stats_.predict_only = d.fused_channels == 0;
      lost_frames = 0;
      const int arrivals = channel_count(present);
      if (arrivals >= static_cast<int>(config_.init.min_arrivals) && 2 * static_cast<int>(stats_.fused) <= arrivals) {
        lost_frames = static_cast<std::uint16_t>(lost_frames_ < UINT16_MAX ? lost_frames_ + 1 : lost_frames_);
        // Lost: most of what full frames said was outside the gate, several
        // frames running. Start again from this frame if its fix explains
        // more arrivals than the track fused.
        if (config_.reacquire_after_lost_frames > 0 && lost_frames >= config_.reacquire_after_lost_frames) {
          Filter fresh = next;
          const UnderwaterStepStats tracked = stats_;
          if (initialise(fresh, z, present) == Status::kOk && stats_.fused > tracked.fused) {
            next = fresh;
            lost_frames = 0;
          } else {
            stats_ = tracked;
          }
        }
      }
    }

    if (config_.project_depth) {
      const Status s = project_depth(next);
      if (s != Status::kOk) return refuse(s);
    }
    if (stats_.initialised) {
      track_id_ = track_id_ < UINT32_MAX ? track_id_ + 1 : 1;
      age_ = 0;
      hits_ = 0;
      misses_ = 0;
    } else {
      age_ = static_cast<std::uint16_t>(age_ < UINT16_MAX ? age_ + 1 : age_);
    }
    if (stats_.fused > 0) {
      hits_ = static_cast<std::uint16_t>(hits_ < UINT16_MAX ? hits_ + 1 : hits_);
      misses_ = 0;
    } else {
      misses_ = static_cast<std::uint16_t>(misses_ < UINT16_MAX ? misses_ + 1 : misses_);
    }
    filter_ = next;
    initialised_ = true;
    lost_frames_ = lost_frames;
    clock_.accept(scan.t_us, resync);
    stats_.status = Status::kOk;
    stats_.resynced = resync;
    counters_.resyncs = clock_.resyncs();
    ++counters_.frames_ok;
    counters_.arrivals += stats_.arrivals;
    counters_.fused += stats_.fused;
    counters_.gated_out += stats_.gated_out;
    if (stats_.predict_only) ++counters_.predict_only;
    if (stats_.initialised) ++counters_.initialisations;

    Report& r = reports_[0];
    r.t_us = scan.t_us;
    r.track_id = track_id_;
    r.status = TrackStatus::kConfirmed;
    r.age = age_;
    r.hits = hits_;
    r.misses = misses_;
    r.associated = stats_.fused > 0;
    r.measurement_index = r.associated ? std::int16_t{0} : std::int16_t{-1};
    r.fusion = filter_.diagnostics();
    if (stats_.initialised) {  // the fix chose the channels; the update had only its inliers
      r.fusion.present = stats_.present;
      r.fusion.rejected = stats_.gated_mask;
    }
    r.nis = r.fusion.nis;  // no association gate: the update's NIS
    r.test_ratio = Scalar(0);
    r.score = Scalar(0);
    r.x = filter_.x();
    r.P = filter_.P();
    report_count_ = 1;
    return Status::kOk;
  }

  /// The report of the last kOk step (one), or nothing.
  std::span<const Report> reports() const { return {reports_, report_count_}; }
  const UnderwaterStepStats& last_step() const { return stats_; }
  const UnderwaterCounters& counters() const { return counters_; }
  /// The filter (state, covariance, per-channel diagnostics of the last update).
  const Filter& filter() const { return filter_; }
  /// The multilateration result of the last fix attempt.
  const MultilaterationResult<Scalar>& last_fix() const { return fix_; }
  bool initialised() const { return initialised_; }
  const Config& config() const { return config_; }

 private:
  Status refuse(Status s) {
    stats_ = UnderwaterStepStats{};
    stats_.status = s;
    report_count_ = 0;
    ++counters_.rejected[static_cast<std::size_t>(s)];
    return s;
  }

  /// Frame checks; fills the channel vector and mask on success. The time
  /// against the last accepted frame is checked only when check_time.
  Status validate(const Scan& scan, MeasVec& z, ChannelMask& present, bool check_time) const {
    using T = ScalarTraits<Scalar>;
    if (scan.count > kMaxArrivals) return Status::kMalformedFrame;
    for (std::size_t i = 0; i < kMaxArrivals; ++i) {
      if (i >= scan.count) break;
      const auto& a = scan.arrivals[i];
      if (a.path != ArrivalPath::kDirect && a.path != ArrivalPath::kReflected) return Status::kMalformedFrame;
      if (a.beacon >= kMaxBeacons) continue;  // out of range, reported below
      const int ch = Toa::channel(a.beacon, a.path);
      if (has_channel(present, ch)) return Status::kMalformedFrame;
      present = with_channel(present, ch);
    }
    if (check_time) {
      if (const Status s = clock_.check(scan.t_us); s != Status::kOk) return s;
    }
    for (std::size_t i = 0; i < kMaxArrivals; ++i) {
      if (i >= scan.count) break;
      if (!T::is_finite(scan.arrivals[i].toa_s)) return Status::kNonFinite;
    }
    for (std::size_t i = 0; i < kMaxArrivals; ++i) {
      if (i >= scan.count) break;
      const auto& a = scan.arrivals[i];
      if (a.beacon >= config_.toa.beacon_count || a.beacon >= kMaxBeacons) return Status::kOutOfRange;
      if (!(a.toa_s > Scalar(0)) || a.toa_s > config_.max_toa_s) return Status::kOutOfRange;
      z(Toa::channel(a.beacon, a.path)) = a.toa_s;
    }
    return Status::kOk;
  }

  /// The channels the per-channel gate dropped in the last update (its
  /// test ratio over 1), not those the ellipsoidal gate peeled.
  static ChannelMask dropped_by_channel_gate(const Filter& f) {
    const auto& d = f.diagnostics();
    ChannelMask m = 0;
    for (int i = 0; i < Filter::kMeasDim; ++i) {
      if (has_channel(d.rejected, i) && d.test_ratio(i) > Scalar(1)) m = with_channel(m, i);
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
  /// predicted state, weighted by the probability that a gated arrival is
  /// good, Pr(good, gated) / Pr(gated) <= tail / (gated fraction so far)
  /// (1 when nothing but noise is gated, about 0.45 with UW-003's 5 %
  /// outliers), capped at 1. The mean is left alone (a two-sided gate says
  /// nothing about the sign). The kept channels need no correction: the
  /// update conditions on their values. Only channels dropped by the
  /// per-channel gate count; the ellipsoidal gate's are left as they are.
  Status add_gate_truncation(Filter& f, const State& x_pred, int arrivals_now) const {
    const ChannelMask gated = dropped_by_channel_gate(f);
    const auto H = f.measurement().jacobian(x_pred);
    const auto R = f.measurement().noise();
    // Running totals including this frame (counters_ moves at the commit).
    const std::int64_t arrivals = static_cast<std::int64_t>(counters_.arrivals) + arrivals_now;
    const std::int64_t dropped = static_cast<std::int64_t>(counters_.gated_out) + channel_count(gated);
    Scalar good = gate_tail_ * ScalarTraits<Scalar>::from_ratio(arrivals, dropped);
    if (good > Scalar(1)) good = Scalar(1);
    const Scalar w = good * gate_excess_;
    const Cov& P = f.P();
    Cov widened = P;
    for (int i = 0; i < Filter::kMeasDim; ++i) {
      if (!has_channel(gated, i)) continue;
      const State g = P * H.row(i).transpose();
      const Scalar s_i = H.row(i).dot(g) + R(i, i);
      widened += (w / s_i) * (g * g.transpose());
    }
    return f.reset(f.x(), widened);
  }

  /// The water lies between the surface and the seabed; a linearised update
  /// can still put the estimate outside, typically above the surface at the
  /// mirror image of the target that the direct arrivals cannot tell apart
  /// (2 of 200 uw003 first updates land at -32 and -7 m; direct-only runs
  /// stay there). Project the state onto the violated bound along P
  /// (x -= P e (e^T x - bound) / P_zz, e the depth axis: the estimate
  /// projection of a linear inequality constraint, which also moves x, y, c
  /// by their correlation with depth); P is kept, which is conservative.
  Status project_depth(Filter& f) const {
    const Scalar lo = config_.init.depth_margin_m;
    const Scalar hi = config_.toa.seabed_depth_m - config_.init.depth_margin_m;
    const Scalar z = f.x()(Layout::kZ);
    if (!(z < lo) && !(z > hi)) return Status::kOk;
    const Scalar bound = z < lo ? lo : hi;
    const Cov& P = f.P();
    const Scalar pzz = P(Layout::kZ, Layout::kZ);
    if (!(pzz > Scalar(0))) return Status::kNotPositiveDefinite;
    State x = f.x() - P.col(Layout::kZ) * ((z - bound) / pzz);
    x(Layout::kZ) = bound;  // exact, whatever the rounding
    return f.reset(x, P);
  }

  /// Fix by multilateration, then one EKF update with the fix's inliers from
  /// a wide prior centred on it. Works on `f`; records the fix in fix_.
  Status initialise(Filter& f, const MeasVec& z, ChannelMask present) {
    fix_ = multilaterate(f.measurement(), z, present, config_.init);
    if (fix_.status != Status::kOk) return fix_.status;
    State x0 = State::Zero();
    x0(Layout::kX) = fix_.position_m(0);
    x0(Layout::kY) = fix_.position_m(1);
    x0(Layout::kZ) = fix_.position_m(2);
    x0(Layout::kC) = config_.init.sound_speed_mps;
    Cov P0 = Cov::Zero();
    const Scalar sp = config_.initial_position_sigma_m;
    const Scalar sv = config_.initial_velocity_sigma_mps;
    const Scalar sc = config_.initial_sound_speed_sigma_mps;
    for (int a = 0; a < 3; ++a) {
      P0(Layout::kPos + a, Layout::kPos + a) = sp * sp;
      P0(Layout::kVel + a, Layout::kVel + a) = sv * sv;
    }
    P0(Layout::kC, Layout::kC) = sc * sc;
    Status s = f.reset(x0, P0);
    if (s == Status::kOk) s = f.update(z, fix_.inliers);
    if (s != Status::kOk) return s;
    stats_.initialised = true;
    stats_.fused_mask = fix_.inliers;
    stats_.gated_mask = fix_.rejected;
    stats_.fused = static_cast<std::uint8_t>(channel_count(fix_.inliers));
    stats_.gated_out = static_cast<std::uint8_t>(channel_count(fix_.rejected));
    stats_.predict_only = false;
    return Status::kOk;
  }

  Config config_;
  Filter filter_{};
  MultilaterationResult<Scalar> fix_{};
  Scalar gate_tail_{};    ///< Pr(|u| > k), u ~ N(0, 1), k = config.gate.k_sigma.
  Scalar gate_excess_{};  ///< E[u^2 | |u| > k] - 1.
  UnderwaterStepStats stats_{};
  UnderwaterCounters counters_{};
  Report reports_[1]{};
  std::size_t report_count_ = 0;
  FrameClock clock_{};  ///< Last accepted frame's time and the time-fault rules.
  std::uint16_t lost_frames_ = 0;  ///< Consecutive lost frames (reacquire_after_lost_frames).
  std::uint32_t track_id_ = 0;     ///< Id of the current track (a new one per initialisation, from 1).
  std::uint16_t age_ = 0;          ///< Frames since the track's initialisation.
  std::uint16_t hits_ = 0;         ///< Frames that fused an arrival since then.
  std::uint16_t misses_ = 0;       ///< Consecutive predict-only frames.
  bool initialised_ = false;
};

/// Parameters of the underwater tracker in SI units (double), with the
/// defaults of SPEC section 9, UW-003, and its "filter defaults that a check
/// found workable". make_underwater_tracker() turns them into a Config.
struct UnderwaterTrackerParams {
  static constexpr int kMaxBeacons = 8;  ///< 8 beacons x 2 paths = hal::kMaxToaArrivals.
  double beacons_m[kMaxBeacons][3] = {{0, 0, 0}, {2000, 0, 0}, {0, 2000, 0}, {2000, 2000, 0}};  ///< [x, y, depth], m.
  std::uint8_t beacon_count = 4;              ///< Beacons in use.
  double seabed_depth_m = 150.0;              ///< D, m.
  double sigma_toa_s = 3e-3;                  ///< TOA noise sigma, s.
  double accel_sigma_mps2 = 0.05;             ///< White acceleration per axis, m/s^2.
  /// c random walk: sigma after 1 s, m/s. UW-003's truth walks 0.3 m/s per
  /// 1 s step (clamped to 1500 +- 2), i.e. 0.3 m/s per sqrt(s); SPEC 9's
  /// "workable" 0.1 is a third of that (a ninth of the variance).
  double sound_speed_sigma_mps_per_sqrt_s = 0.3;
  double initial_sound_speed_mps = 1500.0;    ///< c of the first fix and of the filter start, m/s.
  double initial_sound_speed_sigma_mps = 1.0; ///< Initial c sigma, m/s.
  double initial_velocity_sigma_mps = 2.0;    ///< Initial velocity sigma per axis, m/s.
  double initial_position_sigma_m = 100.0;    ///< Prior position sigma before the first update, m.
  double gate_k_sigma = 2.0;                  ///< Per-channel gate multiplier k (paper: 2).
  bool per_channel_gate = true;               ///< Per-channel gate on/off.
  bool ellipsoidal_gate = false;              ///< Ellipsoidal gate on/off.
  GateProbability ellipsoid_probability = GateProbability::k99;  ///< Its probability.
  double reject_sigma = 3.0;                  ///< Multilateration rejection threshold, sigma.
  double max_toa_s = 10.0;                    ///< Largest plausible arrival time, s.
  std::uint16_t reacquire_after_lost_frames = 3;  ///< Frames fusing at most half their arrivals; 0: never re-run the fix.
  bool gate_truncation_covariance = true;         ///< Widen P for channels the per-channel gate dropped.
  bool project_depth = true;                      ///< Keep the depth estimate within (0, D).
  std::int64_t max_predict_us = 60'000'000;        ///< Longer gaps restart from a fresh fix, us.
  std::int64_t max_forward_jump_us = 600'000'000;  ///< Later frames are refused (kTimeJumpedForward), us.
  std::uint8_t resync_frames = 3;                  ///< Consistent refused frames that move the clock (0: never).
};

/// Tracker configuration from the parameters. Beacons past kMaxBeacons are ignored.
template <class Scalar, int kMaxBeacons>
UnderwaterTrackerConfig<Scalar, kMaxBeacons> underwater_tracker_config(const UnderwaterTrackerParams& p) {
  using T = ScalarTraits<Scalar>;
  UnderwaterTrackerConfig<Scalar, kMaxBeacons> c;
  c.motion.accel_sigma_mps2 = T::from_double(p.accel_sigma_mps2);
  c.motion.sound_speed_q_m2ps3 = T::from_double(p.sound_speed_sigma_mps_per_sqrt_s * p.sound_speed_sigma_mps_per_sqrt_s);
  const int n = p.beacon_count < kMaxBeacons ? p.beacon_count : kMaxBeacons;
  c.toa.beacon_count = static_cast<std::uint8_t>(n);
  for (int i = 0; i < kMaxBeacons; ++i) {
    if (i >= n) break;
    c.toa.beacons_m[i] = Vec<Scalar, 3>(T::from_double(p.beacons_m[i][0]), T::from_double(p.beacons_m[i][1]),
                                        T::from_double(p.beacons_m[i][2]));
  }
  c.toa.seabed_depth_m = T::from_double(p.seabed_depth_m);
  c.toa.sigma_toa_s = T::from_double(p.sigma_toa_s);
  c.gate.per_channel = p.per_channel_gate;
  c.gate.k_sigma = T::from_double(p.gate_k_sigma);
  c.gate.ellipsoidal = p.ellipsoidal_gate;
  c.gate.ellipsoid_probability = p.ellipsoid_probability;
  c.init.sound_speed_mps = T::from_double(p.initial_sound_speed_mps);
  c.init.reject_sigma = T::from_double(p.reject_sigma);
  c.initial_position_sigma_m = T::from_double(p.initial_position_sigma_m);
  c.initial_velocity_sigma_mps = T::from_double(p.initial_velocity_sigma_mps);
  c.initial_sound_speed_sigma_mps = T::from_double(p.initial_sound_speed_sigma_mps);
  c.max_toa_s = T::from_double(p.max_toa_s);
  c.reacquire_after_lost_frames = p.reacquire_after_lost_frames;
  c.gate_truncation_covariance = p.gate_truncation_covariance;
  c.project_depth = p.project_depth;
  c.max_predict_us = p.max_predict_us;
  c.max_forward_jump_us = p.max_forward_jump_us;
  c.resync_frames = p.resync_frames;
  return c;
}

/// The underwater tracker with the given parameters.
template <class Scalar, int kMaxBeacons = 4>
UnderwaterTracker<Scalar, kMaxBeacons> make_underwater_tracker(const UnderwaterTrackerParams& p) {
  return UnderwaterTracker<Scalar, kMaxBeacons>(underwater_tracker_config<Scalar, kMaxBeacons>(p));
}

}  // namespace kestrel
