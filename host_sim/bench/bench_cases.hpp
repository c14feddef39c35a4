// SPDX-License-Identifier: Apache-2.0
// What kestrel-bench times and kestrel-instr-count counts, defined once
// (docs/performance.md, "What is measured"): every filter x scalar x form
// (dense / structured) on the CA-2D + polar radar models with the S1 sensor
// and the tuned EKF-CA (bench_params()), fed by two-point initiation from S1
// frames 0 and 1 and then predict + update on every later frame; and the
// path classes of the host board's radar tracker (kMaxTracks 16, kMaxPlots
// 32, gate 99.9 %), each with the StepStats that prove a measured step took
// that path. A new filter joins both programs with one line in
// for_each_ekf_case() or for_each_sigma_case() (a new family needs a new
// function and, for kestrel-instr-count, a translation unit of its own:
// instr_count.hpp); kTrackerPaths<F> = false measures it as a filter only.
// The radar IMM (for_each_imm_case()) is counted by kestrel-instr-count
// only, with its own defaults and the normal and worst_case tracker paths.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bench/bench_inputs.hpp"
#include "kestrel/filters/ekf.hpp"
#include "kestrel/filters/imm_radar.hpp"
#include "kestrel/filters/r2aekf.hpp"
#include "kestrel/filters/sigma_point_filter.hpp"
#include "kestrel/filters/sr_sigma_point_filter.hpp"
#include "kestrel/filters/structure.hpp"
#include "kestrel/scalar/fixed_point_eigen.hpp"
#include "kestrel/host/board.hpp"
#include "kestrel/tracking/radar_tracker.hpp"

