// SPDX-License-Identifier: Apache-2.0
// The real-time loop (docs/tracking.md, "The real-time loop"): one step(scan)
// per frame validates the frame, predicts every track to its time, gates and
// associates (confirmed tracks first), updates, initiates from unused
// measurements, confirms and deletes, and reports. It is composed at compile
// time of a Filter, an Initiator, an Associator, a Manager, a
// MeasurementNoise policy and the capacities (docs/architecture.md, "The
// composed tracker"), and keeps what they share: validation, time, the gates,
// the track table, the health rules, statistics and reports. Work is bounded
// by kMaxTracks x kMaxMeasurements, with no allocation and no recursion; a
// frame that fails validation is refused with its status before any track
// changes. Time faults and the covariance health rules: docs/tracking.md.
#pragma once

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>

#include "kestrel/association/chi_square.hpp"
#include "kestrel/association/gate.hpp"
#include "kestrel/association/nearest_neighbour.hpp"
#include "kestrel/association/robust_gate.hpp"
#include "kestrel/filters/channels.hpp"
#include "kestrel/math/finite.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"
#include "kestrel/tracking/elapsed.hpp"
#include "kestrel/tracking/frame_clock.hpp"
#include "kestrel/tracking/m_of_n.hpp"
#include "kestrel/tracking/measurement_noise.hpp"
#include "kestrel/tracking/measurement_scan.hpp"
#include "kestrel/tracking/track.hpp"
#include "kestrel/tracking/track_table.hpp"

