// SPDX-License-Identifier: Apache-2.0
// `run` of a sonar scenario (uw003 and its variants; docs/sonar.md): the
// Monte Carlo of the sonar tracker, scored with the UW metrics (3D /
// horizontal / depth RMSE, sound-speed error std, gated-out arrivals
// against the true outliers); its files are listed in report/sonar_files.hpp.
// `sonar-study`: every variant with the paper's gate (k = 2), k = 3 and no
// gate, and the comparison table (sonar_study.md / .json).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/scenario_report.hpp"
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

/// The scenario's tracker, then --config and --set (`extra` last: the study's
/// gate of the row).
SonarTrackerParams params_from(const RunOptions& o, const SonarScenarioParams& scenario,
                               const std::vector<Setting>& extra = {}) {
  SonarTrackerParams p = sonar_params_for(scenario);
  std::vector<Setting> settings = read_settings(o.filter.config, o.filter.sets);
  settings.insert(settings.end(), extra.begin(), extra.end());
  apply_sonar_settings(settings, p);
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

}  // namespace

int run_sonar(const RunOptions& o) {
  const SonarScenarioParams scenario = sonar_config_by_name(o.scenario);
  const SonarTrackerParams params = params_from(o, scenario);
  const auto config = monte_carlo_params<SonarMonteCarloParams>(o);
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

int cmd_sonar_study(const RunOptions& o) {
  const auto config = monte_carlo_params<SonarMonteCarloParams>(o);
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
      const SonarTrackerParams params =
          params_from(o, scenario, {Setting{"gate_k_sigma", g.k, "the study's row"},
                                    Setting{"per_channel_gate", g.per_channel ? 1.0 : 0.0, "the study's row"}});
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
      << config.base_seed + config.runs - 1 << " (kestrel-sim sonar-study)\n\n"
      << md;
    if (!f) throw std::runtime_error("cannot write sonar_study.md");
  }
  write_json_file(dir / "sonar_study.json",
                  {{"schema", "kestrel-sim-sonar-study/1"}, {"runs", config.runs}, {"rows", rows}});
  std::printf("wrote %s/{sonar_study.md, sonar_study.json} and one folder per row\n", dir.c_str());
  return 0;
}

}  // namespace kestrel::sim::cli
