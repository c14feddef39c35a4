// SPDX-License-Identifier: Apache-2.0
#include "cli/cmd_sonar.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "filters/sensor_settings.hpp"
#include "metrics/sonar_metrics.hpp"
#include "report/output_files.hpp"
#include "report/sonar_files.hpp"
#include "report/summary_json.hpp"
#include "scenarios/sensor_kind.hpp"

namespace kestrel::sim::cli {

namespace {

void print_ci(const char* name, const MeanCi& m, const char* unit) {
  std::printf("  %-34s %9.3f  [%.3f, %.3f] %s (n = %zu)\n", name, m.mean, m.ci95_low, m.ci95_high, unit, m.n);
}

SonarTrackerParams params_from(const SonarOptions& o, const SonarScenarioParams& scenario) {
  SonarTrackerParams p = sonar_params_for(scenario);
  // --config, then --set, then the options of their own.
  apply_sonar_settings(read_settings(o.config, o.sets), p);
  if (o.gate_k) {
    if (!(*o.gate_k > 0.0)) throw std::invalid_argument("--gate-k must be positive");
    p.gate_k_sigma = *o.gate_k;
  }
  if (o.no_gate) p.per_channel_gate = false;
  if (o.ellipsoidal) p.ellipsoidal_gate = true;
  if (o.ellipsoid_probability) p.ellipsoid_probability = gate_option(*o.ellipsoid_probability, "--ellipsoid-p");
  if (o.accel_sigma_mps2) p.accel_sigma_mps2 = *o.accel_sigma_mps2;
  if (o.sound_speed_sigma) p.sound_speed_sigma_mps_per_sqrt_s = *o.sound_speed_sigma;
  if (o.reacquire_after) p.reacquire_after_lost_frames = static_cast<std::uint16_t>(*o.reacquire_after);
  if (o.no_gate_truncation) p.gate_truncation_covariance = false;
  if (o.no_depth_projection) p.project_depth = false;
  return p;
}

std::string gate_label(const SonarTrackerParams& p) {
  std::string s;
  if (p.per_channel_gate) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "k = %g", p.gate_k_sigma);
    s = buf;
  }
  if (p.ellipsoidal_gate) s += s.empty() ? "ellipsoidal" : " + ellipsoidal";
  return s.empty() ? "no gate" : s;
}

SonarMonteCarloParams mc_config(const SonarOptions& o) {
  if (o.runs == 0) throw std::invalid_argument("--runs must be at least 1");
  if (!(o.budget_us > 0.0)) throw std::invalid_argument("--budget-us must be positive");
  SonarMonteCarloParams c;
  c.runs = o.runs;
  c.base_seed = o.seed;
  c.jobs = o.jobs;
  c.budget_ns = static_cast<std::uint64_t>(std::llround(o.budget_us * 1000.0));
  return c;
}