namespace kestrel {

/// What the tracker needs from a filter (EKF, R2-AEKF, UKF, ... all fit).
template <class F>
concept TrackingFilter = requires(F& f, const F& cf, const typename F::State& x,
                                  const typename F::Cov& P, const typename F::MeasVec& z,
                                  typename F::Scalar dt) {
  { f.reset(x, P) } -> std::same_as<Status>;
  { f.predict(dt) } -> std::same_as<Status>;
  { cf.innovation(z) } -> std::same_as<Innovation<typename F::Scalar, F::kMeasDim>>;
  { f.update(z) } -> std::same_as<Status>;
  { cf.x() } -> std::convertible_to<typename F::State>;
  { cf.P() } -> std::convertible_to<typename F::Cov>;
  { cf.diagnostics() } -> std::convertible_to<FusionDiagnostics<typename F::Scalar, F::kMeasDim>>;
};

/// A filter that fuses the channels of a measurement it is given and chooses
/// among them itself (ChannelGatedEkf): the tracker then takes a
/// ChannelScan and calls update_channels() instead of update().
template <class F>
concept ChannelFilter = requires(F& f, const F& cf, const typename F::MeasVec& z, ChannelMask m) {
  { cf.innovation(z, m) } -> std::same_as<Innovation<typename F::Scalar, F::kMeasDim>>;
  { f.update_channels(z, m) } -> std::same_as<Status>;
};

/// A single-point initiator that starts the track's filter itself (reset
/// and, e.g., an update with the plot's inliers) instead of handing out x
/// and P: the filter is a copy of the tracker's prototype (or, on a
/// restart, of the track's own filter).
template <class I, class F>
concept FilterStartingInitiator = requires(I& i, F& f, const typename F::MeasVec& z, ChannelMask m) {
  { i.start(f, z, m) } -> std::same_as<Status>;
};

/// A filter that hands out what every plot is measured against (Ekf: h(x)
/// and the factor of S), so a plot's distance costs its residual and one
/// substitution. Other filters are gated through innovation().
template <class F>
concept PredictsMeasurement = requires(const F& f, const typename F::MeasVec& z) {
  { f.predicted_measurement().distance(z) } -> std::same_as<PlotDistance<typename F::Scalar>>;
};

/// A filter that forms a plot's innovation from the distance its gate took
/// (Ekf): the plot a track takes is not whitened twice.
template <class F>
concept InnovationFromDistance =
    requires(const F& f, const typename F::MeasVec& z, const PlotDistance<typename F::Scalar>& d) {
      { f.innovation(z, d) } -> std::same_as<Innovation<typename F::Scalar, F::kMeasDim>>;
    };

/// A filter that updates from the innovation it formed for the plot (Ekf):
/// the residual of the plot a track takes is formed once.
template <class F>
concept UpdatesFromInnovation = requires(F& f, const Innovation<typename F::Scalar, F::kMeasDim>& in) {
  { f.update_innovation(in) } -> std::same_as<Status>;
};

/// A filter that fuses a plot with its model's R scaled by a factor (Ekf,
/// Imm): what a track's adaptive measurement noise needs
/// (AdaptiveMeasurementNoise, association/adaptive_noise.hpp).
template <class F>
concept ScalesMeasurementNoise = requires(F& f, const F& cf, const typename F::MeasVec& z,
                                          typename F::Scalar s) {
  { cf.innovation_scaled(z, s) } -> std::same_as<Innovation<typename F::Scalar, F::kMeasDim>>;
  { f.update_scaled(z, s) } -> std::same_as<Status>;
};

/// A filter that can fold several plots in at once with association
/// weights (probabilistic association, association/pda.hpp).
template <class F, std::size_t kMax>
concept WeightedUpdateFilter = requires(F& f, const typename F::MeasVec (&z)[kMax],
                                        const typename F::Scalar (&beta)[kMax], std::size_t n,
                                        typename F::Scalar beta_none) {
  { f.update_pda(z, beta, n, beta_none) } -> std::same_as<Status>;
};

/// A filter whose prediction can be committed unchecked and checked later
/// (Ekf): the tracker then checks each track's P once per frame, by the
/// update's own check or, for a track without an update, by
/// verify_prediction() in manage().
template <class F>
concept VerifiesPredictionLater = requires(F& f, const F& cf, typename F::Scalar dt) {
  { f.predict_unverified(dt) } -> std::same_as<Status>;
  { cf.verify_prediction() } -> std::same_as<Status>;
};

/// Track-management and validation parameters.
template <class Scalar, int kMeasDim>
struct TrackerConfig {
  GateProbability gate_confirmed = GateProbability::k99;  ///< Gate of confirmed tracks.
  GateProbability gate_tentative = GateProbability::k99;  ///< Gate of tentative tracks.
  /// When positive, replaces the chi-square quantile of gate_confirmed (d2
  /// units). For filter-evaluation runs with one target and no clutter
  /// (S1/S2 of docs/scenarios.md, scored as the papers score filters, ungated): a gate
  /// there only turns a lagging filter into a dropped and re-started track,
  /// which resets its lag and flatters its error.
  Scalar gate_confirmed_threshold{};
  /// Robust gating of confirmed tracks (association/robust_gate.hpp) when
  /// above 1 and the chi-square gate applies (no gate_confirmed_threshold):
  /// plots up to this factor times the gate's d2 are taken with their
  /// innovation shrunk to the gate's edge. 0: off, a plot beyond the gate is
  /// a miss. For single-plot associators (NN, GNN); PDA weighs its own gate.
  Scalar robust_gate_factor{};
  std::uint8_t confirm_m = 2;          ///< MOfN: confirm with M associations ...
  std::uint8_t confirm_n = 3;          ///< ... in the first N frames (N <= 8).
  std::uint16_t max_coast_misses = 5;  ///< MOfN: delete a confirmed track after this many misses in a row.
  Scalar max_position_variance_m2{};   ///< Delete when var(x)+var(y) exceeds this, m^2.
  Vec<Scalar, kMeasDim> z_min{};       ///< Smallest valid measurement, per channel.
  Vec<Scalar, kMeasDim> z_max{};       ///< Largest valid measurement, per channel.
  bool report_tentative = false;       ///< Also report tentative (initialised) tracks.
  /// A track whose state is older than this at a frame is deleted, not
  /// extrapolated (its plots restart it), us. Default 10 s: 20 frame periods
  /// of a 0.5 s radar scan.
  std::int64_t max_predict_us = 10'000'000;
  /// A frame later than the last accepted one by more than this is refused
  /// with kTimeJumpedForward, us. Default 10 min.
  std::int64_t max_forward_jump_us = 600'000'000;
  /// Restart on a new clock after this many consecutive refused frames
  /// (kTimeWentBackwards / kTimeJumpedForward) that are consistent with each
  /// other (each at or after the previous, within max_forward_jump_us).
  /// 0: never restart.
  std::uint8_t resync_frames = 3;
};

/// What one step did (readable after step()).
struct StepStats {
  Status status = Status::kOk;     ///< Return value of the step.
  std::uint16_t measurements = 0;  ///< Measurements in the frame.
  std::uint16_t associated = 0;    ///< Used to update an existing track.
  std::uint16_t initiated = 0;     ///< Turned a seed into an initialised track.
  std::uint16_t seeded = 0;        ///< Started a new seed.
  std::uint16_t confirmed = 0;     ///< Tracks confirmed in this frame.
  std::uint16_t deleted = 0;       ///< Tracks deleted in this frame.
  std::uint16_t dropped = 0;       ///< Unused measurements (or seeds to keep) with no free slot.
  std::uint16_t refused = 0;       ///< Unused measurements the initiator refused to start from (kOutOfRange).
  std::uint16_t filter_failures = 0;  ///< Predict/update refused by a filter.
  std::uint16_t stale = 0;      ///< Deleted: predict gap over max_predict_us (also in `deleted`).
  std::uint16_t unhealthy = 0;  ///< Deleted: P not positive definite, or a variance not positive and finite (also in `deleted`).
  std::uint16_t restarted = 0;  ///< Lost tracks started again from their plot (TrackVerdict::kRestart).
  std::uint16_t clipped = 0;    ///< Of `associated`: taken beyond the gate with a shrunk innovation (RobustGate).
  bool resynced = false;        ///< The tracker restarted on this frame's clock (tracks deleted first).
  /// The first status a filter or the initiator refused with in this frame
  /// (kOk: none), e.g. kUnderdetermined from a multilateration initiator.
  Status failure = Status::kOk;
};

template <TrackingFilter Filter, class Initiator, std::size_t kMaxTracks, std::size_t kMaxMeasurements,
          template <class, std::size_t, std::size_t> class Associator = NearestNeighbour,
          template <class> class Manager = MOfN,
          template <class, std::size_t> class MeasurementNoise = NominalMeasurementNoise>
class Tracker {
 public:
  using Scalar = typename Filter::Scalar;
  static constexpr int kMeasDim = Filter::kMeasDim;
  using MeasVec = typename Filter::MeasVec;
  using Innov = Innovation<Scalar, kMeasDim>;
  /// A ChannelScan for a ChannelFilter, a MeasurementScan otherwise.
  using Scan = std::conditional_t<ChannelFilter<Filter>, ChannelScan<Scalar, kMeasDim, kMaxMeasurements>,
                                  MeasurementScan<Scalar, kMeasDim, kMaxMeasurements>>;
  using TrackT = Track<Filter>;
  using Report = TrackReport<Filter>;
  using Table = TrackTable<TrackT, kMaxTracks>;
  using Config = TrackerConfig<Scalar, kMeasDim>;
  using InitiatorT = Initiator;
  using AssociatorT = Associator<Scalar, kMaxTracks, kMaxMeasurements>;
  using AssociatorParams = typename AssociatorT::Params;
  using ManagerT = Manager<Scalar>;
  using MeasurementNoiseT = MeasurementNoise<Scalar, kMaxTracks>;
  static_assert(kMaxMeasurements < 32768, "measurement indices are int16");
  static_assert(!MeasurementNoiseT::kAdapts || (ScalesMeasurementNoise<Filter> && !ChannelFilter<Filter>),
                "AdaptiveMeasurementNoise needs a filter that fuses with a scaled R (ScalesMeasurementNoise)");

  /// @param prototype  a filter holding the model parameters every track copies.
  /// @param manager    the track manager with its own parameters (MOfN reads
  ///                   its own from config).
  /// @param associator the associator's parameters (PDA's P_D and clutter
  ///                   density; NN and GNN have none). Its scratch storage
  ///                   (GNN's cost matrix) is built in place, never copied.
  Tracker(const Filter& prototype, const Initiator& initiator, const Config& config,
          const ManagerT& manager = ManagerT{}, const AssociatorParams& associator = AssociatorParams{})
      : initiator_(initiator),
        config_(config),
        manager_(manager),
        associator_(associator),
        clock_(config.max_forward_jump_us, config.resync_frames) {
    prototype_.filter = prototype;
    gate_confirmed_ = EllipsoidalGate<Scalar, kMeasDim>::with_probability(config.gate_confirmed);
    gate_tentative_ = EllipsoidalGate<Scalar, kMeasDim>::with_probability(config.gate_tentative);
    gate_probability_confirmed_ = probability_of(config.gate_confirmed);
    gate_probability_tentative_ = probability_of(config.gate_tentative);
    if (config.gate_confirmed_threshold > Scalar(0)) {
      gate_confirmed_.threshold = config.gate_confirmed_threshold;
      gate_probability_confirmed_ = Scalar(1);  // an explicit threshold is taken as "ungated"
    } else if (config.robust_gate_factor > Scalar(1)) {
      // The associator searches the outer gate; fold_in() shrinks what lies
      // beyond the chi-square one.
      robust_confirmed_.inner = gate_confirmed_.threshold;
      gate_confirmed_.threshold = gate_confirmed_.threshold * config.robust_gate_factor;
    }
    manager_.configure(config_);
  }

