// SPDX-License-Identifier: Apache-2.0
// `kestrel-sim run`: one scenario, one filter, N seeds. A PCL, sonar or
// multi-target scenario runs its kind's Monte Carlo (run_pcl.cpp,
// run_sonar.cpp, run_multi.cpp), with the options of KindOptions the kind
// takes.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/scenario_report.hpp"
#include "plots/plot_runner.hpp"
#include "report/run_files.hpp"
#include "report/summary_json.hpp"
#include "scenarios/registry.hpp"
#include "scenarios/sensor_kind.hpp"
#include "stream/stream_writer.hpp"

namespace kestrel::sim::cli {

namespace {
void print_files(const std::filesystem::path& dir, const std::string& filter, const ScenarioReport& r) {
  const RunFileNames n = run_file_names(dir, filter);
  std::printf("wrote %s, %s, %s, %s", n.tracks_csv.c_str(), n.steps_csv.c_str(), n.runs_csv.c_str(),
              (dir / "summary.json").c_str());
  if (r.modes_written) std::printf(", %s", n.modes_csv.c_str());
  if (r.plotted) std::printf(" and %s_{xy,error%s}.png", n.plot_prefix.c_str(), r.modes_plotted ? ",modes" : "");
  std::printf("\n");
}
}  // namespace

void check_filter_fits(const FilterChoice& f, hal::FrameKind kind, const std::string& what) {
  const std::string kind_name = sensor_kind_name(kind);
  const std::string fitting = kind_name + " frames: " + join_names(filters_for_kind(kind));
  if (f.filter_given) {
    const std::optional<hal::FrameKind> takes = filter_kind(f.filter);
    if (!takes.has_value() && kind != hal::FrameKind::kRadar) {
      throw std::invalid_argument(what + "; unknown filter '" + f.filter + "' (filters for " + fitting + ")");
    }
    // An unknown radar filter is left to find_filter, which lists them.
    if (takes.has_value() && *takes != kind) {
      throw std::invalid_argument(what + "; filter '" + f.filter + "' takes " + sensor_kind_name(*takes) +
                                  " frames (filters for " + fitting + ")");
    }
  }
  if (kind != hal::FrameKind::kRadar && !f.radar_only_given.empty()) {
    throw std::invalid_argument(what + "; " + join_names(f.radar_only_given) +
                                " set the radar filters and do not apply (the " + kind_name +
                                " tracker's keys: `--set` / `--config`, `list --settings`)");
  }
}

namespace {
/// Throws naming the options of KindOptions given that `allowed` does not
/// hold: `what` says which kind of scenario it is.
void check_kind_options(const KindOptions& k, const std::vector<std::string>& allowed, const std::string& what) {
  std::vector<std::string> wrong;
  for (const std::string& g : k.given) {
    if (std::find(allowed.begin(), allowed.end(), g) == allowed.end()) wrong.push_back(g);
  }
  if (wrong.empty()) return;
  const std::string verb = wrong.size() == 1 ? " does not apply to it" : " do not apply to it";
  throw std::invalid_argument(what + "; " + join_names(wrong) + verb +
                              (allowed.empty() ? std::string() : " (it takes " + join_names(allowed) + ")"));
}
}  // namespace

int run_sensor_scenario(const RunOptions& o, hal::FrameKind kind) {
  const std::string what = "scenario '" + o.scenario + "' is a " + sensor_kind_name(kind) + " scenario";
  if (kind == hal::FrameKind::kPcl) {
    check_kind_options(o.kind, {"--associator", "--manager", "--gate-tentative"}, what);
    return run_pcl(o);
  }
  if (kind == hal::FrameKind::kSonar) {
    check_kind_options(o.kind, {}, what);
    return run_sonar(o);
  }
  throw std::invalid_argument("scenario '" + o.scenario + "' is a radar scenario: `run` runs it with a radar filter");
}

int cmd_run(const RunOptions& o) {
  const std::optional<hal::FrameKind> kind = scenario_kind(o.scenario);
  if (kind.has_value() && *kind != hal::FrameKind::kRadar) {
    check_filter_fits(o.filter, *kind,
                      "scenario '" + o.scenario + "' is a " + sensor_kind_name(*kind) + " scenario");
    return run_sensor_scenario(o, *kind);
  }
  if (kind.has_value()) check_filter_fits(o.filter, *kind, "scenario '" + o.scenario + "' is a radar scenario");
  const auto made = make_scenario(o.scenario);
  // Several targets: multi's runs and scoring (OSPA, GOSPA, swaps), not RMSE.
  if (made->info().targets > 1) {
    check_kind_options(o.kind,
                       {"--associator", "--gate-tentative", "--compare-oracle", "--cutoff", "--order", "--persistence"},
                       "scenario '" + o.scenario + "' is a multi-target radar scenario");
    return run_multi_target_scenario(o);
  }
  check_kind_options(o.kind, {}, "scenario '" + o.scenario + "' is a single-target radar scenario");
  MonteCarloParams config = monte_carlo_params<MonteCarloParams>(o);
  config.options = o.filter.options;
  const std::string scenario = made->info().name;
  const std::filesystem::path dir = o.out.empty() ? std::filesystem::path("results") / scenario : std::filesystem::path(o.out);
  const ScenarioReport report = run_scenario_report(scenario, o.filter.filter, config, dir, o.plots);
  print_table_header(stdout);
  print_table_row(stdout, report.row);
  print_continuity(stdout, report.row);
  print_files(dir, report.row.filter, report);
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

}  // namespace kestrel::sim::cli
