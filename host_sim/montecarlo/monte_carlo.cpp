// SPDX-License-Identifier: Apache-2.0
#include "montecarlo/monte_carlo.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "pipeline/worker_pool.hpp"

namespace kestrel::sim {

RunRecord record_of(const RunDetail& d) {
  RunRecord r;
  r.seed = d.seed;
  r.metrics = d.metrics;
  for (const FrameOutcome& f : d.stream.frames) {
    if (f.stepped) r.step_ns.push_back(f.step_ns);
    if (f.status != Status::kOk) ++r.frames_not_ok;
  }
  // A change of the scored track's id means the tracker dropped the target
  // and started a new track on it (or a duplicate became the nearest):
  // nearest-track scoring would otherwise hide it.
  std::uint32_t last_id = 0;
  for (const ScoredStep& s : d.steps) {
    r.max_confirmed_tracks = std::max(r.max_confirmed_tracks, s.confirmed_tracks);
    if (!s.estimate.has_value()) continue;
    if (last_id != 0 && s.estimate->track_id != last_id) ++r.track_switches;
    last_id = s.estimate->track_id;
    if (s.k >= d.stream.frames.size()) continue;
    const FrameOutcome& f = d.stream.frames[s.k];
    if (f.mode_probabilities.size() != f.tracks.size()) continue;  // a filter without modes
    for (std::size_t i = 0; i < f.tracks.size(); ++i) {
      if (f.tracks[i].track_id == s.estimate->track_id) {
        r.modes.push_back(ModeSample{s.t_s, s.estimate->track_id, f.mode_probabilities[i]});
        break;
      }
    }
  }
  r.continuity = compute_track_continuity(on_target_tracks(d));
  return r;
}

MonteCarloResult run_monte_carlo(const Scenario& scenario, const FilterEntry& filter, const MonteCarloParams& config) {
  MonteCarloResult result;
  result.runs.resize(config.runs);
  const std::string label(filter.name);
  for_each_index(
      config.runs, config.jobs,
      [&](std::size_t i) {
        RunDetail d = run_scenario_once(scenario, config.base_seed + i, filter, config.options, config.budget_ns,
                                        config.scoring);
        result.runs[i] = record_of(d);
        if (i == 0) result.first = std::move(d);  // only the worker that takes i == 0 writes it
      },
      Progress{label.c_str()});
  return result;
}

MonteCarloSummary summarise(const std::vector<RunRecord>& runs, std::uint64_t budget_ns) {
  MonteCarloSummary s;
  s.runs = runs.size();
  std::vector<double> recovery;
  s.worst_held_fraction = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::uint64_t> all_steps;
  for (const RunRecord& r : runs) {
    const double f = r.continuity.held_fraction;
    if (std::isfinite(f) && (std::isnan(s.worst_held_fraction) || f < s.worst_held_fraction)) {
      s.worst_held_fraction = f;
    }
    s.max_track_ids_on_target = std::max(s.max_track_ids_on_target, r.continuity.track_ids_on_target);
    // docs/metrics.md: recovery is averaged over the runs that had an episode.
    if (!r.metrics.episodes.empty()) recovery.push_back(r.metrics.recovery_s);
    else ++s.runs_without_loss;
    if (r.metrics.missing_steps > 0) ++s.runs_with_missing;
    s.missing_steps += r.metrics.missing_steps;
    s.max_confirmed_tracks = std::max(s.max_confirmed_tracks, r.max_confirmed_tracks);
    s.frames_not_ok += r.frames_not_ok;
    all_steps.insert(all_steps.end(), r.step_ns.begin(), r.step_ns.end());
  }
  using R = RunRecord;
  s.rmse_m = mean_ci95_of(runs, [](const R& r) { return r.metrics.rmse_m; });
  s.peak_m = mean_ci95_of(runs, [](const R& r) { return r.metrics.peak_m; });
  s.nees_pos = mean_ci95_of(runs, [](const R& r) { return r.metrics.nees_pos; });
  s.nis = mean_ci95_of(runs, [](const R& r) { return r.metrics.nis; });
  s.track_loss_s = mean_ci95_of(runs, [](const R& r) { return r.metrics.track_loss_s; });
  s.recovery_s = mean_ci95(recovery);
  s.track_switches = mean_ci95_of(runs, &R::track_switches);
  s.held_fraction = mean_ci95_of(runs, [](const R& r) { return r.continuity.held_fraction; });
  s.loss_episodes = mean_ci95_of(runs, [](const R& r) { return r.metrics.episodes.size(); });
  s.track_ids_on_target = mean_ci95_of(runs, [](const R& r) { return r.continuity.track_ids_on_target; });
  s.false_tracks = mean_ci95_of(runs, [](const R& r) { return r.continuity.false_tracks; });
  s.timing = summarise_step_times(all_steps, budget_ns);
  return s;
}

}  // namespace kestrel::sim