  /// The pairs one association pass offers the associator: the tracks of
  /// one class that are predicted to this frame (index k, in table order)
  /// against the measurements not yet used (index j).
  class AssociationCandidates {
   public:
    using Innov = Tracker::Innov;
    std::size_t tracks() const { return count_; }
    std::size_t measurements() const { return scan_.count; }
    bool free(std::size_t j) const { return !used_[j]; }
    /// Track k's side of all its pairs, taken once per track: everything
    /// that does not depend on the plot.
    auto track(std::size_t k) const {
      const Filter& f = tracker_.table_[slot_[k]].filter;
      if constexpr (PredictsMeasurement<Filter>) {
        return f.predicted_measurement();
      } else {
        return ThroughInnovation{&f};
      }
    }
    /// The normalised distance of measurement j from a track (track(k)):
    /// the per-pair work of every associator.
    /// (PlotDistance, or the whole Innovation where that is what it cost.)
    template <class TrackSide>
    auto distance(const TrackSide& track, std::size_t j) const {
      if constexpr (PredictsMeasurement<Filter>) {
        return track.distance(scan_.z[j]);
      } else {
        return track.distance(scan_.z[j], channels_of(scan_, j));
      }
    }
    /// The innovation of measurement j against track k (pure).
    Innov innovation(std::size_t k, std::size_t j) const {
      return innovation_of(tracker_.table_[slot_[k]].filter, scan_, j);
    }
    bool gated(const PlotDistance<Scalar>& d) const { return gate_.accepts(d); }
    bool gated(const Innov& in) const { return gate_.accepts(in); }
    Scalar gate_threshold() const { return gate_.threshold; }
    /// P_G: the probability that the target's plot falls in the gate (1 for
    /// an explicit threshold, which the tracker takes as "ungated").
    Scalar gate_probability() const { return gate_probability_; }
    /// Track k's stable id, measurement j and the frame time: what an
    /// associator told more than the plots needs (a simulation's oracle,
    /// which knows each plot's true origin, keys its labels on them).
    std::uint32_t track_id(std::size_t k) const { return tracker_.table_[slot_[k]].id; }
    const MeasVec& measurement(std::size_t j) const { return scan_.z[j]; }
    std::int64_t t_us() const { return scan_.t_us; }
    /// Update track k with measurement j. On success j is used and k is
    /// hit; if the filter refuses, both stay open.
    void assign(std::size_t k, std::size_t j) {
      if constexpr (ChannelFilter<Filter>) {  // the filter's own gate tests it; no association test
        tracker_.fold_in(slot_[k], scan_, j, Innov{}, gate_, robust_, used_, hit_, drop_);
      } else {
        tracker_.fold_in(slot_[k], scan_, j, innovation(k, j), gate_, robust_, used_, hit_, drop_);
      }
    }
    /// The same with `d` = distance(track(k), j): an innovation (a filter
    /// gated through innovation()) is used as is; a PlotDistance costs the
    /// plot's residual on the filter's shared linearisation.
    template <class Distance>
    void assign(std::size_t k, std::size_t j, const Distance& d) {
      if constexpr (std::is_same_v<Distance, Innov>) {
        tracker_.fold_in(slot_[k], scan_, j, d, gate_, robust_, used_, hit_, drop_);
      } else if constexpr (InnovationFromDistance<Filter> && !ChannelFilter<Filter>) {
        const Filter& f = tracker_.table_[slot_[k]].filter;
        tracker_.fold_in(slot_[k], scan_, j, f.innovation(scan_.z[j], d), gate_, robust_, used_, hit_, drop_);
      } else {
        assign(k, j);
      }
    }
    /// Update track k with the measurements index[0..n) weighted by
    /// beta[0..n), beta_none for none of them (probabilistic association;
    /// the filter needs update_pda). On success all n are used.
    template <class F = Filter>
      requires WeightedUpdateFilter<F, kMaxMeasurements>
    void assign_weighted(std::size_t k, const std::size_t (&index)[kMaxMeasurements],
                         const Scalar (&beta)[kMaxMeasurements], std::size_t n, Scalar beta_none) {
      tracker_.fold_in_weighted(slot_[k], scan_, index, beta, n, beta_none, gate_, used_, hit_, drop_);
    }

   private:
    friend class Tracker;
    struct ThroughInnovation {
      const Filter* filter;
      Innov distance(const MeasVec& z, ChannelMask present) const {
        if constexpr (ChannelFilter<Filter>) {
          return filter->innovation(z, present);
        } else {
          (void)present;
          return filter->innovation(z);
        }
      }
    };
    AssociationCandidates(Tracker& tracker, const Scan& scan, const EllipsoidalGate<Scalar, kMeasDim>& gate,
                          const RobustGate<Scalar, kMeasDim>& robust, Scalar gate_probability,
                          bool (&used)[kMaxMeasurements], bool (&hit)[kMaxTracks], bool (&drop)[kMaxTracks])
        : tracker_(tracker), scan_(scan), gate_(gate), robust_(robust), gate_probability_(gate_probability),
          used_(used), hit_(hit), drop_(drop) {}
    Tracker& tracker_;
    const Scan& scan_;
    const EllipsoidalGate<Scalar, kMeasDim>& gate_;
    const RobustGate<Scalar, kMeasDim>& robust_;
    Scalar gate_probability_;
    bool (&used_)[kMaxMeasurements];
    bool (&hit_)[kMaxTracks];
    bool (&drop_)[kMaxTracks];
    std::size_t slot_[kMaxTracks];  // [0, count_) written before it is read
    std::size_t count_ = 0;
  };

  /// The adaptive measurement noise's rule (robust_noise_gain and
  /// robust_noise_max_scale), for a tracker built with
  /// AdaptiveMeasurementNoise; it acts on confirmed tracks under the robust
  /// gate (config.robust_gate_factor), so a gain without that gate is
  /// refused. Call before the first step.
  /// @return kOk; kOutOfRange (a gain but 0 on a tracker built without the
  ///         adaptive noise, NominalMeasurementNoise, or without the robust
  ///         gate; a gain outside [0, 1] or a max scale below 1); kNonFinite.
  ///         The tracker is unchanged on any refusal.
  [[nodiscard]] Status configure_measurement_noise(const MeasurementNoiseConfig<Scalar>& p) {
    KESTREL_TRY(MeasurementNoiseT::check(p));
    if constexpr (MeasurementNoiseT::kAdapts) {
      // Without the robust gate the rule would not act: refused, not ignored.
      if (p.gain > Scalar(0) && !(robust_confirmed_.inner > Scalar(0))) return Status::kOutOfRange;
      // A plot's NIS counts up to the chi-square gate, as a clipped plot does.
      measurement_noise_.configure(p, robust_confirmed_.inner);
    }
    return Status::kOk;
  }

