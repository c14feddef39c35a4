// SPDX-License-Identifier: Apache-2.0
// `run` of a multi-target radar scenario (crossing, raid, formation-split;
// docs/multitarget.md): the Monte Carlo of the multi-target tracker, scored
// with OSPA, GOSPA, track swaps, false confirmed tracks, fragmentation and
// time to confirm, optionally beside the same runs with the oracle
// associator; `replay` against several targets' truth and `timing` of such
// a scenario take the same tracker.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/scenario_report.hpp"
#include "filters/ekf_ca.hpp"
#include "filters/imm_filters.hpp"
#include "filters/sensor_settings.hpp"
#include "metrics/monte_carlo_stats.hpp"
#include "montecarlo/multi_run.hpp"
#include "pipeline/worker_pool.hpp"
#include "plots/plot_runner.hpp"
#include "report/output_files.hpp"
#include "report/run_files.hpp"
#include "report/summary_json.hpp"
#include "scenarios/registry.hpp"
#include "scenarios/sensor_kind.hpp"

namespace kestrel::sim::cli {

namespace {

struct Summary {
  MeanCi gospa, ospa, localisation, missed, false_per_step, swaps, no_swap, false_tracks, fragmentations,
      time_to_confirm, unconfirmed;
};

/// A run's mean time to confirm over the targets it confirmed (NaN if none).
double mean_time_to_confirm_s(const MultiTargetRunMetrics& m) {
  double sum = 0.0;
  std::size_t n = 0;
  for (const double t : m.time_to_confirm_s) {
    if (t < 0.0) continue;  // never confirmed
    sum += t;
    ++n;
  }
  return n > 0 ? sum / static_cast<double>(n) : std::nan("");
}

Summary summarise(const std::vector<MultiTargetRunMetrics>& runs) {
  using M = MultiTargetRunMetrics;
  const auto never_confirmed = [](const M& m) {
    return std::count_if(m.time_to_confirm_s.begin(), m.time_to_confirm_s.end(), [](double t) { return t < 0.0; });
  };
  return Summary{mean_ci95_of(runs, &M::mean_gospa_m),
                 mean_ci95_of(runs, &M::mean_ospa_m),
                 mean_ci95_of(runs, &M::mean_gospa_localisation_m),
                 mean_ci95_of(runs, &M::mean_missed),
                 mean_ci95_of(runs, &M::mean_false),
                 mean_ci95_of(runs, &M::swaps),
                 mean_ci95_of(runs, [](const M& m) { return m.swaps == 0 ? 1.0 : 0.0; }),
                 mean_ci95_of(runs, &M::false_tracks),
                 mean_ci95_of(runs, &M::fragmentations),
                 mean_ci95_of(runs, mean_time_to_confirm_s),
                 mean_ci95_of(runs, never_confirmed)};
}

void print_ci(const char* name, const MeanCi& m, const char* unit) {
  std::printf("  %-40s %9.4f  [%.4f, %.4f] %s\n", name, m.mean, m.ci95_low, m.ci95_high, unit);
}

void print_summary(const char* label, const Summary& s) {
  std::printf(" %s, mean over runs [95 %% interval]:\n", label);
  print_ci("GOSPA (mean over steps)", s.gospa, "m");
  print_ci("OSPA (mean over steps)", s.ospa, "m");
  print_ci("GOSPA localisation part", s.localisation, "m");
  print_ci("missed targets per step", s.missed, "");
  print_ci("false tracks per step", s.false_per_step, "");
  print_ci("track swaps per run", s.swaps, "");
  print_ci("runs without a track swap", s.no_swap, "(fraction)");
  print_ci("false confirmed tracks per run", s.false_tracks, "");
  print_ci("fragmentations per run", s.fragmentations, "");
  print_ci("time to confirm", s.time_to_confirm, "s");
  print_ci("targets never confirmed per run", s.unconfirmed, "");
}

nlohmann::json summary_json(const Summary& s) {
  return {{"gospa_m", interval_json(s.gospa)},
          {"ospa_m", interval_json(s.ospa)},
          {"gospa_localisation_m", interval_json(s.localisation)},
          {"missed_targets_per_step", interval_json(s.missed)},
          {"false_tracks_per_step", interval_json(s.false_per_step)},
          {"track_swaps_per_run", interval_json(s.swaps)},
          {"runs_without_swap", interval_json(s.no_swap)},
          {"false_confirmed_tracks_per_run", interval_json(s.false_tracks)},
          {"fragmentations_per_run", interval_json(s.fragmentations)},
          {"time_to_confirm_s", interval_json(s.time_to_confirm)},
          {"targets_never_confirmed_per_run", interval_json(s.unconfirmed)}};
}

/// The results[scenario][filter] entry of summary.json: the settings, the
/// associator's figures and, with --compare-oracle, the oracle's.
nlohmann::json summary_entry(const RunOptions& o, const ScenarioInfo& info, const MultiRunParams& config,
                             const char* filter_label, const Summary* main, const Summary* oracle) {
  FilterOptions gate = config.options;
  gate.board_gate = true;  // make_multi_target_tracker gates confirmed tracks as a board does
  const FilterSetup setup = config.filter == MultiFilter::kImm ? imm_setup(gate) : ekf_ca_setup(gate);
  nlohmann::json parameters = nlohmann::json::object();
  for (const auto& [name, value] : setup.parameters) parameters[name] = value;
  if (config.gate_tentative.has_value()) parameters["gate_tentative"] = gate_probability(*config.gate_tentative);
  nlohmann::json entry = {{"kind", sensor_kind_name(hal::FrameKind::kRadar)},
                          {"scenario", info.name},
                          {"targets", info.targets},
                          {"filter", multi_filter_name(config.filter)},
                          {"filter_label", filter_label},
                          {"associator", multi_associator_name(config.associator)},
                          {"parameters", parameters},
                          {"runs", o.runs},
                          {"base_seed", o.seed},
                          {"cutoff_m", o.kind.cutoff_m},
                          {"order", o.kind.order},
                          {"persistence_steps", o.kind.persistence_steps}};
  if (main != nullptr) entry.update(summary_json(*main));
  if (oracle != nullptr) entry["oracle"] = summary_json(*oracle);
  return entry;
}

struct McResult {
  std::vector<MultiTargetRunMetrics> runs;
};

McResult run_mc(const Scenario& scenario, const RunOptions& o, const MultiRunParams& config) {
  McResult r;
  r.runs.resize(o.runs);
  for_each_index(
      o.runs, o.jobs, [&](std::size_t i) { r.runs[i] = run_multi_once(scenario, o.seed + i, config).metrics; },
      Progress{multi_associator_name(config.associator)});
  return r;
}

void write_runs_csv(const std::filesystem::path& path, const RunOptions& o, const char* associator,
                    const std::vector<MultiTargetRunMetrics>& runs, bool append) {
  std::ofstream f(path, append ? std::ios::app : std::ios::trunc);
  if (!append) {
    f << "associator,seed,gospa_m,ospa_m,gospa_localisation_m,missed_per_step,false_per_step,swaps,false_tracks,"
         "confirmed_tracks,fragmentations\n";
  }
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const MultiTargetRunMetrics& m = runs[i];
    f << associator << ',' << o.seed + i << ',' << m.mean_gospa_m << ',' << m.mean_ospa_m << ','
      << m.mean_gospa_localisation_m << ',' << m.mean_missed << ',' << m.mean_false << ',' << m.swaps << ','
      << m.false_tracks << ',' << m.confirmed_tracks << ',' << m.fragmentations << '\n';
  }
}

/// `times_s`: each step's time (a replay's frames); empty: k x the
/// scenario's frame period.
void write_steps_csv(const std::filesystem::path& path, const ScenarioInfo& info,
                     const std::vector<std::pair<const char*, const std::vector<MultiTargetRunMetrics>*>>& sets,
                     const std::vector<double>& times_s = {}) {
  std::ofstream f(path);
  f << "step,time_s";
  for (const auto& [name, runs] : sets) f << ",gospa_m_" << name << ",ospa_m_" << name;
  f << '\n';
  for (std::size_t k = 0; k < info.steps; ++k) {
    f << k << ',' << (k < times_s.size() ? times_s[k] : static_cast<double>(k) * info.frame_period_s);
    for (const auto& [name, runs] : sets) {
      double g = 0.0, os = 0.0;
      std::size_t n = 0;
      for (const MultiTargetRunMetrics& m : *runs) {
        if (k >= m.gospa_m.size()) continue;
        g += m.gospa_m[k];
        os += m.ospa_m[k];
        ++n;
      }
      f << ',' << (n ? g / static_cast<double>(n) : std::nan("")) << ',' << (n ? os / static_cast<double>(n) : std::nan(""));
    }
    f << '\n';
  }
}

/// The runs' parameters: the options' associator (GNN by default with more
/// than one target), filter, scoring and budget over `options`, the radar
/// tracker's settings already resolved.
MultiRunParams multi_params(const RunOptions& o, const ScenarioInfo& info) {
  if (o.runs == 0) throw std::invalid_argument("--runs must be at least 1");
  if (!(o.kind.cutoff_m > 0.0) || !(o.kind.order >= 1.0)) throw std::invalid_argument("--cutoff must be positive and --order at least 1");
  if (o.kind.persistence_steps < 1) throw std::invalid_argument("--persistence must be at least 1");
  MultiRunParams config;
  config.associator = o.kind.associator.empty() ? default_multi_associator(info) : multi_associator_by_name(o.kind.associator);
  config.filter = multi_filter_by_name(o.filter.filter);
  config.options = o.filter.options;
  if (o.kind.gate_tentative) config.gate_tentative = gate_option(*o.kind.gate_tentative, "--gate-tentative");
  config.spa = SpaParams{o.kind.cutoff_m, o.kind.order};
  config.persistence_steps = o.kind.persistence_steps;
  config.budget_ns = budget_ns_from_us(o.filter.budget_us);
  return config;
}

int report_multi(const RunOptions& o, const Scenario& scenario, const MultiRunParams& config) {
  const ScenarioInfo& info = scenario.info();
  const std::filesystem::path dir =
      o.out.empty() ? std::filesystem::path("results") / (info.name + "-multi") : std::filesystem::path(o.out);
  std::filesystem::create_directories(dir);

  const McResult main = run_mc(scenario, o, config);
  const RadarTrackerParams p = radar_tracker_params(config.options);
  char filter[64];
  if (config.filter == MultiFilter::kImm) {
    std::snprintf(filter, sizeof filter, "IMM CV/CA/CT (CA qj %g)", imm_params(config.options).ca_qj);
  } else {
    std::snprintf(filter, sizeof filter, "EKF-CA qj %g", p.qj);
  }
  std::printf("%s: %zu targets, %zu runs (seeds %llu..%llu), %s, %u-of-%u, max speed %g m/s, %s, c %g m, p %g\n",
              info.name.c_str(), info.targets, o.runs, static_cast<unsigned long long>(o.seed),
              static_cast<unsigned long long>(o.seed + o.runs - 1), filter, unsigned{p.confirm_m},
              unsigned{p.confirm_n}, p.max_speed_mps, multi_associator_name(config.associator), o.kind.cutoff_m, o.kind.order);
  const Summary s = summarise(main.runs);
  print_summary(multi_associator_name(config.associator), s);
  write_runs_csv(dir / "multi_runs.csv", o, multi_associator_name(config.associator), main.runs, false);
  std::vector<std::pair<const char*, const std::vector<MultiTargetRunMetrics>*>> sets{
      {multi_associator_name(config.associator), &main.runs}};
  McResult oracle;
  std::optional<Summary> so;
  if (o.kind.compare_oracle && config.associator != MultiAssociator::kOracle) {
    MultiRunParams oc = config;
    oc.associator = MultiAssociator::kOracle;
    oracle = run_mc(scenario, o, oc);
    so = summarise(oracle.runs);
    print_summary("oracle", *so);
    write_runs_csv(dir / "multi_runs.csv", o, "oracle", oracle.runs, true);
    sets.emplace_back("oracle", &oracle.runs);
    // Paired over seeds: the per-run excess of GOSPA over the oracle's,
    // relative to the oracle's mean.
    std::vector<double> excess;
    for (std::size_t i = 0; i < o.runs; ++i) excess.push_back(main.runs[i].mean_gospa_m - oracle.runs[i].mean_gospa_m);
    const MeanCi e = mean_ci95(excess);
    std::printf(" GOSPA %s / oracle: %.4f; paired excess %.3f m [%.3f, %.3f], i.e. %+.1f %% [%+.1f, %+.1f] of the oracle's\n",
                multi_associator_name(config.associator), s.gospa.mean / so->gospa.mean, e.mean, e.ci95_low,
                e.ci95_high, 100.0 * e.mean / so->gospa.mean, 100.0 * e.ci95_low / so->gospa.mean,
                100.0 * e.ci95_high / so->gospa.mean);
  }
  write_steps_csv(dir / "multi_steps.csv", info, sets);
  merge_summary_file(dir / "summary.json", info.name, multi_filter_name(config.filter),
                     summary_entry(o, info, config, filter, &s, so ? &*so : nullptr));
  std::printf("wrote %s/{multi_runs.csv, multi_steps.csv, summary.json}\n", dir.c_str());
  if (o.plots && plot_gospa(dir / "multi_steps.csv", dir / "multi_gospa.png",
                            info.name + " / seeds " + std::to_string(o.seed) + ".." +
                                std::to_string(o.seed + o.runs - 1))) {
    std::printf("wrote %s/multi_gospa.png\n", dir.c_str());
  }
  return 0;
}

}  // namespace

