// SPDX-License-Identifier: Apache-2.0
// `kestrel-sim sweep`: one scenario and one filter over a list of values of
// one parameter, each through the same runs as `run` (same seeds), in one
// summary.json (and, for a single-target radar scenario, one table): any
// scenario `run` takes, with the keys of its tracker.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/scenario_report.hpp"
#include "filters/sensor_settings.hpp"
#include "filters/settings.hpp"
#include "report/summary_json.hpp"
#include "scenarios/registry.hpp"
#include "scenarios/sensor_kind.hpp"

namespace kestrel::sim::cli {

namespace {

/// The swept parameter: its key, and each value as written (for the tag)
/// and as a setting.
struct Sweep {
  std::string key;
  std::vector<std::string> texts;
  std::vector<Setting> values;
};

/// Picks the swept --set out of `sets` (the one with a list, else the
/// first) and leaves the fixed ones in `fixed`.
Sweep split_sets(const std::vector<std::string>& sets, std::vector<std::string>& fixed) {
  std::size_t swept = 0;
  std::size_t lists = 0;
  for (std::size_t i = 0; i < sets.size(); ++i) {
    if (sets[i].find(',') != std::string::npos) {
      swept = i;
      ++lists;
    }
  }
  if (sets.empty()) throw std::invalid_argument("--set KEY=V1,V2,... is required (e.g. qj=1.6,16,160)");
  if (lists > 1) throw std::invalid_argument("--set: a sweep varies one parameter; give one KEY=V1,V2,... only");
  Sweep sweep;
  const std::string& text = sets[swept];
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0) throw std::invalid_argument("--set " + text + ": expected KEY=V1,V2,...");
  sweep.key = text.substr(0, eq);
  std::size_t start = eq + 1;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    sweep.texts.push_back(item);
    sweep.values.push_back(parse_setting(sweep.key + "=" + item, "--set"));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  for (std::size_t i = 0; i < sets.size(); ++i) {
    if (i != swept) fixed.push_back(sets[i]);
  }
  return sweep;
}

std::filesystem::path sweep_dir(const SweepOptions& o, const std::string& scenario, const std::string& filter) {
  return o.out.empty() ? std::filesystem::path("results") / ("sweep-" + scenario + "-" + filter)
                       : std::filesystem::path(o.out);
}

/// The sweep of a scenario that `run` scores with figures of another kind
/// (PCL, sonar, several targets): per value one `run` into <out>/<tag>, whose
/// summary.json entry goes into <out>/summary.json with the swept value.
int sweep_by_run(const SweepOptions& o, const Sweep& sweep, const std::vector<std::string>& fixed,
                 hal::FrameKind kind, const std::string& scenario) {
  const std::string filter = !o.filter.filter_given && kind == hal::FrameKind::kPcl     ? std::string(kPclFilterName)
                             : !o.filter.filter_given && kind == hal::FrameKind::kSonar ? std::string(kSonarFilterName)
                                                                                      : o.filter.filter;
  const std::filesystem::path dir = sweep_dir(o, scenario, filter);
  // Every value is checked before the first run.
  std::vector<RunOptions> runs(sweep.values.size());
  for (std::size_t i = 0; i < runs.size(); ++i) {
    RunOptions& r = runs[i];
    r.scenario = scenario;
    r.filter = o.filter;
    r.filter.sets = fixed;
    r.filter.sets.push_back(sweep.key + "=" + sweep.texts[i]);
    r.runs = o.runs;
    r.seed = o.seed;
    r.jobs = o.jobs;
    r.plots = o.plots;
    r.out = (dir / (filter + "-" + sweep.key + sweep.texts[i])).string();
    const std::vector<Setting> settings = read_settings(r.filter.config, r.filter.sets);
    if (kind == hal::FrameKind::kPcl) {
      PclTrackerParams scratch;
      apply_pcl_settings(settings, scratch);
    } else if (kind == hal::FrameKind::kSonar) {
      SonarTrackerParams scratch;
      apply_sonar_settings(settings, scratch);
    } else {
      resolve_settings(r.filter, r.filter.sets);
    }
  }
  nlohmann::json results = nlohmann::json::object();
  for (std::size_t i = 0; i < runs.size(); ++i) {
    std::fprintf(stderr, "kestrel-sim sweep: %s = %s (%zu of %zu), %zu runs\n", sweep.key.c_str(),
                 sweep.texts[i].c_str(), i + 1, runs.size(), o.runs);
    const std::filesystem::path summary = std::filesystem::path(runs[i].out) / "summary.json";
    std::filesystem::remove(summary);  // the value's entry alone, not a merge with an older run
    const int rc = kind == hal::FrameKind::kRadar ? run_multi_target_scenario(runs[i]) : run_sensor_scenario(runs[i], kind);
    if (rc != 0) return rc;
    std::ifstream in(summary);
    const nlohmann::json written = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    if (!written.is_object() || !written.contains("results")) {
      throw std::runtime_error(summary.string() + ": no summary written");
    }
    for (const auto& [name, entries] : written["results"].items()) {
      for (const auto& [written_filter, entry] : entries.items()) {
        nlohmann::json e = entry;
        e["sweep"] = {{"parameter", sweep.key}, {"value", sweep.values[i].value}};
        results[name][written_filter + "-" + sweep.key + sweep.texts[i]] = e;
      }
    }
  }
  write_summary_file(dir / "summary.json", results);
  std::printf("wrote %s and per value a directory %s-%s<value> under %s\n", (dir / "summary.json").c_str(),
              filter.c_str(), sweep.key.c_str(), dir.c_str());
  return 0;
}

}  // namespace