  /// The measurement noise policy's state (AdaptiveMeasurementNoise: each
  /// slot's lambda and the last frame's count of scaled updates).
  const MeasurementNoiseT& measurement_noise() const { return measurement_noise_; }

  /// Process one frame.
  /// @return kOk; kMalformedFrame (count over capacity); kNonFinite; kOutOfRange
  ///         (a measurement outside [z_min, z_max]); kTimeWentBackwards;
  ///         kTimeJumpedForward (later than the last frame by more than
  ///         config.max_forward_jump_us). On any non-kOk status the tracks
  ///         and the clock are unchanged and reports() is empty; only the
  ///         count of consecutive off-clock frames moves (header comment).
  [[nodiscard]] Status step(const Scan& scan) {
    stats_ = StepStats{};
    report_count_ = 0;
    if constexpr (MeasurementNoiseT::kAdapts) measurement_noise_.begin_frame();
    Status valid = validate(scan);
    if (valid == Status::kOk) valid = clock_.check(scan.t_us);
    bool resync = false;
    if (valid == Status::kTimeWentBackwards || valid == Status::kTimeJumpedForward) {
      if (clock_.off_clock(scan.t_us)) {
        delete_all_tracks();
        resync = true;
        valid = Status::kOk;
      }
    }
    if (valid != Status::kOk) {
      stats_.status = valid;
      ++rejected_[static_cast<std::size_t>(valid)];
      return valid;
    }
    clock_.accept(scan.t_us, resync);
    stats_.resynced = resync;
    stats_.measurements = static_cast<std::uint16_t>(scan.count);

    bool used[kMaxMeasurements] = {};
    bool hit[kMaxTracks] = {};
    bool existed[kMaxTracks] = {};
    bool drop[kMaxTracks] = {};

    predict_all(scan.t_us, existed, drop);
    release_unpredicted(existed, drop);
    associate(scan, TrackStatus::kConfirmed, gate_confirmed_, robust_confirmed_, gate_probability_confirmed_, used,
              hit, drop);
    associate(scan, TrackStatus::kTentative, gate_tentative_, RobustGate<Scalar, kMeasDim>{},
              gate_probability_tentative_, used, hit, drop);
    initiate_from_seeds(scan, existed, used, hit);
    seed_new(scan, used, hit);
    manage(scan, existed, hit, drop);
    build_reports(scan.t_us);
    return Status::kOk;
  }

  /// Reports of the last successful step (confirmed tracks, plus tentative
  /// initialised ones if config.report_tentative).
  std::span<const Report> reports() const { return {reports_, report_count_}; }
  const StepStats& last_step() const { return stats_; }

  /// A track of fewer plots than this takes no plot beyond the chi-square
  /// gate under the robust gate: its S is still mostly its start's, wide,
  /// so such a plot lies far off and is most likely not the target's.
  /// Four: the two of a two-point start and two plain updates. Why:
  /// docs/robustness.md, "A young track".
  static constexpr std::uint16_t kRobustGateMinHits = 4;

  const Table& tracks() const { return table_; }
  const Config& config() const { return config_; }
  const Initiator& initiator() const { return initiator_; }
  /// The filter every new track copies (its models and parameters).
  const Filter& prototype_filter() const { return prototype_.filter; }
  /// Frames refused so far, per status.
  std::uint32_t rejected(Status s) const { return rejected_[static_cast<std::size_t>(s)]; }
  /// Restarts on a new clock so far (header comment).
  std::uint32_t resyncs() const { return clock_.resyncs(); }

 private:
  /// The frame's content: count, finiteness, measurement box.
  /// A ChannelScan: the present channels only (a channel the filter does
  /// not have is kMalformedFrame).
  Status validate(const Scan& scan) const {
    if (scan.count > kMaxMeasurements) return Status::kMalformedFrame;
    if constexpr (ChannelFilter<Filter>) {
      for (std::size_t i = 0; i < kMaxMeasurements; ++i) {
        if (i >= scan.count) break;
        if ((scan.present[i] & ~all_channels(kMeasDim)) != 0) return Status::kMalformedFrame;
      }
    }
    for (std::size_t i = 0; i < kMaxMeasurements; ++i) {
      if (i >= scan.count) break;
      const ChannelMask present = channels_of(scan, i);
      for (int c = 0; c < kMeasDim; ++c) {
        if (has_channel(present, c) && !ScalarTraits<Scalar>::is_finite(scan.z[i](c))) return Status::kNonFinite;
      }
    }
    for (std::size_t i = 0; i < kMaxMeasurements; ++i) {
      if (i >= scan.count) break;
      const ChannelMask present = channels_of(scan, i);
      for (int c = 0; c < kMeasDim; ++c) {
        if (!has_channel(present, c)) continue;
        if (scan.z[i](c) < config_.z_min(c) || scan.z[i](c) > config_.z_max(c)) {
          return Status::kOutOfRange;
        }
      }
    }
    return Status::kOk;
  }

  /// The channels measurement j carries (all of them in a MeasurementScan).
  static ChannelMask channels_of(const Scan& scan, std::size_t j) {
    if constexpr (ChannelFilter<Filter>) {
      return scan.present[j] & all_channels(kMeasDim);
    } else {
      (void)scan;
      (void)j;
      return all_channels(kMeasDim);
    }
  }

  static Innov innovation_of(const Filter& f, const Scan& scan, std::size_t j) {
    if constexpr (ChannelFilter<Filter>) {
      return f.innovation(scan.z[j], channels_of(scan, j));
    } else {
      return f.innovation(scan.z[j]);
    }
  }

  static Status update_of(Filter& f, const Scan& scan, std::size_t j) {
    if constexpr (ChannelFilter<Filter>) {
      return f.update_channels(scan.z[j], channels_of(scan, j));
    } else {
      return f.update(scan.z[j]);
    }
  }

  void note_failure(Status s) {
    if (stats_.failure == Status::kOk) stats_.failure = s;
  }

  /// The resync rule took a new clock: no track's time means anything on it.
  void delete_all_tracks() {
    for (const std::size_t i : table_.active_slots()) {
      table_.release(i);
      ++stats_.deleted;
    }
  }

