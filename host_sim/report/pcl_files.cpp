// SPDX-License-Identifier: Apache-2.0
#include "report/pcl_files.hpp"

#include <cmath>
#include <fstream>
#include <map>
#include <stdexcept>

#include "csv/sensor_truth_csv.hpp"
#include "kestrel/models/measurement/bistatic_range_rate.hpp"
#include "plots/plot_runner.hpp"
#include "report/output_files.hpp"
#include "scenarios/sensor_kind.hpp"

namespace kestrel::sim {

namespace {

const char* gate_name(GateProbability g) {
  switch (g) {
    case GateProbability::k90: return "0.90";
    case GateProbability::k95: return "0.95";
    case GateProbability::k99: return "0.99";
    case GateProbability::k995: return "0.995";
    case GateProbability::k999: return "0.999";
  }
  return "?";
}

}  // namespace

void write_pcl_runs_csv(const std::filesystem::path& path, const std::vector<PclRunMetrics>& runs) {
  std::ofstream out = open_out(path);
  out << "seed,association_accuracy,assoc_correct,assoc_frames,coverage,covered_frames,coverage_frames,"
         "confirmed_tracks,target_tracks,false_tracks,rb_rmse_m,drb_rmse_mps,rmse_frames,time_to_confirm_s,"
         "detections,cut_by_adapter,cut_by_sensor,frames_over_capacity,frames_refused,vetoed_starts,"
         "dropped_starts,max_tracks_in_table\n";
  for (const PclRunMetrics& r : runs) {
    out << r.seed << ',' << csv_cell(r.association_accuracy) << ',' << r.assoc_correct << ',' << r.assoc_frames << ','
        << csv_cell(r.coverage) << ',' << r.covered_frames << ',' << r.coverage_frames << ',' << r.confirmed_tracks
        << ',' << r.target_tracks << ',' << r.false_tracks << ',' << csv_cell(r.rb_rmse_m) << ','
        << csv_cell(r.drb_rmse_mps) << ',' << r.rmse_frames << ',' << csv_cell(r.time_to_confirm_s) << ','
        << r.detections << ',' << r.cut_by_adapter << ',' << r.cut_by_sensor << ',' << r.frames_over_capacity << ','
        << r.frames_refused << ',' << r.refused_starts << ',' << r.dropped_starts << ',' << r.max_tracks_in_table
        << '\n';
  }
}

void write_pcl_run_csvs(const std::filesystem::path& dir, const PclScenarioParams& scenario,
                        const PclScenarioRun& run, const PclRunOutput& out, const PclTolerance& tol) {
  const double lambda = pcl_lambda_m(scenario);
  const std::size_t n = std::min(run.frames.size(), out.frames.size());
  // The truth `generate` writes beside a stream: `replay --truth` takes either.
  write_pcl_truth_csv(dir / "pcl_truth.csv", run);
  {
    std::ofstream f = open_out(dir / "pcl_candidates.csv");
    f << "time_s,index,rb_m,fd_hz,drb_mps,snr_db,is_target,chosen_by_track\n";
    for (std::size_t k = 0; k < n; ++k) {
      const hal::Frame& w = run.frames[k].wire;
      std::map<int, std::uint32_t> chosen;
      for (const PclTrackRow& r : out.frames[k].tracks) {
        if (r.frame_index >= 0) chosen[r.frame_index] = r.id;
      }
      for (std::size_t i = 0; i < w.count; ++i) {
        const double rb = static_cast<double>(w.pcl[i].bistatic_range_mm) * 1e-3;
        const double fd = static_cast<double>(w.pcl[i].doppler_mhz) * 1e-3;
        const auto it = chosen.find(static_cast<int>(i));
        f << static_cast<double>(w.t_us) * 1e-6 << ',' << i << ',' << rb << ',' << fd << ','
          << range_rate_from_doppler(fd, lambda) << ',' << static_cast<double>(w.pcl[i].snr_cdb) * 0.01 << ','
          << (static_cast<int>(i) == run.frames[k].target_index ? 1 : 0) << ','
          << (it == chosen.end() ? 0u : it->second) << '\n';
      }
    }
  }
  std::vector<double> time_s;
  for (const PclTruth& t : run.truth) time_s.push_back(t.t_s);
  write_pcl_tracks_csv(dir / "pcl_tracks.csv", out.frames, time_s, lambda, &run.truth, tol);
}

void write_pcl_tracks_csv(const std::filesystem::path& path, const std::vector<PclFrameOutcome>& frames,
                          const std::vector<double>& time_s, double lambda_m, const std::vector<PclTruth>* truth,
                          const PclTolerance& tol) {
  std::ofstream f = open_out(path);
  f << "time_s,track_id,associated,frame_index,rb_m,drb_mps,fd_hz,p_rr,p_rd,p_dd,nis,test_ratio,age,hits,misses,"
       "pred_rb_m,pred_drb_mps,pred_fd_hz,on_target\n";
  const std::size_t n = std::min(frames.size(), time_s.size());
  const double nan = std::nan("");
  for (std::size_t k = 0; k < n; ++k) {
    for (const PclTrackRow& r : frames[k].tracks) {
      // Without truth there is nothing to be on: the cell stays empty.
      std::string on;
      if (truth != nullptr && k < truth->size() && std::isfinite((*truth)[k].rb_m)) {
        const PclTruth& t = (*truth)[k];
        on = std::abs(r.rb_m - t.rb_m) <= tol.rb_m && std::abs(r.drb_mps - t.drb_mps) <= tol.drb_mps ? "1" : "0";
      }
      f << time_s[k] << ',' << r.id << ',' << (r.associated ? 1 : 0) << ',' << r.frame_index << ',' << r.rb_m << ','
        << r.drb_mps << ',' << doppler_from_range_rate(r.drb_mps, lambda_m) << ',' << r.p_rr << ',' << r.p_rd << ','
        << r.p_dd << ',' << csv_cell(r.nis) << ',' << r.test_ratio << ',' << r.age << ',' << r.hits << ',' << r.misses
        << ',' << csv_cell(r.has_prediction ? r.pred_rb_m : nan) << ','
        << csv_cell(r.has_prediction ? r.pred_drb_mps : nan) << ','
        << csv_cell(r.has_prediction ? doppler_from_range_rate(r.pred_drb_mps, lambda_m) : nan) << ',' << on << '\n';
    }
  }
  if (!f) throw std::runtime_error("cannot write '" + path.string() + "'");
}

nlohmann::json pcl_scenario_json(const PclScenarioParams& sc) {
  return {{"name", sc.name},
          {"frames", sc.frames},
          {"frame_period_s", sc.frame_period_s},
          {"carrier_hz", sc.carrier_hz},
          {"pd", sc.pd},
          {"sigma_rb_m", sc.sigma_rb_m},
          {"sigma_fd_hz", sc.sigma_fd_hz},
          {"clutter_mean", sc.clutter_mean},
          {"ridge_max", sc.ridge_max},
          {"scan_capacity", sc.scan_capacity},
          {"track_capacity", pcl_track_capacity(sc.scan_capacity)}};
}

nlohmann::json pcl_tracker_json(const PclTrackerParams& p, const TrackerPolicies& policies) {
  return {{"accel_sigma_mps2", p.accel_sigma_mps2},
          {"gate_confirmed", gate_name(p.gate_confirmed)},
          {"gate_tentative", gate_name(p.gate_tentative)},
          {"confirm_m", p.confirm_m},
          {"confirm_n", p.confirm_n},
          {"min_start_doppler_hz", p.min_start_doppler_hz},
          {"max_coast_misses", p.max_coast_misses},
          {"max_rb_variance_m2", p.max_rb_variance_m2},
          {"associator", policy_name(kAssociatorNames, policies.associator)},
          {"manager", policy_name(kManagerNames, policies.manager)},
          {"detection_probability", p.detection_probability},
          {"clutter_density", p.clutter_density},
          {"new_target_density", p.new_target_density},
          {"false_track_probability", p.false_track_probability},
          {"missed_track_probability", p.missed_track_probability}};
}

nlohmann::json pcl_summary_json(const PclScenarioParams& sc, const PclTrackerParams& p, const PclMonteCarloParams& c,
                                const PclSummary& s) {
  nlohmann::json j = {
      {"kind", sensor_kind_name(hal::FrameKind::kPcl)},
      {"scenario", pcl_scenario_json(sc)},
      {"tracker", pcl_tracker_json(p, c.policies)},
      {"runs", s.runs},
      {"base_seed", c.base_seed},
      {"tolerance", {{"rb_m", c.tolerance.rb_m}, {"drb_mps", c.tolerance.drb_mps}}},
      {"association_accuracy", interval_json(s.association_accuracy)},
      {"association_accuracy_pooled", number_or_null(s.pooled_accuracy)},
      {"coverage_after_confirmation", interval_json(s.coverage)},
      {"coverage_pooled", number_or_null(s.pooled_coverage)},
      {"false_confirmed_tracks_per_run", interval_json(s.false_tracks)},
      {"runs_with_false_track", s.runs_with_false_track},
      {"total_false_tracks", s.total_false_tracks},
      {"runs_never_confirmed", s.runs_never_confirmed},
      {"rb_rmse_m", interval_json(s.rb_rmse_m)},
      {"drb_rmse_mps", interval_json(s.drb_rmse_mps)},
      {"time_to_first_confirmation_s", interval_json(s.time_to_confirm_s)},
      {"detections", s.detections},
      {"detections_cut_by_adapter", s.cut_by_adapter},
      {"detections_cut_by_sensor", s.cut_by_sensor},
      {"frames_over_capacity", s.frames_over_capacity},
      {"frames_refused", s.frames_refused},
      {"vetoed_starts", s.refused_starts},
      {"dropped_starts", s.dropped_starts},
      {"max_tracks_in_table", s.max_tracks_in_table},
  };
  j["step_ns"] = step_ns_json(s.timing);
  j["step_ns"]["jobs"] = c.jobs;
  return j;
}

bool plot_pcl(const std::filesystem::path& dir, const std::string& title) {
  return run_named_plot_script("pcl_plots.py", {"--dir", dir.string(), "--title", title});
}

}  // namespace kestrel::sim
