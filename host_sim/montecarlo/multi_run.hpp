// SPDX-License-Identifier: Apache-2.0
// One multi-target run (docs/multitarget.md): a multi-target scenario's
// wire stream through the EKF-CA radar tracker, built for many targets
// (track table kMultiMaxTracks) with the associator chosen, and scored with
// the multi-target metrics. The oracle associator is told each plot's true
// origin (ScenarioRun::origins), so comparing a run with it isolates what
// association costs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "filters/filter_registry.hpp"
#include "filters/imm_filters.hpp"
#include "filters/settings.hpp"
#include "kestrel/association/chi_square.hpp"
#include "kestrel/filters/imm_radar.hpp"
#include "kestrel/hal/frame.hpp"
#include "kestrel/tracking/radar_tracker.hpp"
#include "metrics/multi_target_metrics.hpp"
#include "pipeline/stream_run_result.hpp"
#include "scenarios/scenario.hpp"

namespace kestrel::sim {

/// Track table capacity of the multi-target tracker: twelve targets plus
/// the seeds and tentative tracks a frame of false alarms starts.
inline constexpr std::size_t kMultiMaxTracks = 64;

enum class MultiAssociator { kNearestNeighbour, kGlobalNearestNeighbour, kOracle };

/// "nn", "gnn", "oracle"; throws std::invalid_argument otherwise.
MultiAssociator multi_associator_by_name(const std::string& name);
const char* multi_associator_name(MultiAssociator a);
/// GNN when the scenario has more than one target, nearest neighbour otherwise.
MultiAssociator default_multi_associator(const ScenarioInfo& info);

/// The radar filters of a multi-target run: EKF-CA, or the IMM (CV/CA/CT, docs/imm.md)
/// with its defaults and the `imm.KEY` settings.
enum class MultiFilter { kEkfCa, kImm };

MultiFilter multi_filter_by_name(const std::string& name);
const char* multi_filter_name(MultiFilter f);

struct MultiRunParams {
  MultiAssociator associator = MultiAssociator::kGlobalNearestNeighbour;
  MultiFilter filter = MultiFilter::kEkfCa;
  /// qj and the radar tracker's keys (filters/settings.hpp): defaults,
  /// then --config and --set. The confirmed-track gate is the board's
  /// unless gate_d2 is given.
  FilterOptions options;
  /// Gate of tentative tracks alone (default: gate_probability, 0.999).
  std::optional<GateProbability> gate_tentative;
  SpaParams spa;                        ///< c and p of OSPA and GOSPA.
  std::size_t persistence_steps = 3;    ///< Of swaps and fragmentation.
  std::uint64_t budget_ns = 1'000'000;
};

/// The tracker of a multi-target run: EKF-CA with two-point initiation (its
/// second hypotheses by the seed_* keys) and M-of-N, kMultiMaxTracks tracks,
/// the wire's 32 plots, the associator given.
template <class Filter, template <class, std::size_t, std::size_t> class Associator>
using MultiTargetTracker = Tracker<Filter, TwoPointHypothesesInitiator<CaMotion<double>, CaPolarRadar<double>>,
                                   kMultiMaxTracks, hal::kMaxRadarPlots, Associator>;

/// The filter every track starts from, by the config's settings.
template <class Filter>
Filter multi_target_filter(const MultiRunParams& config) {
  if constexpr (std::is_same_v<Filter, RadarImm<double>>) {
    return make_radar_imm<double>(imm_params(config.options));
  } else {
    const RadarTrackerParams p = radar_tracker_params(config.options);
    CaMotion<double> motion;
    motion.qj = p.qj;
    CaPolarRadar<double> radar;
    radar.sigma_range_m = p.sigma_range_m;
    radar.sigma_bearing_rad = p.sigma_bearing_rad;
    return EkfCa<double>(motion, radar);
  }
}

template <class Filter, template <class, std::size_t, std::size_t> class Associator>
std::unique_ptr<MultiTargetTracker<Filter, Associator>> make_multi_target_tracker(
    const MultiRunParams& config,
    const typename MultiTargetTracker<Filter, Associator>::AssociatorParams& params = {}) {
  using T = MultiTargetTracker<Filter, Associator>;
  const RadarTrackerParams p = radar_tracker_params(config.options);
  const Filter prototype = multi_target_filter<Filter>(config);
  const auto init = radar_initiator<T>(prototype.measurement(), p.max_speed_mps, p.init_accel_sigma_mps2, p);
  typename T::Config tc = tracker_config_of<double>(p);
  FilterOptions gate = config.options;
  gate.board_gate = true;
  apply_gate_options<double>(gate, tc);
  if (config.gate_tentative.has_value()) tc.gate_tentative = *config.gate_tentative;
  auto tracker = std::make_unique<T>(prototype, init, tc, typename T::ManagerT{}, params);
  apply_measurement_noise(*tracker, p);  // built without the adaptive noise: refuses a gain
  return tracker;
}

struct OracleLabels {
  std::map<std::int64_t, std::vector<int>> origins;
};

struct MultiRunDetail {
  std::uint64_t seed = 0;
  StreamRunResult stream;
  std::vector<MultiTargetStep> steps;
  MultiTargetRunMetrics metrics;
};

/// Generate `scenario` with `seed`, run the tracker over its wire stream and score it.
MultiRunDetail run_multi_once(const Scenario& scenario, std::uint64_t seed, const MultiRunParams& config);

/// The scored steps of a run: every target and the confirmed tracks per frame.
std::vector<MultiTargetStep> multi_target_steps(const ScenarioRun& run, const StreamRunResult& stream);

/// The tracker of `config` over a recorded stream (`replay`): nn or gnn;
/// the oracle, which needs each plot's origin, throws std::invalid_argument.
StreamRunResult run_multi_stream(const MultiRunParams& config, StreamInput input);

/// The scored steps of a replay against a truth of several targets
/// (targets[i]: target i's rows): each decoded frame at a time every target
/// has a row for, to the wire's microsecond; `without_truth` counts the
/// decoded frames without.
std::vector<MultiTargetStep> multi_target_steps_at_times(const std::vector<std::vector<TruthSample>>& targets,
                                                         const StreamRunResult& stream, std::size_t& without_truth);

}  // namespace kestrel::sim
