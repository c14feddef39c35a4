// SPDX-License-Identifier: Apache-2.0
// `kestrel-sim sweep`: one scenario and one filter over a list of values of
// one parameter, each through the same runs as `run` (same seeds), in one
// table and one summary.json.
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/scenario_report.hpp"
#include "filters/settings.hpp"
#include "report/summary_json.hpp"
#include "scenarios/registry.hpp"

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

}  // namespace

int cmd_sweep(const SweepOptions& o) {
  std::vector<std::string> fixed;
  const Sweep sweep = split_sets(o.filter.sets, fixed);
  const std::string& key = sweep.key;
  FilterChoice base = o.filter;
  resolve_settings(base, fixed);
  // Every value is checked before the first run.
  std::vector<FilterOptions> options(sweep.values.size(), base.options);
  for (std::size_t i = 0; i < sweep.values.size(); ++i) apply_settings({&sweep.values[i], 1}, options[i]);
  if (o.runs == 0) throw std::invalid_argument("--runs must be at least 1");
  const std::string scenario = make_scenario(o.scenario)->info().name;
  const std::filesystem::path dir = o.out.empty()
                                        ? std::filesystem::path("results") / ("sweep-" + scenario + "-" + o.filter.filter)
                                        : std::filesystem::path(o.out);
  MonteCarloParams config;
  config.runs = o.runs;
  config.base_seed = o.seed;
  config.jobs = o.jobs;
  config.budget_ns = budget_ns_from_us(o.filter.budget_us);

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