int run_single(const SonarOptions& o) {
  const SonarScenarioParams scenario = sonar_config_by_name(o.scenario);
  const SonarTrackerParams params = params_from(o, scenario);
  const SonarMonteCarloParams config = mc_config(o);
  const SonarMonteCarloResult mc = run_sonar_monte_carlo(scenario, params, config);
  const SonarSummary s = summarise_sonar(mc.runs, config.budget_ns);

  const std::filesystem::path dir =
      o.out.empty() ? std::filesystem::path("results") / scenario.name : std::filesystem::path(o.out);
  std::filesystem::create_directories(dir);
  write_sonar_runs_csv(dir / "sonar_runs.csv", mc.runs);
  write_sonar_steps_csv(dir / "sonar_steps.csv", s);
  write_sonar_run_csvs(dir, mc.first_run, mc.first_output);
  nlohmann::json summary = sonar_summary_json(scenario, params, config, s);
  summary["parameters"] = sonar_parameters(params);  // every key, as the run used it
  merge_summary_file(dir / "summary.json", scenario.name, std::string(kSonarFilterName), summary);
  const bool plotted =
      o.plots &&
      plot_sonar(dir, scenario.name + " / sonar EKF, " + gate_label(params) + " / seed " + std::to_string(o.seed));

  std::printf("%s: %zu runs (seeds %llu..%llu), sonar EKF, %s, sa %g m/s^2, c noise %g m/s/sqrt(s)\n",
              scenario.name.c_str(), s.runs, static_cast<unsigned long long>(o.seed),
              static_cast<unsigned long long>(o.seed + o.runs - 1), gate_label(params).c_str(),
              params.accel_sigma_mps2, params.sound_speed_sigma_mps_per_sqrt_s);
  std::printf("  mean over runs [95 %% interval]:\n");
  print_ci("3D RMSE", s.rmse_3d_m, "m");
  print_ci("horizontal RMSE", s.rmse_h_m, "m");
  print_ci("depth RMSE", s.rmse_depth_m, "m");
  print_ci("3D peak error", s.peak_3d_m, "m");
  print_ci("position NEES (3 dof)", s.nees, "");
  print_ci("sound-speed error std (per run)", s.c_err_std_mps, "m/s");
  print_ci("sound-speed error mean (per run)", s.c_err_mean_mps, "m/s");
  std::printf("  sound-speed error pooled over runs and frames: std %.3f m/s, mean %.3f m/s\n",
              s.pooled_c_err_std_mps, s.pooled_c_err_mean_mps);
  std::printf("  arrivals %zu: true outliers %zu, of which gated %zu; good arrivals gated %zu; gated in all %zu; "
              "predict-only frames %zu\n",
              s.arrivals, s.outliers, s.outliers_gated, s.good_gated, s.gated, s.predict_only);
  std::printf("  runs with the first fix after frame 0: %zu; never initialised: %zu; re-acquisitions %zu; frames "
              "refused %zu; truth depth reflections %zu\n",
              s.runs_late_init, s.runs_not_initialised, s.reinitialisations, s.frames_refused, s.depth_reflections);
  std::printf("  step (adapter + SonarTracker::step) ns: median %llu, p99 %llu, max %llu, mean %.0f over %zu "
              "steps (%u job%s)\n",
              static_cast<unsigned long long>(s.timing.median_ns), static_cast<unsigned long long>(s.timing.p99_ns),
              static_cast<unsigned long long>(s.timing.max_ns), s.timing.mean_ns, s.timing.steps, o.jobs,
              o.jobs == 1 ? "" : "s");
  std::printf("wrote %s/{sonar_runs.csv, sonar_steps.csv, sonar_truth.csv, sonar_arrivals.csv, sonar_track.csv, "
              "summary.json%s}\n",
              dir.c_str(), plotted ? ", sonar_track.png, sonar_error.png, sonar_sound_speed.png" : "");
  return 0;
}

/// Every variant with the paper's gate (k = 2), k = 3 and no gate.
int run_study(const SonarOptions& o) {
  const SonarMonteCarloParams config = mc_config(o);
  const std::filesystem::path dir =
      o.out.empty() ? std::filesystem::path("results") / "sonar_study" : std::filesystem::path(o.out);
  std::filesystem::create_directories(dir);
  struct Gate {
    const char* label;
    bool per_channel;
    double k;
  };
  const Gate gates[] = {{"k = 2 (paper)", true, 2.0}, {"k = 3", true, 3.0}, {"no gate", false, 3.0}};

  nlohmann::json rows = nlohmann::json::array();
  std::string md;
  md += "| scenario | gate | 3D RMSE m | horizontal m | depth m | c err std m/s (per run / pooled) | NEES | "
        "outliers gated / true | good gated |\n";
  md += "|---|---|---|---|---|---|---|---|---|\n";
  for (const std::string& name : sonar_scenario_names()) {
    const SonarScenarioParams scenario = sonar_config_by_name(name);
    for (const Gate& g : gates) {
      SonarOptions oo = o;
      oo.gate_k = g.k;
      oo.no_gate = !g.per_channel;
      const SonarTrackerParams params = params_from(oo, scenario);
      const SonarMonteCarloResult mc = run_sonar_monte_carlo(scenario, params, config);
      const SonarSummary s = summarise_sonar(mc.runs, config.budget_ns);
      const std::filesystem::path sub = dir / (name + "_" + (g.per_channel ? "k" + std::to_string(static_cast<int>(g.k))
                                                                           : std::string("nogate")));
      std::filesystem::create_directories(sub);
      write_sonar_runs_csv(sub / "sonar_runs.csv", mc.runs);
      write_sonar_steps_csv(sub / "sonar_steps.csv", s);
      write_sonar_run_csvs(sub, mc.first_run, mc.first_output);
      const nlohmann::json j = sonar_summary_json(scenario, params, config, s);
      merge_summary_file(sub / "summary.json", scenario.name, std::string(kSonarFilterName), j);
      if (o.plots && g.per_channel && g.k == 3.0) {
        plot_sonar(sub, scenario.name + " / sonar EKF, " + gate_label(params) + " / seed " + std::to_string(o.seed));
      }
      char line[512];
      std::snprintf(line, sizeof line,
                    "| %s | %s | %.2f [%.2f, %.2f] | %.2f | %.2f | %.2f / %.2f | %.2f | %zu / %zu | %zu |\n",
                    name.c_str(), g.label, s.rmse_3d_m.mean, s.rmse_3d_m.ci95_low, s.rmse_3d_m.ci95_high,
                    s.rmse_h_m.mean, s.rmse_depth_m.mean, s.c_err_std_mps.mean, s.pooled_c_err_std_mps, s.nees.mean,
                    s.outliers_gated, s.outliers, s.good_gated);
      md += line;
      std::fputs(line, stdout);
      std::fflush(stdout);
      rows.push_back({{"scenario", name}, {"gate", g.label}, {"summary", j}});
    }
  }
  {
    std::ofstream f(dir / "sonar_study.md", std::ios::trunc);
    f << "UW study: " << config.runs << " runs per row, seeds " << config.base_seed << ".."
      << config.base_seed + config.runs - 1 << " (kestrel-sim sonar --study)\n\n"
      << md;
    if (!f) throw std::runtime_error("cannot write sonar_study.md");
  }
  write_json_file(dir / "sonar_study.json",
                  {{"schema", "kestrel-sim-sonar-study/1"}, {"runs", config.runs}, {"rows", rows}});
  std::printf("wrote %s/{sonar_study.md, sonar_study.json} and one folder per row\n", dir.c_str());
  return 0;
}

}  // namespace