namespace kestrel::bench {

/// The names of one case: "ekf-ca", "double", "dense".
struct CaseName {
  const char* filter;
  const char* scalar;
  const char* form;
};

template <class S>
using DenseEkfCa = Ekf<Dense<CaMotion<S>>, Dense<CaPolarRadar<S>>>;
template <class S>
using DenseR2AekfCa = R2Aekf<Dense<CaMotion<S>>, Dense<CaPolarRadar<S>>>;

/// A sigma-point filter on CA-2D + polar radar: structured (the models as
/// they are) or dense (Dense<M>, every time update through sigma points).
template <template <class, class> class Filter, class S>
using SigmaCa = Filter<CaMotion<S>, CaPolarRadar<S>>;
template <template <class, class> class Filter, class S>
using DenseSigmaCa = Filter<Dense<CaMotion<S>>, Dense<CaPolarRadar<S>>>;

/// Whether the tracker paths of filter F are measured too: the EKF family
/// the board's radar tracker runs. The sigma-point filters are measured as
/// filters only (filter/ paths; their tracker paths would differ from the
/// EKF's by the filter calls alone).
template <class F>
inline constexpr bool kTrackerPaths = true;
template <class M, class H>
inline constexpr bool kTrackerPaths<Ukf<M, H>> = false;
template <class M, class H>
inline constexpr bool kTrackerPaths<Cdkf<M, H>> = false;
template <class M, class H>
inline constexpr bool kTrackerPaths<SrUkf<M, H>> = false;
template <class M, class H>
inline constexpr bool kTrackerPaths<SrCdkf<M, H>> = false;

/// Calls visit.template operator()<Filter>(CaseName) for every EKF-family case.
/// Forms: "dense" is the generic filter on the same models with their
/// structure hidden (Dense<M>: the test oracle and the baseline);
/// "structured" lets the filter use what the models expose
/// (kestrel/filters/structure.hpp); for Q31.32 that is the sparse form of
/// the sequential whitened update (Ekf's header comment).
template <class Visitor>
void for_each_ekf_case(Visitor&& visit) {
  visit.template operator()<DenseEkfCa<double>>(CaseName{"ekf-ca", "double", "dense"});
  visit.template operator()<EkfCa<double>>(CaseName{"ekf-ca", "double", "structured"});
  visit.template operator()<DenseEkfCa<float>>(CaseName{"ekf-ca", "float", "dense"});
  visit.template operator()<EkfCa<float>>(CaseName{"ekf-ca", "float", "structured"});
  visit.template operator()<DenseEkfCa<Q31_32>>(CaseName{"ekf-ca", "q31_32", "dense"});
  visit.template operator()<EkfCa<Q31_32>>(CaseName{"ekf-ca", "q31_32", "structured"});
  visit.template operator()<DenseR2AekfCa<double>>(CaseName{"r2aekf", "double", "dense"});
  visit.template operator()<R2AekfCa<double>>(CaseName{"r2aekf", "double", "structured"});
  visit.template operator()<DenseR2AekfCa<float>>(CaseName{"r2aekf", "float", "dense"});
  visit.template operator()<R2AekfCa<float>>(CaseName{"r2aekf", "float", "structured"});
}

/// The sigma-point cases, as for_each_ekf_case.
template <class Visitor>
void for_each_sigma_case(Visitor&& visit) {
  // Sigma-point filters (filter paths only, kTrackerPaths): "structured"
  // takes the closed-form time update of the affine CA-2D
  // (filters/sigma_points.hpp), "dense" draws the points. The square-root
  // forms are measured in double only: in float both forms refuse an early
  // S1 update of this run (the rank-1 downdate of Sx reports
  // kNotPositiveDefinite after the two-point initiation; SR-UKF at the first
  // update, SR-CDKF within the first six).
  visit.template operator()<DenseSigmaCa<Ukf, double>>(CaseName{"ukf-ca", "double", "dense"});
  visit.template operator()<SigmaCa<Ukf, double>>(CaseName{"ukf-ca", "double", "structured"});
  visit.template operator()<DenseSigmaCa<Ukf, float>>(CaseName{"ukf-ca", "float", "dense"});
  visit.template operator()<SigmaCa<Ukf, float>>(CaseName{"ukf-ca", "float", "structured"});
  visit.template operator()<DenseSigmaCa<Cdkf, double>>(CaseName{"cdkf-ca", "double", "dense"});
  visit.template operator()<SigmaCa<Cdkf, double>>(CaseName{"cdkf-ca", "double", "structured"});
  visit.template operator()<DenseSigmaCa<Cdkf, float>>(CaseName{"cdkf-ca", "float", "dense"});
  visit.template operator()<SigmaCa<Cdkf, float>>(CaseName{"cdkf-ca", "float", "structured"});
  visit.template operator()<DenseSigmaCa<SrUkf, double>>(CaseName{"srukf-ca", "double", "dense"});
  visit.template operator()<SigmaCa<SrUkf, double>>(CaseName{"srukf-ca", "double", "structured"});
  visit.template operator()<DenseSigmaCa<SrCdkf, double>>(CaseName{"srcdkf-ca", "double", "dense"});
  visit.template operator()<SigmaCa<SrCdkf, double>>(CaseName{"srcdkf-ca", "double", "structured"});
}

/// Calls visit.template operator()<Filter>(CaseName) for the radar IMM
/// (CV, CA and CT EKFs, each on its structured models) in double and float.
template <class Visitor>
void for_each_imm_case(Visitor&& visit) {
  visit.template operator()<RadarImm<double>>(CaseName{"imm", "double", "structured"});
  visit.template operator()<RadarImm<float>>(CaseName{"imm", "float", "structured"});
}

/// Every case: the EKF family, then the sigma-point filters.
template <class Visitor>
void for_each_filter_case(Visitor&& visit) {
  for_each_ekf_case(visit);
  for_each_sigma_case(visit);
}

/// Model parameters of every case: the S1 sensor and the tuned EKF-CA of
/// docs/r2aekf.md (qj = 160 m^2/s^5), which holds S1's weave inside the 99.9 % gate
/// (paper 000's qj = 1.6 loses it every half period, which would turn the
/// "normal" path into a drop-and-restart cycle). Counts do not depend on qj.
inline RadarTrackerParams bench_params() {
  RadarTrackerParams p;
  p.qj = 160.0;
  return p;
}

/// A filter of type F with the CA-2D/polar parameters p. The IMM takes
/// kestrel-sim's defaults (docs/imm.md) with p's sensor: its modes have
/// their own noise, not p's qj.
template <class F>
F make_filter(const RadarTrackerParams& p) {
  using Scalar = typename F::Scalar;
  if constexpr (requires { F::kModes; }) {
    RadarImmParams ip;
    ip.sigma_range_m = p.sigma_range_m;
    ip.sigma_bearing_rad = p.sigma_bearing_rad;
    return make_radar_imm<Scalar>(ip);
  } else {
    using T = ScalarTraits<Scalar>;
    typename F::MotionModel motion{};
    motion.qj = T::from_double(p.qj);
    typename F::MeasurementModel radar{};
    radar.sigma_range_m = T::from_double(p.sigma_range_m);
    radar.sigma_bearing_rad = T::from_double(p.sigma_bearing_rad);
    return F(motion, radar);
  }
}

template <class F>
using InitiatorFor = TwoPointInitiator<typename F::MotionModel, typename F::MeasurementModel>;

template <class F>
InitiatorFor<F> make_initiator(const RadarTrackerParams& p) {
  using T = ScalarTraits<typename F::Scalar>;
  const F f = make_filter<F>(p);
  return InitiatorFor<F>{f.measurement(), T::from_double(p.max_speed_mps), T::from_double(p.init_accel_sigma_mps2)};
}

template <class Scalar>
Vec<Scalar, 2> to_meas(const PlotSi& plot) {
  using T = ScalarTraits<Scalar>;
  Vec<Scalar, 2> z;
  z << T::from_double(plot.range_m), T::from_double(plot.bearing_rad);
  return z;
}

/// One filter step's input: the time since the previous frame and the plot.
template <class Scalar>
struct FilterInput {
  Scalar dt;
  Vec<Scalar, 2> z;
};

/// A filter initiated from S1 frames 0 and 1 and the inputs of frames 2...
template <class F>
struct FilterRun {
  F start;
  std::vector<FilterInput<typename F::Scalar>> inputs;
};

template <class F>
FilterRun<F> make_filter_run(const std::vector<FrameSi>& frames) {
  using Scalar = typename F::Scalar;
  using T = ScalarTraits<Scalar>;
  const RadarTrackerParams p = bench_params();
  FilterRun<F> run{make_filter<F>(p), {}};
  const auto init = make_initiator<F>(p);
  typename F::State x;
  typename F::Cov P;
  const Scalar dt0 = T::from_ratio(frames[1].t_us - frames[0].t_us, 1000000);
  if (init.initiate(to_meas<Scalar>(frames[0].plots[0]), to_meas<Scalar>(frames[1].plots[0]), dt0, x, P) !=
          Status::kOk ||
      run.start.reset(x, P) != Status::kOk) {
    throw std::runtime_error("bench: two-point initiation failed");
  }
  for (std::size_t k = 2; k < frames.size(); ++k) {
    run.inputs.push_back(FilterInput<Scalar>{T::from_ratio(frames[k].t_us - frames[k - 1].t_us, 1000000),
                                             to_meas<Scalar>(frames[k].plots[0])});
  }
  return run;
}

// ---------------------------------------------------------------------------
// Tracker paths

template <class F>
using BenchTracker = host::BoardRadarTracker<F>;

template <class F>
BenchTracker<F> make_tracker() {
  const RadarTrackerParams p = bench_params();
  return BenchTracker<F>(make_filter<F>(p), make_initiator<F>(p),
                         tracker_config_of<typename F::Scalar>(p));
}

template <class Tracker>
typename Tracker::Scan to_scan(const FrameSi& frame) {
  typename Tracker::Scan scan;
  scan.t_us = frame.t_us;
  scan.count = frame.plots.size();
  for (std::size_t i = 0; i < frame.plots.size() && i < Tracker::Scan::kMaxMeasurements; ++i) {
    scan.z[i] = to_meas<typename Tracker::Scalar>(frame.plots[i]);
  }
  return scan;
}

/// One path class: a tracker state, the scans to step, and which steps count.
///   restart == false: the scans are stepped in order from `start`; step i
///     is measured when counted[i] (the others only carry the state along).
///   restart == true: scans holds one scan, stepped `reps` times, each
///     time from a fresh copy of `start` (every measured step is the same).
template <class Tracker>
struct TrackerPath {
  std::string name;         ///< Path class: normal, gated_out, rejected, initiation, worst_case.
  std::string description;  ///< One line for the report.
  std::unique_ptr<Tracker> start;
  std::vector<typename Tracker::Scan> scans;
  std::vector<char> counted;
  bool restart = false;
  std::size_t reps = 1;