  /// P_G in the scalar, converted at compile time (no double work on a board).
  static Scalar probability_of(GateProbability p) {
    using T = ScalarTraits<Scalar>;
    constexpr Scalar kProbability[] = {
        T::from_double(gate_probability(GateProbability::k90)), T::from_double(gate_probability(GateProbability::k95)),
        T::from_double(gate_probability(GateProbability::k99)), T::from_double(gate_probability(GateProbability::k995)),
        T::from_double(gate_probability(GateProbability::k999))};
    return kProbability[static_cast<int>(p)];
  }

  static Scalar seconds(std::int64_t dt_us) {
    return ScalarTraits<Scalar>::from_ratio(dt_us, 1000000);
  }

  /// Predict every initialised track to the frame time. A track older than
  /// max_predict_us, or whose filter finds the predicted P not positive
  /// definite, is marked to drop (deleted in manage()).
  void predict_all(std::int64_t t_us, bool (&existed)[kMaxTracks], bool (&drop)[kMaxTracks]) {
    for (const std::size_t i : table_.active_slots()) {
      existed[i] = true;
      TrackT& tr = table_[i];
      tr.associated = false;
      tr.measurement_index = -1;
      if (!tr.initialised) continue;  // a seed keeps its own time
      const std::int64_t gap_us = elapsed_us(t_us, tr.t_us);
      if (gap_us > config_.max_predict_us) {
        drop[i] = true;
        ++stats_.stale;
        continue;
      }
      Status s;
      if constexpr (VerifiesPredictionLater<Filter>) {
        s = tr.filter.predict_unverified(seconds(gap_us));
      } else {
        s = tr.filter.predict(seconds(gap_us));
      }
      if (s != Status::kOk) {
        ++stats_.filter_failures;
        note_failure(s);
        if (s == Status::kNotPositiveDefinite) {
          drop[i] = true;
          ++stats_.unhealthy;
        }
        continue;  // otherwise a miss in manage(); deleted if it keeps failing
      }
      tr.t_us = t_us;
    }
  }

  /// Tracks marked to drop while predicting (stale, or a P the filter
  /// refused) are deleted now, before association: their slots and the
  /// plots they would have taken are free for new tracks in this frame.
  void release_unpredicted(bool (&existed)[kMaxTracks], bool (&drop)[kMaxTracks]) {
    for (const std::size_t i : table_.active_slots()) {
      if (!drop[i]) continue;
      table_.release(i);
      ++stats_.deleted;
      existed[i] = false;
      drop[i] = false;
    }
  }

  /// One association pass over the tracks of `status` that were predicted
  /// to this frame, in table order (age order for a table that only grows).
  void associate(const Scan& scan, TrackStatus status, const EllipsoidalGate<Scalar, kMeasDim>& gate,
                 const RobustGate<Scalar, kMeasDim>& robust, Scalar gate_probability,
                 bool (&used)[kMaxMeasurements], bool (&hit)[kMaxTracks], bool (&drop)[kMaxTracks]) {
    AssociationCandidates c(*this, scan, gate, robust, gate_probability, used, hit, drop);
    for (const std::size_t i : table_.active_slots()) {
      const TrackT& tr = table_[i];
      if (tr.status != status || !tr.initialised || drop[i]) continue;
      if (tr.t_us != scan.t_us) continue;  // prediction failed this frame
      c.slot_[c.count_++] = i;
    }
    if (c.count_ > 0) associator_.associate(c);
  }

  /// Too few plots for the robust gate (kRobustGateMinHits).
  static bool young(const TrackT& tr) { return tr.hits < kRobustGateMinHits; }

  /// Update track `slot` with measurement j; record the association.
  /// `in`: its innovation before the update (the report and the manager read it).
  /// `robust`: beyond its inner gate the update takes the shrunk innovation.
  void fold_in(std::size_t slot, const Scan& scan, std::size_t j, const Innov& in,
               const EllipsoidalGate<Scalar, kMeasDim>& gate, const RobustGate<Scalar, kMeasDim>& robust,
               bool (&used)[kMaxMeasurements], bool (&hit)[kMaxTracks], bool (&drop)[kMaxTracks]) {
    if (slot >= kMaxTracks || j >= scan.count || used[j] || hit[slot]) return;  // associator contract
    TrackT& tr = table_[slot];
    if constexpr (MeasurementNoiseT::kAdapts) {
      // Confirmed tracks under the robust gate (the only pass with an
      // inner gate) fuse with lambda R.
      if (robust.inner > Scalar(0) && measurement_noise_.enabled()) {
        fold_in_scaled(slot, scan, j, in, robust, used, hit, drop);
        return;
      }
    }
    const bool clipped = robust.clips(in);
    if (clipped && young(tr)) return;  // a miss: see young()
    Status s;
    if (clipped) {
      s = tr.filter.update(robust.shrink(scan.z[j], in));
    } else if constexpr (UpdatesFromInnovation<Filter> && !ChannelFilter<Filter>) {
      s = tr.filter.update_innovation(in);  // `in` is plot j's at this state (associator contract)
    } else {
      s = update_of(tr.filter, scan, j);
    }
    if (s != Status::kOk) {
      ++stats_.filter_failures;
      note_failure(s);
      if (s == Status::kNotPositiveDefinite) {  // the track's P, not the plot: the plot stays free
        drop[slot] = true;
        ++stats_.unhealthy;
      }
      return;
    }
    used[j] = true;
    tr.measurement_index = static_cast<std::int16_t>(j);
    if constexpr (ChannelFilter<Filter>) {
      // The filter's gate was the test: its NIS over what it fused. A plot
      // the track took but fused none of is not a hit.
      tr.nis = tr.filter.diagnostics().nis;
      tr.test_ratio = Scalar(0);
      if (!tr.filter.diagnostics().fused) return;
    } else {
      tr.nis = in.d2;
      // Against the gate that decides a plain update: over 1 means clipped.
      tr.test_ratio = in.d2 / (robust.inner > Scalar(0) ? robust.inner : gate.threshold);
    }
    hit[slot] = true;
    tr.associated = true;
    manager_.hit(tr, in);
    ++stats_.associated;
    if (clipped) ++stats_.clipped;
  }

