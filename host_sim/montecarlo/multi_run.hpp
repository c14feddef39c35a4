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
#include <optional>
#include <string>
#include <vector>

#include "filters/filter_registry.hpp"
#include "kestrel/association/chi_square.hpp"
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

struct MultiRunConfig {
  MultiAssociator associator = MultiAssociator::kGlobalNearestNeighbour;
  std::optional<double> qj;             ///< EKF-CA white-jerk PSD (default RadarTrackerParams').
  std::optional<unsigned> confirm_m;    ///< M-of-N (default RadarTrackerParams').
  std::optional<unsigned> confirm_n;
  /// Two-point pairs faster than this are refused, m/s (default RadarTrackerParams' 1000).
  std::optional<double> max_speed_mps;
  /// Gate of tentative tracks (default RadarTrackerParams' gate, 0.999).
  std::optional<GateProbability> gate_tentative;
  SpaConfig spa;                        ///< c and p of OSPA and GOSPA.
  std::size_t persistence_steps = 3;    ///< Of swaps and fragmentation.
  std::uint64_t budget_ns = 1'000'000;
};

/// Each plot's true origin by frame time (us on the wire): what the oracle
/// associator is told.
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
MultiRunDetail run_multi_once(const Scenario& scenario, std::uint64_t seed, const MultiRunConfig& config);

/// The scored steps of a run: every target and the confirmed tracks per frame.
std::vector<MultiTargetStep> multi_target_steps(const ScenarioRun& run, const StreamRunResult& stream);

}  // namespace kestrel::sim
