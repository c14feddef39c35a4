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
#include "report/summary_json.hpp"
#include "scenarios/registry.hpp"

namespace kestrel::sim::cli {

namespace {

struct SweepValue {
  std::string text;  ///< As written, for the tag.
  double value = 0.0;
};

/// "qj=1.6,16,160" -> key "qj" and its values.
std::vector<SweepValue> parse_set(const std::string& set, std::string& key) {
  const std::size_t eq = set.find('=');
  if (eq == std::string::npos || eq == 0) throw std::invalid_argument("--set must be KEY=V1,V2,... (e.g. qj=1.6,16,160)");
  key = set.substr(0, eq);
  if (key != "qj" && key != "gate-d2") {
    throw std::invalid_argument("--set: unknown parameter '" + key + "' (known: qj, gate-d2)");
  }
  std::vector<SweepValue> values;
  std::size_t start = eq + 1;
  while (start <= set.size()) {
    const std::size_t comma = set.find(',', start);
    const std::string item = set.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    std::size_t used = 0;
    double v = 0.0;
    try {
      v = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (item.empty() || used != item.size() || !(v > 0.0)) {
      throw std::invalid_argument("--set " + key + ": '" + item + "' is not a positive number");
    }
    values.push_back({item, v});
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return values;
}

}  // namespace

int cmd_sweep(const SweepOptions& o) {
  std::string key;
  const std::vector<SweepValue> values = parse_set(o.set, key);
  if (o.runs == 0) throw std::invalid_argument("--runs must be at least 1");
  const std::string scenario = make_scenario(o.scenario)->info().name;
  const std::filesystem::path dir = o.out.empty()
                                        ? std::filesystem::path("results") / ("sweep-" + scenario + "-" + o.filter.filter)
                                        : std::filesystem::path(o.out);
  MonteCarloConfig config;
  config.runs = o.runs;
  config.base_seed = o.seed;
  config.jobs = o.jobs;
  config.budget_ns = budget_ns_from_us(o.filter.budget_us);

  nlohmann::json results = nlohmann::json::object();
  std::vector<TableRow> rows;
  for (std::size_t i = 0; i < values.size(); ++i) {
    config.options = o.filter.options;
    if (key == "qj") config.options.qj = values[i].value;
    if (key == "gate-d2") config.options.confirmed_gate_d2 = values[i].value;
    const std::string tag = o.filter.filter + "-" + key + values[i].text;
    std::fprintf(stderr, "kestrel-sim sweep: %s = %s (%zu of %zu), %zu runs\n", key.c_str(), values[i].text.c_str(),
                 i + 1, values.size(), o.runs);
    ScenarioReport r = run_scenario_report(scenario, o.filter.filter, config, dir, o.plots, tag);
    r.entry["sweep"] = {{"parameter", key}, {"value", values[i].value}};
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