  /// fold_in() with the track's lambda R (AdaptiveMeasurementNoise): the
  /// plot is tested against the robust gate and fused against lambda R (the
  /// association measured it against R), then lambda follows its NIS.
  /// (A member template, so that an explicit instantiation of a nominal
  /// tracker instantiates no body: clang 14 ignores the constraint there.)
  template <class Noise = MeasurementNoiseT>
    requires Noise::kAdapts
  void fold_in_scaled(std::size_t slot, const Scan& scan, std::size_t j, const Innov& in,
                      const RobustGate<Scalar, kMeasDim>& robust, bool (&used)[kMaxMeasurements],
                      bool (&hit)[kMaxTracks], bool (&drop)[kMaxTracks]) {
    TrackT& tr = table_[slot];
    const Scalar scale = measurement_noise_.scale(slot);
    Scalar fused_d2 = in.d2;  // the plot's NIS against the S it is fused with
    bool clipped = false;
    Status s = Status::kOk;
    if (scale > Scalar(1)) {
      const Innov fused = tr.filter.innovation_scaled(scan.z[j], scale);
      fused_d2 = fused.d2;
      clipped = robust.clips(fused);
      if (clipped && young(tr)) return;  // a miss: see young()
      s = tr.filter.update_scaled(clipped ? robust.shrink(scan.z[j], fused) : scan.z[j], scale);
    } else {
      clipped = robust.clips(in);
      if (clipped && young(tr)) return;  // a miss: see young()
      s = clipped ? tr.filter.update(robust.shrink(scan.z[j], in)) : update_of(tr.filter, scan, j);
    }
    if (s != Status::kOk) {
      ++stats_.filter_failures;
      note_failure(s);
      if (s == Status::kNotPositiveDefinite) {  // the track's P, not the plot: the plot stays free
        drop[slot] = true;
        ++stats_.unhealthy;
      }
      return;
    }
    used[j] = true;
    tr.measurement_index = static_cast<std::int16_t>(j);
    tr.nis = in.d2;
    // Against the gate that decides a plain update: over 1 means clipped.
    tr.test_ratio = fused_d2 / robust.inner;
    // misses is still the previous frame's: 0 after a hit.
    measurement_noise_.after_plot(slot, scale, fused_d2, kMeasDim, tr.misses == 0);
    hit[slot] = true;
    tr.associated = true;
    manager_.hit(tr, in);
    ++stats_.associated;
    if (clipped) ++stats_.clipped;
  }

  /// Update track `slot` with several measurements and their weights
  /// (AssociationCandidates::assign_weighted); the report names the plot of
  /// largest weight.
  template <class F = Filter>
    requires WeightedUpdateFilter<F, kMaxMeasurements>
  void fold_in_weighted(std::size_t slot, const Scan& scan, const std::size_t (&index)[kMaxMeasurements],
                        const Scalar (&beta)[kMaxMeasurements], std::size_t n, Scalar beta_none,
                        const EllipsoidalGate<Scalar, kMeasDim>& gate, bool (&used)[kMaxMeasurements],
                        bool (&hit)[kMaxTracks], bool (&drop)[kMaxTracks]) {
    if (slot >= kMaxTracks || hit[slot] || n == 0 || n > kMaxMeasurements) return;  // associator contract
    MeasVec z[kMaxMeasurements];
    std::size_t best = kMaxMeasurements;
    for (std::size_t i = 0; i < kMaxMeasurements; ++i) {
      if (i >= n) break;
      if (index[i] >= scan.count || used[index[i]]) return;  // associator contract
      z[i] = scan.z[index[i]];
      if (best == kMaxMeasurements || beta[i] > beta[best]) best = i;
    }
    TrackT& tr = table_[slot];
    const Innov in = tr.filter.innovation(z[best]);  // before the update: the manager scores it
    if (const Status s = tr.filter.update_pda(z, beta, n, beta_none); s != Status::kOk) {
      ++stats_.filter_failures;
      note_failure(s);
      if (s == Status::kNotPositiveDefinite) {
        drop[slot] = true;
        ++stats_.unhealthy;
      }
      return;
    }
    for (std::size_t i = 0; i < kMaxMeasurements; ++i) {
      if (i >= n) break;
      used[index[i]] = true;
    }
    hit[slot] = true;
    tr.associated = true;
    tr.measurement_index = static_cast<std::int16_t>(index[best]);
    tr.nis = in.d2;
    tr.test_ratio = in.d2 / gate.threshold;
    if constexpr (requires { manager_.hit_weighted(tr, beta_none); }) {
      manager_.hit_weighted(tr, beta_none);  // the evidence of the whole gate
    } else {
      manager_.hit(tr, in);
    }
    ++stats_.associated;
  }

  /// An initiator that keeps more than one hypothesis of a start
  /// (TwoPointHypothesesInitiator); the code for it is compiled only then.
  static constexpr bool kKeepsHypotheses = requires { requires Initiator::kKeepsHypotheses; };

  /// A seed pairs with the unused measurement of lowest pairing cost and
  /// becomes a track. With a TwoPointHypothesesInitiator, seeds from the
  /// last frame pair first (over the shorter interval their pair gives the
  /// better velocity), then the older ones it keeps.
  void initiate_from_seeds(const Scan& scan, const bool (&existed)[kMaxTracks], bool (&used)[kMaxMeasurements],
                           bool (&hit)[kMaxTracks]) {
    if constexpr (!Initiator::kSinglePoint) {
      for (const std::size_t i : table_.active_slots()) {
        if (table_[i].initialised) continue;
        if constexpr (kKeepsHypotheses) {
          // Made in this frame (a kept copy, a pairing plot's seed), or older
          // than the last frame (the second pass). pair_seed() may take slots
          // while this loop runs, which the loop may or may not visit
          // (TrackTable::SlotIterator); existed[] skips them either way.
          if (!existed[i] || table_[i].age != 0) continue;
        }
        pair_seed(i, scan, used, hit);
      }
      if constexpr (kKeepsHypotheses) {
        if (initiator_.seed_extra_frames == 0) return;
        for (const std::size_t i : table_.active_slots()) {
          if (table_[i].initialised || !existed[i] || table_[i].age == 0) continue;
          pair_seed(i, scan, used, hit);
        }
      }
    } else {
      (void)existed;
    }
  }

