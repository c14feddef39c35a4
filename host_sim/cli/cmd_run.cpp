// SPDX-License-Identifier: Apache-2.0
// `kestrel-sim run` (one scenario, one filter, N seeds) and `kestrel-sim
// suite` (the default suite the README runs: S1 and S2 with EKF-CA).
#include <cstdio>
#include <filesystem>

#include "cli/commands.hpp"
#include "cli/scenario_report.hpp"
#include "plots/plot_runner.hpp"
#include "report/run_files.hpp"
#include "report/summary_json.hpp"
#include "scenarios/registry.hpp"
#include "stream/stream_writer.hpp"

namespace kestrel::sim::cli {

namespace {
MonteCarloConfig config_from(const FilterChoice& f, std::size_t runs, std::uint64_t seed, unsigned jobs) {
  MonteCarloConfig c;
  c.runs = runs;
  c.base_seed = seed;
  c.jobs = jobs;
  c.budget_ns = budget_ns_from_us(f.budget_us);
  c.options = f.options;
  return c;
}

void print_files(const std::filesystem::path& dir, const std::string& filter, bool plots) {
  const RunFileNames n = run_file_names(dir, filter);
  std::printf("wrote %s, %s, %s, %s", n.tracks_csv.c_str(), n.steps_csv.c_str(), n.runs_csv.c_str(),
              (dir / "summary.json").c_str());
  if (plots) std::printf(" and %s_{xy,error}.png", n.plot_prefix.c_str());
  std::printf("\n");
}
}  // namespace

int cmd_run(const RunOptions& o) {
  const MonteCarloConfig config = config_from(o.filter, o.runs, o.seed, o.jobs);
  const std::string scenario = make_scenario(o.scenario)->info().name;
  const std::filesystem::path dir = o.out.empty() ? std::filesystem::path("results") / scenario : std::filesystem::path(o.out);
  const ScenarioReport report = run_scenario_report(scenario, o.filter.filter, config, dir, o.plots);
  print_table_header(stdout);
  print_table_row(stdout, report.row);
  print_files(dir, report.row.filter, o.plots);
  if (!o.asterix_out.path.empty()) {
    // Run 0 again, its reports through a Cat062Sink as well: the run is
    // deterministic, so these are the reports of the track CSV above.
    const auto s = make_scenario(scenario);
    const RunDetail d = run_scenario_once(
        *s, o.seed, find_filter(o.filter.filter), config.options, config.budget_ns, config.scoring,
        hal::asterix::Cat062Source{static_cast<std::uint8_t>(o.asterix_out.sac),
                                   static_cast<std::uint8_t>(o.asterix_out.sic), false, 0});
    write_bytes(o.asterix_out.path, d.stream.cat062);
    print_cat062_written(o.asterix_out.path, d.stream);
  }
  return 0;
}

void print_cat062_written(const std::string& path, const StreamRunResult& r) {
  std::size_t reports = 0;
  for (const FrameOutcome& f : r.frames) reports += f.tracks.size();
  std::printf("wrote %s: %zu bytes, CAT062, one data block per track report (%zu reports, %u not written: "
              "outside what CAT062 carries)\n",
              path.c_str(), r.cat062.size(), reports, r.cat062_refused);
}

int cmd_suite(const SuiteOptions& o) {
  FilterChoice f;
  f.options = o.options;
  f.budget_us = o.budget_us;
  const MonteCarloConfig config = config_from(f, o.runs, o.seed, o.jobs);
  const std::filesystem::path root(o.out);
  std::filesystem::create_directories(root);

  nlohmann::json results = nlohmann::json::object();
  std::vector<TableRow> rows;
  for (const std::string& s : o.scenarios) {
    const std::string scenario = make_scenario(s)->info().name;
    for (const std::string& filter : o.filters) {
      std::printf("running %s with %s, %zu runs ...\n", scenario.c_str(), filter.c_str(), o.runs);
      std::fflush(stdout);
      ScenarioReport r = run_scenario_report(scenario, filter, config, root / scenario, o.plots);
      results[scenario][r.row.filter] = r.entry;
      rows.push_back(std::move(r.row));
    }
  }
  const std::filesystem::path summary = root / "summary.json";
  write_summary_file(summary, results);
  if (o.plots) plot_summary(summary, root / "summary.png");

  std::printf("\n");
  print_table_header(stdout);
  for (const TableRow& r : rows) print_table_row(stdout, r);
  std::printf("\nwrote %s (combined), per-scenario files under %s/<scenario>/%s\n", summary.c_str(), root.c_str(),
              o.plots ? ", summary.png" : "");
  return 0;
}

}  // namespace kestrel::sim::cli