CLI::App* add_sonar_command(CLI::App& app, SonarOptions& o) {
  CLI::App* cmd = app.add_subcommand("sonar", "Sonar (underwater multipath TOA) Monte Carlo (uw003 and variants)");
  cmd->add_option("--scenario,-s", o.scenario, "uw003, uw003-direct, uw003-clean, uw003-d100 or uw003-1ms")
      ->capture_default_str();
  cmd->add_option("--runs,-n", o.runs, "Monte Carlo runs")->capture_default_str();
  cmd->add_option("--seed", o.seed, "Seed of run 0; run i uses seed + i")->capture_default_str();
  cmd->add_option("--jobs,-j", o.jobs, "Worker threads (results do not depend on it)")->capture_default_str();
  cmd->add_option("--out,-o", o.out, "Output directory (default results/<scenario>)");
  cmd->add_flag("!--no-plots", o.plots, "Do not run the plot script");
  cmd->add_flag("--study", o.study, "Every variant with k = 2, k = 3 and no gate; writes sonar_study.md");
  cmd->add_option("--budget-us", o.budget_us, "Step budget for overrun counting, us")->capture_default_str();
  cmd->add_option("--config", o.config,
                  "JSON file of sonar tracker parameters by key (`list --settings`, docs/parameters.md)");
  cmd->add_option("--set", o.sets, "KEY=VALUE, repeatable: one sonar tracker parameter; wins over --config, "
                                   "loses to the parameter's own option (--gate-k, ...)");
  cmd->add_option("--gate-k", o.gate_k, "Per-channel gate multiplier k (default 2, the paper's)");
  cmd->add_flag("--no-gate", o.no_gate, "Per-channel gate off");
  cmd->add_flag("--ellipsoidal", o.ellipsoidal, "Ellipsoidal gate on (after the per-channel gate)");
  cmd->add_option("--ellipsoid-p", o.ellipsoid_probability, "Its probability (default 0.99)");
  cmd->add_option("--accel-sigma", o.accel_sigma_mps2, "White acceleration per axis, m/s^2 (default 0.05)");
  cmd->add_option("--sound-speed-sigma", o.sound_speed_sigma, "c random walk, m/s per sqrt(s) (default 0.3)");
  cmd->add_flag("--no-gate-truncation", o.no_gate_truncation, "Do not widen P for channels the per-channel gate dropped");
  cmd->add_flag("--no-depth-projection", o.no_depth_projection, "Do not keep the depth estimate within (0, D)");
  cmd->add_option("--reacquire-after", o.reacquire_after, "Re-run the fix after this many frames in a row that fused at most half their arrivals (0: never)");
  return cmd;
}

int cmd_sonar(const SonarOptions& o) { return o.study ? run_study(o) : run_single(o); }

}  // namespace kestrel::sim::cli