  std::size_t measured_steps() const {
    if (restart) return reps;
    std::size_t n = 0;
    for (const char c : counted) n += c ? 1u : 0u;
    return n;
  }
};

/// Steps `scans` in order on `t`, returning for each whether `is_path` held.
template <class Tracker, class Pred>
std::vector<char> classify(Tracker t, const std::vector<typename Tracker::Scan>& scans, Pred is_path) {
  std::vector<char> out;
  out.reserve(scans.size());
  for (const auto& scan : scans) {
    const Status s = t.step(scan);
    out.push_back(is_path(t, s) ? 1 : 0);
  }
  return out;
}

/// The tracker after stepping frames[0, n).
template <class Tracker>
std::unique_ptr<Tracker> warmed(std::unique_ptr<Tracker> t, const std::vector<FrameSi>& frames, std::size_t n) {
  for (std::size_t k = 0; k < n && k < frames.size(); ++k) {
    static_cast<void>(t->step(to_scan<Tracker>(frames[k])));
  }
  return t;
}

/// Whether every tracker path class is measured for F; the IMM's budgets
/// hold two, normal and worst_case. A compile-time choice, so the EKF
/// family's paths compile to what they were (a counted path's code must
/// not move when a case is added: instr_count.hpp).
template <class F>
inline constexpr bool kAllTrackerPaths = !requires { F::kModes; };

/// Every path class for filter F (see docs/performance.md for what each
/// exercises; kAllTrackerPaths). Throws if a path's defining condition does
/// not hold.
template <class F>
std::vector<TrackerPath<BenchTracker<F>>> make_tracker_paths() {
  using Tracker = BenchTracker<F>;
  using Scan = typename Tracker::Scan;
  constexpr std::size_t kTracks = Tracker::Table::kMaxTracks;
  constexpr std::size_t kPlots = Scan::kMaxMeasurements;
  const std::vector<FrameSi> s1 = s1_frames();
  auto fresh = [] { return std::make_unique<Tracker>(make_tracker<F>()); };
  std::vector<TrackerPath<Tracker>> paths;

  // normal: S1, one confirmed track, its plot associated and fused; steps of
  // S1 where anything else happens (a drop, a re-initiation) are stepped but
  // not counted.
  {
    TrackerPath<Tracker> p;
    p.name = "normal";
    p.description = "S1 single target: predict, gate, update, manage, report (1 confirmed track, 1 plot)";
    p.start = fresh();
    for (std::size_t k = 0; k < s1.size(); ++k) p.scans.push_back(to_scan<Tracker>(s1[k]));
    p.counted = classify(*p.start, p.scans, [](const Tracker& t, Status s) {
      const StepStats& st = t.last_step();
      return s == Status::kOk && st.associated == 1 && st.seeded == 0 && st.initiated == 0 &&
             st.deleted == 0 && t.tracks().size() == 1 && t.reports().size() == 1;
    });
    paths.push_back(std::move(p));
  }

  // The S1 track after 20 frames (confirmed), for the single-frame paths.
  const std::size_t kWarm = 20;
  auto confirmed = [&] { return warmed(fresh(), s1, kWarm); };
  if (confirmed()->reports().size() != 1) throw std::runtime_error("bench: S1 track not confirmed after warm-up");

  // gated_out: the next plot lands 0.1 rad off the track: outside its gate,
  // it starts a seed instead.
  if constexpr (kAllTrackerPaths<F>) {
    TrackerPath<Tracker> p;
    p.name = "gated_out";
    p.description = "1 confirmed track, its plot 0.1 rad off: predict, gate miss, seed, coast, report";
    p.start = confirmed();
    FrameSi f = s1[kWarm];
    f.plots[0].bearing_rad += 0.1;
    p.scans.push_back(to_scan<Tracker>(f));
    p.restart = true;
    p.reps = 20;
    paths.push_back(std::move(p));
  }

  // rejected: a full frame whose last plot is beyond the maximum range:
  // validation reads every plot before refusing (the longest refusal).
  if constexpr (kAllTrackerPaths<F>) {
    TrackerPath<Tracker> p;
    p.name = "rejected";
    p.description = "full frame (32 plots), last one out of range: validated and refused (kOutOfRange)";
    p.start = confirmed();
    FrameSi f;
    f.t_us = s1[kWarm].t_us;
    for (std::size_t i = 0; i < kPlots; ++i) f.plots.push_back(s1[kWarm].plots[0]);
    f.plots.back().range_m = 1.0e7;
    p.scans.push_back(to_scan<Tracker>(f));
    p.restart = true;
    p.reps = 20;
    paths.push_back(std::move(p));
  }

  // initiation: a seed from S1 frame 0 pairs with the plot of frame 1.
  if constexpr (kAllTrackerPaths<F>) {
    TrackerPath<Tracker> p;
    p.name = "initiation";
    p.description = "1 seed + its second plot: two-point initiation of a tentative track";
    p.start = warmed(fresh(), s1, 1);
    p.scans.push_back(to_scan<Tracker>(s1[1]));
    p.restart = true;
    p.reps = 20;
    paths.push_back(std::move(p));
  }

  // worst_case: a full table (16 confirmed tracks) and a full frame (32
  // plots: one per track, 16 clutter plots far outside every gate, which
  // find no free slot).
  {
    TrackerPath<Tracker> p;
    p.name = "worst_case";
    p.description = "16 confirmed tracks x 32 plots: 392 gate tests, 16 updates, 16 plots dropped, 16 reports";
    const std::vector<FrameSi> crowd = crowded_frames(kTracks, kPlots - kTracks, 30);
    p.start = warmed(fresh(), crowd, 10);
    for (std::size_t k = 10; k < crowd.size(); ++k) p.scans.push_back(to_scan<Tracker>(crowd[k]));
    p.counted = classify(*p.start, p.scans, [](const Tracker& t, Status s) {
      const StepStats& st = t.last_step();
      return s == Status::kOk && st.associated == kTracks && st.dropped == kPlots - kTracks &&
             t.reports().size() == kTracks;
    });
    paths.push_back(std::move(p));
  }

  // Restart paths: check once that the step does what the name says.
  for (auto& p : paths) {
    if (!p.restart) {
      if (p.measured_steps() == 0) throw std::runtime_error("bench: path " + p.name + " never occurs");
      continue;
    }
    Tracker t = *p.start;
    const Status s = t.step(p.scans[0]);
    const StepStats& st = t.last_step();
    bool ok = false;
    if (p.name == "gated_out") ok = s == Status::kOk && st.associated == 0 && st.seeded == 1 && t.reports().size() == 1;
    if (p.name == "rejected") ok = s == Status::kOutOfRange;
    if (p.name == "initiation") ok = s == Status::kOk && st.initiated == 1;
    if (!ok) throw std::runtime_error("bench: path " + p.name + " does not take its path");
  }
  return paths;
}

}  // namespace kestrel::bench