std::vector<std::string> multi_target_replay_refuses(const ReplayOptions& o) {
  static const char* const kNotForMulti[] = {"--ungated", "--loss-threshold-m", "--first-scored-step",
                                             "--asterix-out", "--sac", "--sic"};
  std::vector<std::string> out;
  for (const char* n : kNotForMulti) {
    if (std::find(o.filter.radar_only_given.begin(), o.filter.radar_only_given.end(), n) !=
        o.filter.radar_only_given.end()) {
      out.emplace_back(n);
    }
  }
  return out;
}

int replay_multi_target(const ReplayOptions& r, const FilterChoice& filter, StreamInput input,
                        const std::vector<std::vector<TruthSample>>& targets, const std::string& source) {
  RunOptions o;  // run's defaults for several targets: c 500 m, p 2, swaps held 3 steps
  o.runs = 1;
  o.out = r.out;
  o.plots = r.plots;
  o.filter = filter;
  o.kind.associator = r.associator.empty() ? "gnn" : r.associator;  // GNN even if the truth names one target
  ScenarioInfo info;
  info.name = "replay";
  info.targets = targets.size();
  const MultiRunParams config = multi_params(o, info);
  const StreamRunResult stream = run_multi_stream(config, std::move(input));
  const std::filesystem::path dir(o.out);
  std::filesystem::create_directories(dir);
  const std::string name = multi_filter_name(config.filter);
  const char* associator = multi_associator_name(config.associator);
  const std::filesystem::path tracks_csv = dir / (name + "_tracks.csv");
  write_track_csv(tracks_csv, stream);

  if (targets.empty()) {
    std::set<std::uint32_t> ids;
    std::size_t rows = 0, steps = 0;
    for (const FrameOutcome& f : stream.frames) {
      steps += f.stepped ? 1 : 0;
      for (const host::TrackRow& t : f.tracks) {
        if (!t.confirmed) continue;
        ++rows;
        ids.insert(t.track_id);
      }
    }
    std::printf("replay %s: multi-target tracker, %s, %s; %zu frames stepped, %zu confirmed-track rows, %zu track "
                "ids; not scored (no --truth)\n",
                source.c_str(), name.c_str(), associator, steps, rows, ids.size());
    nlohmann::json entry = summary_entry(o, info, config, name.c_str(), nullptr, nullptr);
    for (const char* key : {"base_seed", "targets", "runs", "cutoff_m", "order", "persistence_steps"}) entry.erase(key);
    entry["source"] = source;
    entry["scored"] = false;
    entry["frames_stepped"] = steps;
    entry["confirmed_track_rows"] = rows;
    entry["track_ids"] = ids.size();
    merge_summary_file(dir / "summary.json", info.name, name, entry);
    std::printf("wrote %s, %s\n", tracks_csv.c_str(), (dir / "summary.json").c_str());
    return 0;
  }

  std::size_t without_truth = 0;
  const std::vector<MultiTargetStep> steps = multi_target_steps_at_times(targets, stream, without_truth);
  const std::vector<MultiTargetRunMetrics> runs{compute_multi_target_metrics(steps, config.spa, config.persistence_steps)};
  info.steps = steps.size();
  std::vector<double> times_s;
  for (const MultiTargetStep& st : steps) times_s.push_back(st.t_s);
  write_steps_csv(dir / "multi_steps.csv", info, {{associator, &runs}}, times_s);
  const Summary s = summarise(runs);
  std::printf("replay %s: %zu targets in %s; scored %zu frames (%zu decoded frames at a time without every "
              "target's truth), %s, %s, c %g m, p %g\n",
              source.c_str(), targets.size(), r.truth.c_str(), steps.size(), without_truth, name.c_str(), associator,
              o.kind.cutoff_m, o.kind.order);
  print_summary(associator, s);
  nlohmann::json entry = summary_entry(o, info, config, name.c_str(), &s, nullptr);
  entry.erase("base_seed");
  entry["source"] = source;
  entry["truth"] = r.truth;
  entry["scored"] = true;
  entry["truth_frames"] = {{"matched", steps.size()}, {"without_truth", without_truth}};
  merge_summary_file(dir / "summary.json", info.name, name, entry);
  std::printf("wrote %s, %s/{multi_steps.csv, summary.json}\n", tracks_csv.c_str(), dir.c_str());
  if (o.plots && plot_gospa(dir / "multi_steps.csv", dir / "multi_gospa.png", "replay " + source)) {
    std::printf("wrote %s/multi_gospa.png\n", dir.c_str());
  }
  return 0;
}

