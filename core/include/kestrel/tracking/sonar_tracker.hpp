// SPDX-License-Identifier: Apache-2.0
// The sonar tracker of paper 003 (UW-003): one target, a few beacons,
// each frame a set of TOA arrivals labelled by beacon and path (direct or
// seabed-reflected). It is the one Tracker (tracking/tracker.hpp) composed
// for a labelled sensor: ChannelGatedEkf, MultilaterationInitiator,
// LabelledAssociation and ReacquireWhenLost, with one track and one
// measurement (the frame as one ChannelScan entry, channel = 2 beacon +
// path). What is left here is the sonar's front end: labels become channels
// (the checks that need the beacon table), and the step's summary. State
// [x y z vx vy vz c], measurement models/measurement/multipath_toa.hpp; no
// allocation, bounded loops. Parts and step: docs/sonar.md, "Front end:
// SonarTracker::step(scan)".
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>

#include "kestrel/association/labelled.hpp"
#include "kestrel/filters/channel_gated_ekf.hpp"
#include "kestrel/models/measurement/multipath_toa.hpp"
#include "kestrel/models/motion/constant_velocity_3d_sound_speed.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"
#include "kestrel/tracking/multilateration.hpp"
#include "kestrel/tracking/multilateration_initiator.hpp"
#include "kestrel/tracking/reacquire_when_lost.hpp"
#include "kestrel/tracking/toa_scan.hpp"
#include "kestrel/tracking/track.hpp"
#include "kestrel/tracking/tracker.hpp"

namespace kestrel {

/// Configuration of a SonarTracker, in its scalar.
template <class Scalar, int kMaxBeacons>
struct SonarTrackerConfig {
  ConstantVelocity3DSoundSpeed<Scalar> motion{};   ///< Process noise (accel sigma, c random walk).
  MultipathToaConfig<Scalar, kMaxBeacons> toa{};   ///< Beacons, seabed depth D, TOA sigma.
  ChannelGateConfig<Scalar> gate{};                ///< Per-channel k (default 2) and ellipsoidal option (its widen_for_dropped is gate_truncation_covariance).
  MultilaterationConfig<Scalar> init{};            ///< First fix; its sound speed is the initial c.
  Scalar initial_position_sigma_m = lit<Scalar>(100.0);    ///< Prior sigma around the fix before its EKF update, m.
  Scalar initial_velocity_sigma_mps = lit<Scalar>(2.0);    ///< Initial velocity sigma (velocity starts at 0), m/s.
  Scalar initial_sound_speed_sigma_mps = lit<Scalar>(1.0); ///< Initial c sigma, m/s.
  Scalar max_toa_s = lit<Scalar>(10.0);            ///< Arrival times outside (0, max_toa_s] are out of range, s.
  /// Re-run the multilateration after this many frames in a row that carried
  /// at least init.min_arrivals arrivals but fused at most half of them
  /// (0: never; ReacquireWhenLost). A track that is on the target gates out an arrival with
  /// probability about 0.05 at k = 2 (more with outliers), so half a frame
  /// gated out, frame after frame, means the gate has locked onto a wrong
  /// estimate and is throwing the data away.
  std::uint16_t reacquire_after_lost_frames = 3;
  /// Widen P for the channels the per-channel gate dropped
  /// (ChannelGateConfig::widen_for_dropped).
  /// Without it the k = 2 gate, which drops the ~5 % of good arrivals with
  /// the largest innovations, leaves P too small (uw003-clean, 200 runs:
  /// position NEES 3.66 without, 2.99 with, for 3 degrees of freedom) and
  /// depth drifts (docs/sonar.md).
  bool gate_truncation_covariance = true;
  /// Keep the depth estimate within [init.depth_margin_m, D - that] by
  /// projecting the state onto the bound (ChannelGatedEkf::constrain()).
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
struct SonarStepStats {
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
struct SonarCounters {
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
class SonarTracker {
 public:
  using Motion = ConstantVelocity3DSoundSpeed<Scalar>;
  using Toa = MultipathToa<Motion, kMaxBeacons>;
  using Filter = ChannelGatedEkf<Motion, Toa>;
  using Initiator = MultilaterationInitiator<Scalar>;
  using Core = Tracker<Filter, Initiator, 1, 1, LabelledAssociation, ReacquireWhenLost>;
  using Layout = typename Motion::Layout;
  using State = typename Filter::State;
  using Cov = typename Filter::Cov;
  using MeasVec = typename Filter::MeasVec;
  using Scan = ToaScan<Scalar, kMaxArrivals>;
  /// Every tracker's report (tracking/track.hpp): x = [x y z vx vy vz c]
  /// (m, m, m depth down, m/s x3, m/s); one confirmed track whose id
  /// changes at every (re)start (age 0 on that frame); fusion per channel
  /// (channel = 2 beacon + path): innovation, variance, the per-channel
  /// gate's test ratio, present / rejected (by a gate, or by the fix on a
  /// start) / fused; nis = fusion.nis and test_ratio 0 (the labels
  /// associate; no gate on the whole frame); measurement_index 0 (the
  /// frame), with associated false when the gate dropped every channel.
  using Report = TrackReport<Filter>;
  using Config = SonarTrackerConfig<Scalar, kMaxBeacons>;
  static_assert(Motion::kStateDim == 7, "report layout");
  static_assert(kMaxArrivals <= 255, "per-frame counts are uint8");