int cmd_sweep(const SweepOptions& o) {
  std::vector<std::string> fixed;
  const Sweep sweep = split_sets(o.filter.sets, fixed);
  const std::string& key = sweep.key;
  if (o.runs == 0) throw std::invalid_argument("--runs must be at least 1");
  const std::optional<hal::FrameKind> kind = scenario_kind(o.scenario);
  if (kind.has_value() && *kind != hal::FrameKind::kRadar) {
    check_filter_fits(o.filter, *kind, "scenario '" + o.scenario + "' is a " + sensor_kind_name(*kind) + " scenario");
    return sweep_by_run(o, sweep, fixed, *kind, o.scenario);
  }
  const auto made = make_scenario(o.scenario);
  if (made->info().targets > 1) return sweep_by_run(o, sweep, fixed, hal::FrameKind::kRadar, made->info().name);
  FilterChoice base = o.filter;
  resolve_settings(base, fixed);
  // Every value is checked before the first run.
  std::vector<FilterOptions> options(sweep.values.size(), base.options);
  for (std::size_t i = 0; i < sweep.values.size(); ++i) apply_settings({&sweep.values[i], 1}, options[i]);
  const std::string scenario = made->info().name;
  const std::filesystem::path dir = sweep_dir(o, scenario, o.filter.filter);
  auto config = monte_carlo_params<MonteCarloParams>(o);

  nlohmann::json results = nlohmann::json::object();
  std::vector<TableRow> rows;
  for (std::size_t i = 0; i < options.size(); ++i) {
    config.options = options[i];
    const std::string tag = o.filter.filter + "-" + key + sweep.texts[i];
    std::fprintf(stderr, "kestrel-sim sweep: %s = %s (%zu of %zu), %zu runs\n", key.c_str(), sweep.texts[i].c_str(),
                 i + 1, options.size(), o.runs);
    ScenarioReport r = run_scenario_report(scenario, o.filter.filter, config, dir, o.plots, tag);
    r.entry["sweep"] = {{"parameter", key}, {"value", sweep.values[i].value}};
    results[scenario][tag] = r.entry;
    rows.push_back(std::move(r.row));
  }
  write_summary_file(dir / "summary.json", results);
  print_table_header(stdout);
  for (const TableRow& r : rows) print_table_row(stdout, r);
  std::printf("wrote %s and per value <filter>-%s<value>_{tracks,steps,runs}.csv under %s\n",
              (dir / "summary.json").c_str(), key.c_str(), dir.c_str());
  return 0;
}

}  // namespace kestrel::sim::cli