std::vector<std::uint64_t> multi_target_step_times(const TimingOptions& t, std::string& what) {
  const auto scenario = make_scenario(t.scenario);
  RunOptions o;
  o.runs = t.runs;
  o.seed = t.seed;
  o.filter = t.filter;
  const MultiRunParams config = multi_params(o, scenario->info());
  std::vector<std::uint64_t> step_ns;
  for (std::size_t i = 0; i < o.runs; ++i) {
    const MultiRunDetail d = run_multi_once(*scenario, o.seed + i, config);
    for (const FrameOutcome& f : d.stream.frames) {
      if (f.stepped) step_ns.push_back(f.step_ns);
    }
  }
  what = scenario->info().name + " / multi-target tracker (" + multi_filter_name(config.filter) + ", " +
         multi_associator_name(config.associator) + "), " + std::to_string(o.runs) + " runs";
  return step_ns;
}

int run_multi_target_scenario(const RunOptions& r) {
  if (!r.asterix_out.path.empty()) {
    throw std::invalid_argument("--asterix-out: a run of a multi-target scenario writes no CAT062");
  }
  // main() has resolved --config, --set and the options of their own into
  // r.filter.options.
  const auto scenario = make_scenario(r.scenario);
  return report_multi(r, *scenario, multi_params(r, scenario->info()));
}

}  // namespace kestrel::sim::cli
