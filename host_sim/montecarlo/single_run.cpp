// SPDX-License-Identifier: Apache-2.0
#include "montecarlo/single_run.hpp"

#include <cmath>
#include <utility>

#include "stream/quantise.hpp"
#include "stream/stream_writer.hpp"

namespace kestrel::sim {

RunMetrics metrics_of(const std::vector<ScoredStep>& steps, double period_s, double loss_threshold_m) {
  std::vector<StepError> errors;
  errors.reserve(steps.size());
  for (const ScoredStep& s : steps) errors.push_back(StepError{s.error_m, s.nees, s.nis});
  return compute_run_metrics(errors, period_s, loss_threshold_m);
}

std::vector<OnTargetTracks> on_target_tracks(const RunDetail& d) {
  std::vector<OnTargetTracks> out;
  out.reserve(d.steps.size());
  for (const ScoredStep& s : d.steps) {
    OnTargetTracks on;
    for (const host::TrackRow& row : d.stream.frames[s.k].tracks) {
      if (!row.confirmed) continue;
      if (std::hypot(row.x_m - s.truth.x_m, row.y_m - s.truth.y_m) <= d.loss_threshold_m) {
        on.ids.push_back(row.track_id);
      } else {
        on.off_ids.push_back(row.track_id);
      }
    }
    out.push_back(std::move(on));
  }
  return out;
}

RunDetail evaluate_stream(StreamInput stream, std::vector<MeasurementFrame> frames,
                          std::vector<TruthSample> truth, const FilterEntry& filter, const FilterOptions& options,
                          std::uint64_t budget_ns, const ScoringParams& scoring, double period_s,
                          double loss_threshold_m) {
  RunDetail d;
  d.frames = std::move(frames);
  d.truth = std::move(truth);
  d.stream = filter.run(std::move(stream), options, budget_ns);
  d.steps = score_run(d.stream, d.truth, scoring);
  d.metrics = metrics_of(d.steps, period_s, loss_threshold_m);
  d.loss_threshold_m = loss_threshold_m;
  return d;
}

RunDetail run_scenario_once(const Scenario& scenario, std::uint64_t seed, const FilterEntry& filter,
                            const FilterOptions& options, std::uint64_t budget_ns, const ScoringParams& scoring,
                            std::optional<hal::asterix::Cat062Source> cat062) {
  ScenarioRun generated = scenario.generate(seed);
  std::vector<std::uint8_t> bytes = encode_stream(generated.frames);
  // Keep the frames as the wire carries them, so the per-step CSV shows
  // exactly what the tracker saw.
  std::vector<MeasurementFrame> wire_frames;
  wire_frames.reserve(generated.frames.size());
  for (const MeasurementFrame& f : generated.frames) wire_frames.push_back(from_wire_frame(to_wire_frame(f)));
  const ScenarioInfo& info = scenario.info();
  StreamInput input(std::move(bytes));
  input.cat062 = cat062;
  RunDetail d = evaluate_stream(std::move(input), std::move(wire_frames), std::move(generated.truth), filter,
                                options, budget_ns, scoring, info.frame_period_s, info.loss_threshold_m);
  d.seed = seed;
  return d;
}

}  // namespace kestrel::sim
