// SPDX-License-Identifier: Apache-2.0
#include "cli/cmd_pcl.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "filters/sensor_settings.hpp"
#include "montecarlo/pcl_monte_carlo.hpp"
#include "report/output_files.hpp"
#include "report/pcl_files.hpp"
#include "report/summary_json.hpp"
#include "scenarios/sensor_kind.hpp"

namespace kestrel::sim::cli {

namespace {

std::uint8_t small_count(unsigned v, const char* what) {
  if (v < 1 || v > 8) throw std::invalid_argument(std::string(what) + " must be 1..8");
  return static_cast<std::uint8_t>(v);
}

std::string manager_label(const PclTrackerParams& p, ManagerChoice m) {
  if (m == ManagerChoice::kScore) return "track score";
  return std::to_string(p.confirm_m) + "-of-" + std::to_string(p.confirm_n);
}

void print_ci(const char* name, const MeanCi& m, const char* unit) {
  std::printf("  %-34s %9.4f  [%.4f, %.4f] %s (n = %zu)\n", name, m.mean, m.ci95_low, m.ci95_high, unit, m.n);
}

}  // namespace

CLI::App* add_pcl_command(CLI::App& app, PclOptions& o) {
  CLI::App* cmd = app.add_subcommand("pcl", "Passive-radar Monte Carlo (pcl002, pcl002-hard) with the PCL tracker");
  cmd->add_option("--scenario,-s", o.scenario, "pcl002 or pcl002-hard")->capture_default_str();
  cmd->add_option("--runs,-n", o.runs, "Monte Carlo runs")->capture_default_str();
  cmd->add_option("--seed", o.seed, "Seed of run 0; run i uses seed + i")->capture_default_str();
  cmd->add_option("--jobs,-j", o.jobs, "Worker threads (results do not depend on it)")->capture_default_str();
  cmd->add_option("--out,-o", o.out, "Output directory (default results/<scenario>)");
  cmd->add_flag("!--no-plots", o.plots, "Do not run the plot script");
  cmd->add_option("--budget-us", o.budget_us, "Step budget for overrun counting, us")->capture_default_str();
  cmd->add_option("--config", o.config, "JSON file of PCL tracker parameters by key (`list --settings`, docs/parameters.md)");
  cmd->add_option("--set", o.sets, "KEY=VALUE, repeatable: one PCL tracker parameter; wins over --config, loses to "
                                   "the parameter's own option (--accel-sigma, ...)");
  cmd->add_option("--accel-sigma", o.accel_sigma_mps2, "White-acceleration sigma on Rb, m/s^2 (default 4)");
  cmd->add_option("--confirm-m", o.confirm_m, "M of M-of-N (default 5)");
  cmd->add_option("--confirm-n", o.confirm_n, "N of M-of-N (default 6)");
  cmd->add_option("--gate-tentative", o.gate_tentative, "Gate probability of tentative tracks (default 0.95)");
  cmd->add_option("--gate-confirmed", o.gate_confirmed, "Gate probability of confirmed tracks (default 0.99)");
  cmd->add_option("--min-start-doppler-hz", o.min_start_doppler_hz, "No track start below this |fD|, Hz (default 2)");
  cmd->add_option("--max-coast-misses", o.max_coast_misses, "Misses before a confirmed track is deleted (default 6)");
  cmd->add_option("--associator", o.associator, "nn, gnn or pda")->capture_default_str();
  cmd->add_option("--manager", o.manager, "m-of-n or score (sequential log-likelihood ratio)")->capture_default_str();
  cmd->add_option("--detection-probability", o.detection_probability,
                  "P_D for pda and score (default: the scenario's)");
  cmd->add_option("--clutter-density", o.clutter_density,
                  "False candidates per m x m/s and frame, for pda and score (default: the scenario's)");
  cmd->add_option("--new-target-density", o.new_target_density, "New targets per m x m/s and frame, for score");
  cmd->add_option("--false-track-probability", o.false_track_probability, "alpha of score's confirmation test");
  cmd->add_option("--missed-track-probability", o.missed_track_probability, "beta of score's confirmation test");
  return cmd;
}

int cmd_pcl(const PclOptions& o) {
  const PclScenarioParams scenario = pcl_config_by_name(o.scenario);
  PclTrackerParams params = pcl_params_for(scenario);
  // --config, then --set, then the options of their own.
  const std::vector<Setting> settings = read_settings(o.config, o.sets);
  apply_pcl_settings(settings, params);
  if (o.accel_sigma_mps2) params.accel_sigma_mps2 = *o.accel_sigma_mps2;
  if (o.confirm_m) params.confirm_m = small_count(*o.confirm_m, "--confirm-m");
  if (o.confirm_n) params.confirm_n = small_count(*o.confirm_n, "--confirm-n");
  if (params.confirm_m > params.confirm_n) throw std::invalid_argument("--confirm-m must not exceed --confirm-n");
  if (o.gate_tentative) params.gate_tentative = gate_option(*o.gate_tentative, "--gate-tentative");
  if (o.gate_confirmed) params.gate_confirmed = gate_option(*o.gate_confirmed, "--gate-confirmed");
  if (o.min_start_doppler_hz) params.min_start_doppler_hz = *o.min_start_doppler_hz;
  if (o.max_coast_misses) params.max_coast_misses = static_cast<std::uint16_t>(*o.max_coast_misses);
  const auto probability = [](double v, const char* what) {
    if (!(v > 0.0 && v < 1.0)) throw std::invalid_argument(std::string(what) + " must be in (0, 1)");
    return v;
  };
  const auto density = [](double v, const char* what) {
    if (!(v > 0.0 && std::isfinite(v))) throw std::invalid_argument(std::string(what) + " must be positive");
    return v;
  };
  if (o.detection_probability) {
    params.detection_probability = probability(*o.detection_probability, "--detection-probability");
  }
  if (o.clutter_density) {
    params.clutter_density = density(*o.clutter_density, "--clutter-density");
  }
  if (o.new_target_density) {
    params.new_target_density = density(*o.new_target_density, "--new-target-density");
  }
  if (o.false_track_probability) {
    params.false_track_probability = probability(*o.false_track_probability, "--false-track-probability");
  }
  if (o.missed_track_probability) {
    params.missed_track_probability = probability(*o.missed_track_probability, "--missed-track-probability");
  }
  if (o.runs == 0) throw std::invalid_argument("--runs must be at least 1");
  if (!(o.budget_us > 0.0)) throw std::invalid_argument("--budget-us must be positive");

  PclMonteCarloParams config;
  config.runs = o.runs;
  config.base_seed = o.seed;
  config.jobs = o.jobs;
  config.budget_ns = static_cast<std::uint64_t>(std::llround(o.budget_us * 1000.0));
  config.policies.associator = policy_by_name(kAssociatorNames, o.associator, "associator");
  config.policies.manager = policy_by_name(kManagerNames, o.manager, "track manager");

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
