// SPDX-License-Identifier: Apache-2.0
#include "report/sonar_files.hpp"

#include <fstream>
#include <stdexcept>

#include "csv/sensor_truth_csv.hpp"
#include "plots/plot_runner.hpp"
#include "report/output_files.hpp"
#include "scenarios/sensor_kind.hpp"

namespace kestrel::sim {

namespace {

nlohmann::json series(const std::vector<double>& v) {
  nlohmann::json a = nlohmann::json::array();
  for (const double x : v) a.push_back(number_or_null(x));
  return a;
}

const char* path_name(hal::ToaPath p) { return p == hal::ToaPath::kDirect ? "direct" : "reflected"; }

}  // namespace

void write_sonar_runs_csv(const std::filesystem::path& path, const std::vector<SonarRunMetrics>& runs) {
  std::ofstream out = open_out(path);
  out << "seed,init_frame,scored_frames,rmse_3d_m,rmse_h_m,rmse_depth_m,peak_3d_m,nees,c_err_mean_mps,"
         "c_err_std_mps,arrivals,outliers,outliers_gated,good_gated,gated,predict_only,reinitialisations,"
         "frames_refused,depth_reflections\n";
  for (const SonarRunMetrics& r : runs) {
    out << r.seed << ',' << r.init_frame << ',' << r.scored_frames << ',' << csv_cell(r.rmse_3d_m) << ','
        << csv_cell(r.rmse_h_m) << ',' << csv_cell(r.rmse_depth_m) << ',' << csv_cell(r.peak_3d_m) << ','
        << csv_cell(r.nees) << ',' << csv_cell(r.c_err_mean_mps) << ',' << csv_cell(r.c_err_std_mps) << ','
        << r.arrivals << ',' << r.outliers << ',' << r.outliers_gated << ',' << r.good_gated << ',' << r.gated << ','
        << r.predict_only << ',' << r.reinitialisations << ',' << r.frames_refused << ',' << r.depth_reflections
        << '\n';
  }
  if (!out) throw std::runtime_error("cannot write '" + path.string() + "'");
}

void write_sonar_steps_csv(const std::filesystem::path& path, const SonarSummary& s) {
  std::ofstream out = open_out(path);
  out << "frame,runs_scored,rmse_3d_m,rmse_h_m,rmse_depth_m,c_err_rms_mps\n";
  for (std::size_t k = 0; k < s.step_runs.size(); ++k) {
    out << k << ',' << s.step_runs[k] << ',' << csv_cell(s.step_rmse_3d_m[k]) << ',' << csv_cell(s.step_rmse_h_m[k])
        << ',' << csv_cell(s.step_rmse_depth_m[k]) << ',' << csv_cell(s.step_c_err_rms_mps[k]) << '\n';
  }
  if (!out) throw std::runtime_error("cannot write '" + path.string() + "'");
}

void write_sonar_run_csvs(const std::filesystem::path& dir, const SonarScenarioRun& run, const SonarRunOutput& out) {
  const std::size_t n = std::min(run.frames.size(), out.frames.size());
  // The truth `generate` writes beside a stream: `replay --truth` takes either.
  write_sonar_truth_csv(dir / "sonar_truth.csv", run);
  {
    std::ofstream f = open_out(dir / "sonar_arrivals.csv");
    f << "frame,time_s,beacon,path,true_toa_s,toa_s,wire_toa_ns,outlier,outlier_ms,fused,gated\n";
    for (std::size_t k = 0; k < n; ++k) {
      const SonarFrameRecord& fr = run.frames[k];
      const SonarFrameOutcome& o = out.frames[k];
      for (std::size_t i = 0; i < fr.arrivals.size(); ++i) {
        const SonarArrivalRecord& a = fr.arrivals[i];
        const std::uint32_t bit = 1u << (2u * a.beacon + static_cast<std::uint32_t>(a.path));
        f << k << ',' << csv_cell(run.truth[k].t_s) << ',' << static_cast<int>(a.beacon) << ',' << path_name(a.path)
          << ',' << csv_cell(a.true_toa_s) << ',' << csv_cell(a.toa_s) << ',' << fr.wire.sonar[i].time_of_flight_ns
          << ',' << (a.outlier ? 1 : 0) << ',' << csv_cell(a.outlier_s * 1e3) << ',' << ((o.fused & bit) != 0 ? 1 : 0)
          << ',' << ((o.gated & bit) != 0 ? 1 : 0) << '\n';
      }
    }
  }
  std::vector<double> time_s;
  for (std::size_t k = 0; k < n; ++k) time_s.push_back(run.truth[k].t_s);
  write_sonar_track_csv(dir / "sonar_track.csv", out.frames, time_s);
}

void write_sonar_track_csv(const std::filesystem::path& path, const std::vector<SonarFrameOutcome>& frames,
                           const std::vector<double>& time_s) {
  const std::size_t n = std::min(frames.size(), time_s.size());
  std::ofstream f = open_out(path);
  f << "frame,time_s,status,reported,initialised,predict_only,x_m,y_m,z_m,vx_mps,vy_mps,vz_mps,c_mps,"
       "sd_x_m,sd_y_m,sd_z_m,sd_vx_mps,sd_vy_mps,sd_vz_mps,sd_c_mps,fused,gated,nis,step_ns\n";
  for (std::size_t k = 0; k < n; ++k) {
    const SonarFrameOutcome& o = frames[k];
    f << k << ',' << csv_cell(time_s[k]) << ',' << to_string(o.status) << ',' << (o.reported ? 1 : 0) << ','
      << (o.initialised ? 1 : 0) << ',' << (o.predict_only ? 1 : 0);
    for (std::size_t i = 0; i < 7; ++i) f << ',' << (o.reported ? csv_cell(o.x[i]) : "");
    for (std::size_t i = 0; i < 7; ++i) f << ',' << (o.reported ? csv_cell(o.sd[i]) : "");
    int fused = 0, gated = 0;
    for (int b = 0; b < 32; ++b) {
      fused += static_cast<int>((o.fused >> b) & 1u);
      gated += static_cast<int>((o.gated >> b) & 1u);
    }
    f << ',' << fused << ',' << gated << ',' << (o.reported ? csv_cell(o.nis) : "") << ',' << o.step_ns << '\n';
  }
  if (!f) throw std::runtime_error("cannot write '" + path.string() + "'");
}

nlohmann::json sonar_params_json(const SonarTrackerParams& p) {
  nlohmann::json beacons = nlohmann::json::array();
  for (int i = 0; i < p.beacon_count && i < SonarTrackerParams::kMaxBeacons; ++i) {
    beacons.push_back({p.beacons_m[i][0], p.beacons_m[i][1], p.beacons_m[i][2]});
  }
  return {{"beacons_m", beacons},
          {"seabed_depth_m", p.seabed_depth_m},
          {"sigma_toa_s", p.sigma_toa_s},
          {"accel_sigma_mps2", p.accel_sigma_mps2},
          {"sound_speed_sigma_mps_per_sqrt_s", p.sound_speed_sigma_mps_per_sqrt_s},
          {"initial_sound_speed_mps", p.initial_sound_speed_mps},
          {"initial_sound_speed_sigma_mps", p.initial_sound_speed_sigma_mps},
          {"initial_velocity_sigma_mps", p.initial_velocity_sigma_mps},
          {"initial_position_sigma_m", p.initial_position_sigma_m},
          {"per_channel_gate", p.per_channel_gate},
          {"gate_k_sigma", p.gate_k_sigma},
          {"ellipsoidal_gate", p.ellipsoidal_gate},
          {"reject_sigma", p.reject_sigma},
          {"reacquire_after_lost_frames", p.reacquire_after_lost_frames},
          {"gate_truncation_covariance", p.gate_truncation_covariance},
          {"project_depth", p.project_depth}};
}

nlohmann::json sonar_scenario_json(const SonarScenarioParams& sc) {
  nlohmann::json beacons = nlohmann::json::array();
  for (const auto& b : sc.beacons_m) beacons.push_back({b[0], b[1], b[2]});
  return {{"name", sc.name},
          {"description", sc.description},
          {"frames", sc.frames},
          {"period_s", sc.period_s},
          {"beacons_m", beacons},
          {"seabed_depth_m", sc.seabed_depth_m},
          {"sigma_toa_s", sc.sigma_toa_s},
          {"reflected", sc.reflected},
          {"outlier_probability", sc.outlier_probability},
          {"sound_speed_step_mps", sc.sound_speed_step_mps},
          {"sound_speed_limit_mps", sc.sound_speed_limit_mps},
          {"accel_sigma_mps2", sc.accel_sigma_mps2}};
}

nlohmann::json sonar_summary_json(const SonarScenarioParams& sc, const SonarTrackerParams& params,
                                  const SonarMonteCarloParams& config, const SonarSummary& s) {
  nlohmann::json j;
  j["kind"] = sensor_kind_name(hal::FrameKind::kSonar);
  j["scenario"] = sonar_scenario_json(sc);
  j["tracker"] = sonar_params_json(params);
  j["runs"] = s.runs;
  j["seeds"] = {config.base_seed, config.base_seed + config.runs - 1};
  j["rmse_3d_m"] = interval_json(s.rmse_3d_m);
  j["rmse_h_m"] = interval_json(s.rmse_h_m);
  j["rmse_depth_m"] = interval_json(s.rmse_depth_m);
  j["peak_3d_m"] = interval_json(s.peak_3d_m);
  j["nees"] = interval_json(s.nees);
  j["c_err_std_per_run_mps"] = interval_json(s.c_err_std_mps);
  j["c_err_mean_per_run_mps"] = interval_json(s.c_err_mean_mps);
  j["c_err_std_pooled_mps"] = number_or_null(s.pooled_c_err_std_mps);
  j["c_err_mean_pooled_mps"] = number_or_null(s.pooled_c_err_mean_mps);
  j["gate"] = {{"arrivals", s.arrivals},       {"outliers", s.outliers},
               {"outliers_gated", s.outliers_gated}, {"good_gated", s.good_gated},
               {"gated", s.gated},             {"predict_only_frames", s.predict_only}};
  j["runs_not_initialised"] = s.runs_not_initialised;
  j["runs_late_init"] = s.runs_late_init;
  j["reinitialisations"] = s.reinitialisations;
  j["frames_refused"] = s.frames_refused;
  j["depth_reflections"] = s.depth_reflections;
  j["per_step"] = {{"runs_scored", s.step_runs},
                   {"rmse_3d_m", series(s.step_rmse_3d_m)},
                   {"rmse_h_m", series(s.step_rmse_h_m)},
                   {"rmse_depth_m", series(s.step_rmse_depth_m)},
                   {"c_err_rms_mps", series(s.step_c_err_rms_mps)}};
  j["step_ns"] = step_ns_json(s.timing);
  return j;
}

bool plot_sonar(const std::filesystem::path& dir, const std::string& title) {
  return run_named_plot_script("sonar_plots.py", {"--dir", dir.string(), "--title", title});
}

}  // namespace kestrel::sim