  explicit SonarTracker(const Config& config)
      : config_(config), core_(prototype(config), Initiator(start_config(config)), core_config(config),
                               ReacquireWhenLost<Scalar>(reacquire_params(config))) {}

  /// Process one frame.
  /// @return kOk (tracked, predict-only, or (re)started: see last_step());
  ///   frame checks, in this order, which leave the tracker as it was (only
  ///   the count of consecutive off-clock frames moves): kMalformedFrame
  ///   (count over capacity, unknown path, two arrivals on one channel),
  ///   kNonFinite (an arrival time), kOutOfRange (beacon not configured,
  ///   time outside (0, max_toa_s]), kTimeWentBackwards,
  ///   kTimeJumpedForward (later than the last frame by more than
  ///   max_forward_jump_us); resync_frames such time faults in a row, each
  ///   at or after the previous and within max_forward_jump_us of it,
  ///   restart the track on their clock (last_step().resynced);
  ///   a frame that passed them but left no track: the fix's status
  ///   (kUnderdetermined, kNotPositiveDefinite, kNoConvergence,
  ///   kAmbiguous) when none could start, or the filter's (kNonFinite,
  ///   kNotPositiveDefinite) when the track's update failed and the
  ///   tracker's health rule deleted it; the frame's time was taken.
  ///   reports() is empty after any non-kOk status.
  [[nodiscard]] Status step(const Scan& scan) {
    stats_ = SonarStepStats{};
    reported_ = false;
    ChannelFrame frame;
    KESTREL_TRY_OR(refuse, to_channels(scan, frame));
    KESTREL_TRY_OR(refuse, core_.step(frame));
    const StepStats& cs = core_.last_step();
    const std::span<const Report> r = core_.reports();
    if (r.empty()) return refuse(cs.failure != Status::kOk ? cs.failure : Status::kNotInitialised);

    const FusionDiagnostics<Scalar, Filter::kMeasDim>& d = r[0].fusion;
    stats_.status = Status::kOk;
    stats_.arrivals = static_cast<std::uint8_t>(scan.count);
    stats_.present = frame.present[0];
    stats_.initialised = cs.seeded > 0 || cs.restarted > 0;
    stats_.resynced = cs.resynced;
    stats_.fused_mask = d.fused_channels;
    stats_.gated_mask = d.rejected;
    stats_.fused = static_cast<std::uint8_t>(channel_count(d.fused_channels));
    stats_.gated_out = static_cast<std::uint8_t>(channel_count(d.rejected));
    stats_.predict_only = !stats_.initialised && d.fused_channels == 0;
    ++counters_.frames_ok;
    counters_.arrivals += stats_.arrivals;
    counters_.fused += stats_.fused;
    counters_.gated_out += stats_.gated_out;
    if (stats_.predict_only) ++counters_.predict_only;
    if (stats_.initialised) ++counters_.initialisations;
    counters_.resyncs = core_.resyncs();
    reported_ = true;
    return Status::kOk;
  }

  /// The report of the last kOk step (one), or nothing.
  std::span<const Report> reports() const { return reported_ ? core_.reports() : std::span<const Report>{}; }
  const SonarStepStats& last_step() const { return stats_; }
  const SonarCounters& counters() const { return counters_; }
  /// The track's filter (state, covariance, per-channel diagnostics of the
  /// last update); the prototype before the first fix.
  const Filter& filter() const {
    for (const std::size_t i : core_.tracks().active_slots()) return core_.tracks()[i].filter;
    return prototype_;
  }
  /// The multilateration result of the last fix attempt.
  const MultilaterationResult<Scalar>& last_fix() const { return core_.initiator().last_fix(); }
  /// A track is held (a fix started it and no rule has deleted it).
  bool initialised() const { return core_.tracks().size() > 0; }
  const Config& config() const { return config_; }
  /// The composed tracker (its statistics and track table).
  const Core& core() const { return core_; }

 private:
  using ChannelFrame = typename Core::Scan;

  static Filter prototype(const Config& c) {
    Toa toa;
    toa.config = c.toa;
    ChannelGateConfig<Scalar> gate = c.gate;
    gate.widen_for_dropped = c.gate_truncation_covariance;
    StateBound<Scalar> bound;
    if (c.project_depth) {
      bound.index = Layout::kZ;
      bound.lo = c.init.depth_margin_m;
      bound.hi = c.toa.seabed_depth_m - c.init.depth_margin_m;
    }
    return Filter(c.motion, toa, gate, bound);
  }

  static MultilaterationStart<Scalar> start_config(const Config& c) {
    MultilaterationStart<Scalar> m;
    m.fix = c.init;
    m.position_sigma_m = c.initial_position_sigma_m;
    m.velocity_sigma_mps = c.initial_velocity_sigma_mps;
    m.sound_speed_sigma_mps = c.initial_sound_speed_sigma_mps;
    return m;
  }

