// SPDX-License-Identifier: Apache-2.0
// `kestrel-sim suite`, the main job of `bash run.sh sim`: each paper's
// system at a modest run count through the same commands a user runs one
// by one (run, montecarlo, pcl, sonar), then one report that links them all.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "cli/cmd_montecarlo.hpp"
#include "cli/commands.hpp"
#include "cli/scenario_report.hpp"
#include "plots/plot_runner.hpp"
#include "report/main_report.hpp"
#include "report/summary_json.hpp"
#include "scenarios/registry.hpp"

namespace kestrel::sim::cli {

namespace {

/// One radar entry: "NAME" or "NAME:qj=X".
struct RadarFilterSpec {
  std::string filter;
  FilterOptions options;
  std::string tag;  ///< Files and summary key: NAME, or NAME-qjX.
};

RadarFilterSpec parse_filter_spec(const std::string& spec, const FilterOptions& defaults) {
  RadarFilterSpec r{spec, defaults, spec};
  const std::size_t colon = spec.find(':');
  if (colon == std::string::npos) return r;
  r.filter = spec.substr(0, colon);
  const std::string setting = spec.substr(colon + 1);
  const std::string key = "qj=";
  if (setting.rfind(key, 0) != 0) {
    throw std::invalid_argument("suite filter '" + spec + "': expected NAME or NAME:qj=X");
  }
  std::size_t used = 0;
  const std::string value = setting.substr(key.size());
  double qj = 0.0;
  try {
    qj = std::stod(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != value.size() || !(qj > 0.0)) {
    throw std::invalid_argument("suite filter '" + spec + "': qj must be a positive number");
  }
  r.options.qj = qj;
  r.tag = r.filter + "-qj" + value;
  return r;
}

bool wants(const SuiteOptions& o, const char* part) {
  return std::find(o.parts.begin(), o.parts.end(), part) != o.parts.end();
}

void check_parts(const std::vector<std::string>& parts) {
  for (const std::string& p : parts) {
    if (p != "radar" && p != "mc001" && p != "pcl" && p != "sonar") {
      throw std::invalid_argument("unknown suite part '" + p + "' (known: radar, mc001, pcl, sonar)");
    }
  }
}

void banner(const char* what) {
  std::fprintf(stderr, "\nkestrel-sim suite: %s\n", what);
  std::fflush(stdout);
}

// Sub-commands print their own "wrote ..." lines; the report only links a
// file this suite wrote (older figures from an earlier run do not count).
std::vector<std::filesystem::path> fresh(const std::filesystem::path& root,
                                         const std::vector<std::filesystem::path>& files,
                                         std::filesystem::file_time_type since) {
  std::vector<std::filesystem::path> out;
  for (const auto& f : files) {
    std::error_code ec;
    const auto t = std::filesystem::last_write_time(root / f, ec);
    if (!ec && t >= since) out.push_back(f);
  }
  return out;
}

/// The pcl or sonar part as the `run` a user would type for it.
RunOptions sensor_run(const SuiteOptions& o, const std::string& scenario, unsigned jobs,
                      const std::filesystem::path& root) {
  RunOptions r;
  r.scenario = scenario;
  r.runs = o.runs;
  r.seed = o.seed;
  r.jobs = jobs;
  r.out = (root / scenario).string();
  r.plots = o.plots;
  r.filter.budget_us = o.budget_us;
  return r;
}

}  // namespace

int cmd_suite(const SuiteOptions& o) {
  check_parts(o.parts);
  if (o.runs == 0 || o.mc_runs == 0) throw std::invalid_argument("--runs and --mc-runs must be at least 1");
  const unsigned jobs = o.jobs > 0 ? o.jobs : std::max(1u, std::thread::hardware_concurrency());
  const std::filesystem::path root(o.out);
  std::filesystem::create_directories(root);
  // One tick earlier than now: file times may be coarser than the clock.
  const auto started = std::filesystem::file_time_type::clock::now() - std::chrono::seconds(1);
  const auto wall_start = std::chrono::steady_clock::now();

  MainReport report;
  report.seed = o.seed;
  report.runs = o.runs;
  report.mc_runs = o.mc_runs;

  if (wants(o, "radar")) {
    std::vector<RadarFilterSpec> specs;
    for (const std::string& f : o.filters) specs.push_back(parse_filter_spec(f, o.options));
    MonteCarloParams config;
    config.runs = o.runs;
    config.base_seed = o.seed;
    config.jobs = jobs;
    config.budget_ns = budget_ns_from_us(o.budget_us);
    nlohmann::json results = nlohmann::json::object();
    for (const std::string& s : o.scenarios) {
      const std::string scenario = make_scenario(s)->info().name;
      for (const RadarFilterSpec& spec : specs) {
        char what[160];
        std::snprintf(what, sizeof what, "radar %s with %s, %zu runs", scenario.c_str(), spec.tag.c_str(), o.runs);
        banner(what);
        config.options = spec.options;
        ScenarioReport r = run_scenario_report(scenario, spec.filter, config, root / scenario, o.plots, spec.tag);
        results[scenario][spec.tag] = r.entry;
        MainReport::RadarRow row{r.row, r.label, {}};
        if (r.plotted) {
          const std::filesystem::path prefix = std::filesystem::relative(r.plot_prefix, root);
          row.figures = {prefix.string() + "_xy.png", prefix.string() + "_error.png"};
          if (r.modes_plotted) row.figures.push_back(prefix.string() + "_modes.png");
        }
        report.radar.push_back(std::move(row));
      }
    }
    const std::filesystem::path summary = root / "summary.json";
    write_summary_file(summary, results);
    if (o.plots && plot_summary(summary, root / "summary.png")) report.radar_summary_figure = "summary.png";
  }

  if (wants(o, "mc001")) {
    banner("MC-001, paper 001's filter comparison");
    MonteCarloOptions mc;
    mc.runs = o.mc_runs;
    mc.threads = jobs;
    mc.out = (root / "mc001").string();
    mc.plots = o.plots;
    mc.progress = true;
    if (cmd_montecarlo(mc) != 0) throw std::runtime_error("MC-001 campaign failed");
    report.mc001_dir = "mc001";
    report.mc001_figures = fresh(root, {"mc001/mc001_mse.png", "mc001/mc001_time.png"}, started);
  }

  if (wants(o, "pcl")) {
    banner("PCL-002, paper 002's passive-radar tracker");
    if (run_sensor_scenario(sensor_run(o, "pcl002", jobs, root), hal::FrameKind::kPcl) != 0) {
      throw std::runtime_error("PCL-002 runs failed");
    }
    report.pcl_dir = "pcl002";
    report.pcl_figures = fresh(root, {"pcl002/pcl_range_doppler.png"}, started);
  }

  if (wants(o, "sonar")) {
    banner("UW-003, paper 003's sonar tracker");
    if (run_sensor_scenario(sensor_run(o, "uw003", jobs, root), hal::FrameKind::kSonar) != 0) {
      throw std::runtime_error("UW-003 runs failed");
    }
    report.sonar_dir = "uw003";
    report.sonar_figures =
        fresh(root, {"uw003/sonar_track.png", "uw003/sonar_error.png", "uw003/sonar_sound_speed.png"}, started);
  }

  report.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  const std::filesystem::path md = root / "report.md";
  write_main_report(md, root, report);

  std::printf("\n");
  if (!report.radar.empty()) {
    print_table_header(stdout);
    for (const auto& r : report.radar) print_table_row(stdout, r.row);
  }
  std::printf("\nwrote %s (%.1f s): the tables of every part and links to its figures and files under %s/\n",
              md.c_str(), report.wall_s, root.c_str());
  return 0;
}

}  // namespace kestrel::sim::cli
