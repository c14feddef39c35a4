// SPDX-License-Identifier: Apache-2.0
// `run` of a PCL scenario (pcl002, pcl002-hard; docs/pcl.md): the Monte
// Carlo of the ready-made PCL tracker, scored with the PCL metrics
// (association accuracy, coverage after confirmation, false confirmed
// tracks, Rb/dRb RMSE, time to confirmation); its files are listed in
// report/pcl_files.hpp.
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "cli/commands.hpp"
#include "cli/scenario_report.hpp"
#include "filters/sensor_settings.hpp"
#include "montecarlo/pcl_monte_carlo.hpp"
#include "report/output_files.hpp"
#include "report/pcl_files.hpp"
#include "report/summary_json.hpp"
#include "scenarios/sensor_kind.hpp"

namespace kestrel::sim::cli {

namespace {

std::string manager_label(const PclTrackerParams& p, ManagerChoice m) {
  if (m == ManagerChoice::kScore) return "track score";
  return std::to_string(p.confirm_m) + "-of-" + std::to_string(p.confirm_n);
}

void print_ci(const char* name, const MeanCi& m, const char* unit) {
  std::printf("  %-34s %9.4f  [%.4f, %.4f] %s (n = %zu)\n", name, m.mean, m.ci95_low, m.ci95_high, unit, m.n);
}

}  // namespace

int run_pcl(const RunOptions& o) {
  const PclScenarioParams scenario = pcl_config_by_name(o.scenario);
  PclTrackerParams params = pcl_params_for(scenario);
  const std::vector<Setting> settings = read_settings(o.filter.config, o.filter.sets);
  apply_pcl_settings(settings, params);
  if (o.kind.gate_tentative) params.gate_tentative = gate_option(*o.kind.gate_tentative, "--gate-tentative");

  auto config = monte_carlo_params<PclMonteCarloParams>(o);
  config.policies.associator =
      policy_by_name(kAssociatorNames, o.kind.associator.empty() ? "nn" : o.kind.associator, "associator");
  config.policies.manager =
      policy_by_name(kManagerNames, o.kind.manager.empty() ? "m-of-n" : o.kind.manager, "track manager");

  const PclMonteCarloResult mc = run_pcl_monte_carlo(scenario, params, config);
  const PclSummary s = summarise_pcl(mc.runs, config.budget_ns);

  const std::filesystem::path dir =
      o.out.empty() ? std::filesystem::path("results") / scenario.name : std::filesystem::path(o.out);
  std::filesystem::create_directories(dir);
  write_pcl_runs_csv(dir / "pcl_runs.csv", mc.runs);
  write_pcl_run_csvs(dir, scenario, mc.first_run, mc.first_output, config.tolerance);
  nlohmann::json summary = pcl_summary_json(scenario, params, config, s);
  summary["parameters"] = pcl_parameters(params);  // every key, as the run used it
  merge_summary_file(dir / "summary.json", scenario.name, std::string(kPclFilterName), summary);
  bool plotted = false;
  if (o.plots) {
    plotted = plot_pcl(dir, scenario.name + " / PCL KF, " + std::string(policy_name(kAssociatorNames, config.policies.associator)) +
                      ", " + manager_label(params, config.policies.manager) + " / seed " + std::to_string(o.seed));
  }

  std::printf("%s: %zu runs (seeds %llu..%llu), PCL KF sa %g m/s^2, %s, %s, no start below %g Hz\n",
              scenario.name.c_str(), s.runs, static_cast<unsigned long long>(o.seed),
              static_cast<unsigned long long>(o.seed + o.runs - 1), params.accel_sigma_mps2,
              std::string(policy_name(kAssociatorNames, config.policies.associator)).c_str(),
              manager_label(params, config.policies.manager).c_str(), params.min_start_doppler_hz);
  if (!settings.empty()) {
    std::printf("  parameters set by --config/--set:");
    for (const Setting& st : settings) std::printf(" %s=%g", st.key.c_str(), st.value);
    std::printf("\n");
  }
  std::printf("  mean over runs [95 %% interval]:\n");
  print_ci("association accuracy", s.association_accuracy, "");
  print_ci("coverage after confirmation", s.coverage, "");
  print_ci("false confirmed tracks per run", s.false_tracks, "");
  print_ci("Rb RMSE", s.rb_rmse_m, "m");
  print_ci("dRb RMSE", s.drb_rmse_mps, "m/s");
  print_ci("time to first confirmation", s.time_to_confirm_s, "s");
  std::printf("  pooled: association accuracy %.4f, coverage %.4f; runs with a false track %zu, never confirmed %zu\n",
              s.pooled_accuracy, s.pooled_coverage, s.runs_with_false_track, s.runs_never_confirmed);
  std::printf("  detections %zu: cut by the adapter %zu, lost to the 64-candidate wire cut %zu; frames over scan "
              "capacity %zu; refused %zu; vetoed starts %zu; starts dropped (table full) %zu; most tracks in table %zu\n",
              s.detections, s.cut_by_adapter, s.cut_by_sensor, s.frames_over_capacity, s.frames_refused,
              s.refused_starts, s.dropped_starts, s.max_tracks_in_table);
  std::printf("  step (adapter + Tracker::step) ns: median %llu, p99 %llu, max %llu, mean %.0f over %zu steps "
              "(%u job%s)\n",
              static_cast<unsigned long long>(s.timing.median_ns), static_cast<unsigned long long>(s.timing.p99_ns),
              static_cast<unsigned long long>(s.timing.max_ns), s.timing.mean_ns, s.timing.steps, o.jobs,
              o.jobs == 1 ? "" : "s");
  std::printf("wrote %s/{pcl_runs.csv, pcl_truth.csv, pcl_candidates.csv, pcl_tracks.csv, summary.json%s}\n",
              dir.c_str(), plotted ? ", pcl_range_doppler.png" : "");
  return 0;
}

}  // namespace kestrel::sim::cli
