// SPDX-License-Identifier: Apache-2.0
// One evaluated run: a stream through a registered filter, scored against
// truth. Shared by `run` (one per seed), `replay` (one recorded stream)
// and `timing`.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "filters/filter_registry.hpp"
#include "metrics/run_metrics.hpp"
#include "metrics/scoring.hpp"
#include "metrics/track_continuity.hpp"
#include "pipeline/stream_run_result.hpp"
#include "scenarios/scenario.hpp"

namespace kestrel::sim {

struct RunDetail {
  std::uint64_t seed = 0;
  std::vector<MeasurementFrame> frames;  ///< What the stream carries (SI, as quantised).
  std::vector<TruthSample> truth;
  StreamRunResult stream;                ///< Per-frame tracker output.
  std::vector<ScoredStep> steps;         ///< Scored frames.
  RunMetrics metrics;
  double loss_threshold_m = 0.0;         ///< L the run was scored with, m.
};

/// Run `filter` over `stream` (a wire stream or a CAT048 recording, which
/// may also ask for CAT062 output) and score it.
/// @param frames the SI view of the stream (for the per-step CSV).
/// @param period_s T for the loss time; @param loss_threshold_m L.
RunDetail evaluate_stream(StreamInput stream, std::vector<MeasurementFrame> frames,
                          std::vector<TruthSample> truth, const FilterEntry& filter, const FilterOptions& options,
                          std::uint64_t budget_ns, const ScoringParams& scoring, double period_s,
                          double loss_threshold_m);

/// Generate the scenario with `seed`, encode it, run and score it.
/// @param cat062 when set, the run also writes its reports as CAT062
///        (RunDetail::stream.cat062) with this source.
RunDetail run_scenario_once(const Scenario& scenario, std::uint64_t seed, const FilterEntry& filter,
                            const FilterOptions& options, std::uint64_t budget_ns, const ScoringParams& scoring,
                            std::optional<hal::asterix::Cat062Source> cat062 = std::nullopt);

/// The confirmed tracks within `loss_threshold_m` of the truth at each
/// scored step (the input of compute_track_continuity()).
std::vector<OnTargetTracks> on_target_tracks(const RunDetail& detail);

/// Run metrics of scored steps.
RunMetrics metrics_of(const std::vector<ScoredStep>& steps, double period_s, double loss_threshold_m);

}  // namespace kestrel::sim