  /// Seed i pairs with the unused measurement of lowest pairing cost. With
  /// a TwoPointHypothesesInitiator a seed that meets no unused measurement
  /// at all is deleted at once: every plot went to a track, so it was most
  /// likely an outlier of a tracked target, and waiting would only let it
  /// pair with that target's next missed plot. A member template, so that
  /// an explicit instantiation with a single-point initiator (no pair) does
  /// not compile it.
  template <class = Initiator>
  void pair_seed(std::size_t i, const Scan& scan, bool (&used)[kMaxMeasurements], bool (&hit)[kMaxTracks]) {
    TrackT& tr = table_[i];
    const std::int64_t gap_us = elapsed_us(scan.t_us, tr.t_us);
    if (gap_us > config_.max_predict_us) return;  // manage() drops it
    const Scalar dt = seconds(gap_us);
    std::size_t best = kMaxMeasurements;
    Scalar best_cost{};
    bool met_unused = false;
    for (std::size_t j = 0; j < kMaxMeasurements; ++j) {
      if (j >= scan.count) break;
      if (used[j]) continue;
      met_unused = true;
      const auto cost = initiator_.pair_cost(tr.seed, scan.z[j], dt);
      if (!cost.ok()) continue;
      if (best == kMaxMeasurements || cost.value() < best_cost) {
        best = j;
        best_cost = cost.value();
      }
    }
    if (best == kMaxMeasurements) {
      if constexpr (kKeepsHypotheses) {
        if (!met_unused) {
          table_.release(i);
          ++stats_.deleted;
        }
      } else {
        (void)met_unused;
      }
      return;
    }
    typename Filter::State x;
    typename Filter::Cov P;
    if (initiator_.initiate(tr.seed, scan.z[best], dt, x, P) != Status::kOk ||
        tr.filter.reset(x, P) != Status::kOk) {
      ++stats_.filter_failures;
      return;
    }
    if constexpr (kKeepsHypotheses) {
      // The pair may hold an outlier: the seed pairs again while it has
      // frames left, and the pairing plot starts a seed of its own.
      if (tr.age < initiator_.seed_extra_frames) {
        add_seed(tr.seed, tr.t_us, static_cast<std::uint16_t>(tr.age + 1), -1, hit);
      }
      if (initiator_.seed_from_pairs) add_seed(scan.z[best], scan.t_us, 0, static_cast<std::int16_t>(best), hit);
    }
    used[best] = true;
    hit[i] = true;
    tr.initialised = true;
    tr.t_us = scan.t_us;
    tr.associated = true;
    tr.measurement_index = static_cast<std::int16_t>(best);
    // The pairing plot is evidence too: scored against the state it started.
    if constexpr (ManagerT::kScoresInnovations) manager_.hit(tr, tr.filter.innovation(scan.z[best]));
    ++stats_.initiated;
  }

  /// A seed holding z (taken at t_us; measurement j of this frame, or -1
  /// for a kept copy) in a free slot. `age` 1 makes a kept copy one frame
  /// older, as manage() does not age a slot in the frame it is taken.
  void add_seed(const MeasVec& z, std::int64_t t_us, std::uint16_t age, std::int16_t j, bool (&hit)[kMaxTracks]) {
    const std::size_t slot = table_.allocate(prototype_);
    if (slot == kMaxTracks) {
      ++stats_.dropped;
      return;
    }
    TrackT& tr = table_[slot];
    tr.seed = z;
    tr.t_us = t_us;
    tr.age = age;
    tr.initialised = false;
    tr.associated = j >= 0;
    tr.measurement_index = j;
    manager_.start(tr);
    if constexpr (MeasurementNoiseT::kAdapts) measurement_noise_.start(slot);
    hit[slot] = j >= 0;
    ++stats_.seeded;
  }

  struct NoFilter {};
  /// The filter a FilterStartingInitiator starts before a slot is taken.
  using StartedFilter = std::conditional_t<FilterStartingInitiator<Initiator, Filter>, Filter, NoFilter>;
  static StartedFilter started_from(const Filter& prototype) {
    if constexpr (FilterStartingInitiator<Initiator, Filter>) {
      return prototype;
    } else {
      (void)prototype;
      return NoFilter{};
    }
  }

  /// Every measurement still unused starts a seed (or, for a single-point
  /// initiator, an initialised tentative track). A single-point initiator
  /// runs before a slot is taken, so a measurement it refuses (kOutOfRange,
  /// e.g. the PCL zero-Doppler veto) costs no slot and no track id.
  void seed_new(const Scan& scan, bool (&used)[kMaxMeasurements], bool (&hit)[kMaxTracks]) {
    for (std::size_t j = 0; j < kMaxMeasurements; ++j) {
      if (j >= scan.count) break;
      if (used[j]) continue;
      typename Filter::State x;
      typename Filter::Cov P;
      [[maybe_unused]] StartedFilter started_filter = started_from(prototype_.filter);
      if constexpr (FilterStartingInitiator<Initiator, Filter>) {
        const Status started = initiator_.start(started_filter, scan.z[j], channels_of(scan, j));
        if (started != Status::kOk) {
          if (started == Status::kOutOfRange) {
            ++stats_.refused;
          } else {
            ++stats_.filter_failures;
          }
          note_failure(started);
          continue;
        }
      } else if constexpr (Initiator::kSinglePoint) {
        const Status started = initiator_.initiate(scan.z[j], x, P);
        if (started == Status::kOutOfRange) {
          ++stats_.refused;
          note_failure(started);
          continue;
        }
        if (started != Status::kOk) {
          ++stats_.filter_failures;
          note_failure(started);
          continue;
        }
      }
      const std::size_t slot = table_.allocate(prototype_);
      if (slot == kMaxTracks) {
        ++stats_.dropped;
        continue;
      }
      TrackT& tr = table_[slot];
      tr.t_us = scan.t_us;
      tr.associated = true;
      tr.measurement_index = static_cast<std::int16_t>(j);
      manager_.start(tr);
      if constexpr (MeasurementNoiseT::kAdapts) measurement_noise_.start(slot);
      if constexpr (FilterStartingInitiator<Initiator, Filter>) {
        tr.filter = started_filter;
        tr.initialised = true;
        if (tr.filter.diagnostics().fused) {  // what the start fused is the track's first association
          tr.nis = tr.filter.diagnostics().nis;
        }
      } else if constexpr (Initiator::kSinglePoint) {
        if (tr.filter.reset(x, P) != Status::kOk) {
          table_.release(slot);
          ++stats_.filter_failures;
          continue;
        }
        tr.initialised = true;
      } else {
        tr.seed = scan.z[j];
        tr.initialised = false;
      }
      used[j] = true;
      hit[slot] = true;
      ++stats_.seeded;
    }
  }

  Scalar position_variance(const typename Filter::Cov& P) const {
    using L = typename Filter::Layout;
    if constexpr (requires { L::kX; L::kY; L::kZ; }) {
      return P(L::kX, L::kX) + P(L::kY, L::kY) + P(L::kZ, L::kZ);
    } else if constexpr (requires { L::kX; L::kY; }) {
      return P(L::kX, L::kX) + P(L::kY, L::kY);
    } else {
      return P(0, 0);
    }
  }