  static TrackerConfig<Scalar, Filter::kMeasDim> core_config(const Config& c) {
    TrackerConfig<Scalar, Filter::kMeasDim> t;
    t.z_min = MeasVec::Zero();  // (0, max_toa_s] is checked with the labels
    t.z_max = MeasVec::Constant(c.max_toa_s);
    t.max_position_variance_m2 = std::numeric_limits<Scalar>::max();  // a sonar track is never dropped for its spread
    t.max_predict_us = c.max_predict_us;
    t.max_forward_jump_us = c.max_forward_jump_us;
    t.resync_frames = c.resync_frames;
    return t;
  }

  static ReacquireWhenLostParams reacquire_params(const Config& c) {
    ReacquireWhenLostParams p;
    p.min_arrivals = c.init.min_arrivals;
    p.lost_frames = c.reacquire_after_lost_frames;
    return p;
  }

  Status refuse(Status s) {
    stats_ = SonarStepStats{};
    stats_.status = s;
    reported_ = false;
    counters_.resyncs = core_.resyncs();
    ++counters_.rejected[static_cast<std::size_t>(s)];
    return s;
  }

  /// The labels become channels: one ChannelScan entry holding the frame.
  /// kMalformedFrame: count over capacity, a path that is not one, two
  /// arrivals on one channel; kNonFinite: a time; kOutOfRange: a beacon
  /// not configured, a time outside (0, max_toa_s].
  Status to_channels(const Scan& scan, ChannelFrame& out) const {
    using T = ScalarTraits<Scalar>;
    if (scan.count > kMaxArrivals) return Status::kMalformedFrame;
    ChannelMask present = 0;
    for (std::size_t i = 0; i < kMaxArrivals; ++i) {
      if (i >= scan.count) break;
      const auto& a = scan.arrivals[i];
      if (a.path != ArrivalPath::kDirect && a.path != ArrivalPath::kReflected) return Status::kMalformedFrame;
      if (a.beacon >= kMaxBeacons) continue;  // out of range, reported below
      const int ch = Toa::channel(a.beacon, a.path);
      if (has_channel(present, ch)) return Status::kMalformedFrame;
      present = with_channel(present, ch);
    }
    for (std::size_t i = 0; i < kMaxArrivals; ++i) {
      if (i >= scan.count) break;
      if (!T::is_finite(scan.arrivals[i].toa_s)) return Status::kNonFinite;
    }
    MeasVec z = MeasVec::Zero();
    for (std::size_t i = 0; i < kMaxArrivals; ++i) {
      if (i >= scan.count) break;
      const auto& a = scan.arrivals[i];
      if (a.beacon >= config_.toa.beacon_count || a.beacon >= kMaxBeacons) return Status::kOutOfRange;
      if (!(a.toa_s > Scalar(0)) || a.toa_s > config_.max_toa_s) return Status::kOutOfRange;
      z(Toa::channel(a.beacon, a.path)) = a.toa_s;
    }
    out.t_us = scan.t_us;
    out.count = 1;
    out.z[0] = z;
    out.present[0] = present;
    return Status::kOk;
  }

  Config config_;
  Filter prototype_ = prototype(config_);
  Core core_;
  SonarStepStats stats_{};
  SonarCounters counters_{};
  bool reported_ = false;
};

/// Parameters of the sonar tracker in SI units (double), with the
/// defaults of UW-003 and the filter defaults a check found workable
/// (docs/scenarios.md). make_sonar_tracker() turns them into a Config.
struct SonarTrackerParams {
  static constexpr int kMaxBeacons = 8;  ///< 8 beacons x 2 paths = hal::kMaxSonarArrivals.
  double beacons_m[kMaxBeacons][3] = {{0, 0, 0}, {2000, 0, 0}, {0, 2000, 0}, {2000, 2000, 0}};  ///< [x, y, depth], m.
  std::uint8_t beacon_count = 4;              ///< Beacons in use.
  double seabed_depth_m = 150.0;              ///< D, m.
  double sigma_toa_s = 3e-3;                  ///< TOA noise sigma, s.
  double accel_sigma_mps2 = 0.05;             ///< White acceleration per axis, m/s^2.
  /// c random walk: sigma after 1 s, m/s. UW-003's truth walks 0.3 m/s per
  /// 1 s step (clamped to 1500 +- 2), i.e. 0.3 m/s per sqrt(s); the check's
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
SonarTrackerConfig<Scalar, kMaxBeacons> sonar_tracker_config(const SonarTrackerParams& p) {
  using T = ScalarTraits<Scalar>;
  SonarTrackerConfig<Scalar, kMaxBeacons> c;
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

/// The sonar tracker with the given parameters.
template <class Scalar, int kMaxBeacons = 4>
SonarTracker<Scalar, kMaxBeacons> make_sonar_tracker(const SonarTrackerParams& p) {
  return SonarTracker<Scalar, kMaxBeacons>(sonar_tracker_config<Scalar, kMaxBeacons>(p));
}

}  // namespace kestrel