  /// True when every variance of P is positive and finite (written so that
  /// a NaN fails).
  bool healthy(const typename Filter::Cov& P) const {
    for (int k = 0; k < P.rows(); ++k) {
      if (!(P(k, k) > Scalar(0)) || !ScalarTraits<Scalar>::is_finite(P(k, k))) return false;
    }
    return true;
  }

  /// The frame's bookkeeping (history, age, hits, misses), then the
  /// manager's verdict on every initialised track; a seed lives one frame
  /// (a TwoPointHypothesesInitiator's seed_extra_frames more, within
  /// max_predict_us).
  /// Deleted besides, whatever the manager says: tracks marked to drop this
  /// frame (stale or unhealthy), any track with a variance that is not
  /// positive and finite, and any track whose position variance exceeds
  /// the limit.
  void manage(const Scan& scan, const bool (&existed)[kMaxTracks], const bool (&hit)[kMaxTracks],
              const bool (&drop)[kMaxTracks]) {
    for (const std::size_t i : table_.active_slots()) {  // releases only slot i
      TrackT& tr = table_[i];
      if (existed[i]) {
        tr.history = static_cast<std::uint8_t>((static_cast<unsigned>(tr.history) << 1u) | (hit[i] ? 1u : 0u));
        tr.age = static_cast<std::uint16_t>(tr.age < UINT16_MAX ? tr.age + 1 : tr.age);
      } else {
        tr.history = 1;  // created this frame: its first hit
      }
      if (hit[i]) {
        tr.misses = 0;
        tr.hits = static_cast<std::uint16_t>(tr.hits < UINT16_MAX ? tr.hits + 1 : tr.hits);
      } else {
        tr.misses = static_cast<std::uint16_t>(tr.misses < UINT16_MAX ? tr.misses + 1 : tr.misses);
      }

      // P is checked once per frame: by the update of a track that took a
      // plot, here for one predicted without an update. A checked P has
      // positive, finite variances.
      bool checked = false;
      Status verified = Status::kOk;
      if constexpr (VerifiesPredictionLater<Filter>) {
        checked = existed[i] && tr.initialised && !drop[i] && tr.t_us == scan.t_us;
        if (checked && !hit[i]) verified = tr.filter.verify_prediction();
      }

      bool remove = false;
      if (!tr.initialised) {
        remove = existed[i] && !hit[i];  // a seed lives one frame
        if constexpr (kKeepsHypotheses) {
          remove = remove && (tr.age > initiator_.seed_extra_frames ||
                              elapsed_us(scan.t_us, tr.t_us) > config_.max_predict_us);
        }
      } else {
        const TrackVerdict v = manager_.judge(tr, hit[i]);
        if (v == TrackVerdict::kConfirm && tr.status == TrackStatus::kTentative) {
          tr.status = TrackStatus::kConfirmed;
          ++stats_.confirmed;
        } else if (v == TrackVerdict::kDelete) {
          remove = true;
        } else if (v == TrackVerdict::kRestart) {
          restart(tr, i, scan);
        }
      }
      if (drop[i]) {
        remove = true;
      } else if (tr.initialised) {
        if (checked ? verified != Status::kOk : !healthy(tr.filter.P())) {
          remove = true;
          ++stats_.unhealthy;
          if (verified != Status::kOk) {
            ++stats_.filter_failures;
            note_failure(verified);
          }
        } else if (!(position_variance(tr.filter.P()) <= config_.max_position_variance_m2)) {
          remove = true;
        }
      }
      if (remove) {
        table_.release(i);
        ++stats_.deleted;
      }
    }
  }

  /// TrackVerdict::kRestart: start the track again from the plot it took
  /// this frame, on a copy of its own filter (a FilterStartingInitiator),
  /// and keep that start only if it fused more channels of the plot than
  /// the track's update did. A restarted track has a new id and starts
  /// counting again from this frame (its first hit).
  void restart(TrackT& tr, std::size_t slot, const Scan& scan) {
    if constexpr (FilterStartingInitiator<Initiator, Filter>) {
      if (tr.measurement_index < 0 || static_cast<std::size_t>(tr.measurement_index) >= scan.count) return;
      const auto j = static_cast<std::size_t>(tr.measurement_index);
      Filter fresh = tr.filter;
      if (initiator_.start(fresh, scan.z[j], channels_of(scan, j)) != Status::kOk) return;
      if (channel_count(fresh.diagnostics().fused_channels) <= channel_count(tr.filter.diagnostics().fused_channels)) {
        return;
      }
      tr.filter = fresh;
      table_.renew_id(slot);
      tr.age = 0;
      tr.hits = 1;
      tr.misses = 0;
      tr.history = 1;
      tr.associated = true;
      tr.nis = tr.filter.diagnostics().nis;
      tr.test_ratio = Scalar(0);
      manager_.start(tr);
      if constexpr (MeasurementNoiseT::kAdapts) measurement_noise_.start(slot);
      ++stats_.restarted;
    } else {
      (void)tr;
      (void)slot;
      (void)scan;
    }
  }

  void build_reports(std::int64_t t_us) {
    for (const std::size_t i : table_.active_slots()) {
      if (!table_[i].initialised) continue;
      const TrackT& tr = table_[i];
      if (tr.status != TrackStatus::kConfirmed && !config_.report_tentative) continue;
      Report& r = reports_[report_count_++];
      r.t_us = t_us;
      r.track_id = tr.id;
      r.status = tr.status;
      r.age = tr.age;
      r.hits = tr.hits;
      r.misses = tr.misses;
      r.associated = tr.associated;
      r.measurement_index = tr.measurement_index;
      r.nis = tr.nis;
      r.fusion = tr.filter.diagnostics();
      r.test_ratio = tr.test_ratio;
      r.score = tr.score;
      r.x = tr.filter.x();
      r.P = tr.filter.P();
    }
  }

  Initiator initiator_;
  Config config_;
  ManagerT manager_;
  AssociatorT associator_;
  TrackT prototype_{};
  EllipsoidalGate<Scalar, kMeasDim> gate_confirmed_{};
  EllipsoidalGate<Scalar, kMeasDim> gate_tentative_{};
  RobustGate<Scalar, kMeasDim> robust_confirmed_{};  ///< Off unless config.robust_gate_factor says so.
  Scalar gate_probability_confirmed_{};
  Scalar gate_probability_tentative_{};
  Table table_{};
  Report reports_[kMaxTracks]{};
  std::size_t report_count_ = 0;
  StepStats stats_{};
  std::uint32_t rejected_[kStatusCount] = {};
  FrameClock clock_{};
  /// Empty for NominalMeasurementNoise: the tracker's layout is then that of
  /// a tracker without the policy.
  [[no_unique_address]] MeasurementNoiseT measurement_noise_{};
};

}  // namespace kestrel
