// SPDX-License-Identifier: Apache-2.0
#include "report/summary_json.hpp"

#include <fstream>
#include <stdexcept>

#include "report/output_files.hpp"
#include "scenarios/sensor_kind.hpp"

namespace kestrel::sim {

namespace {
constexpr const char* kSchema = "kestrel-sim-summary/1";
}  // namespace

nlohmann::json summary_metrics(const MonteCarloSummary& s) {
  return {
      {"runs", s.runs},
      {"rmse_m", interval_json(s.rmse_m)},
      {"peak_m", interval_json(s.peak_m)},
      {"nees_pos", interval_json(s.nees_pos)},
      {"nis", interval_json(s.nis)},
      {"track_loss_s", interval_json(s.track_loss_s)},
      {"recovery_s", interval_json(s.recovery_s)},
      {"runs_without_loss", s.runs_without_loss},
      {"runs_with_missing_track", s.runs_with_missing},
      {"missing_steps", s.missing_steps},
      {"max_confirmed_tracks", s.max_confirmed_tracks},
      {"track_switches", interval_json(s.track_switches)},
      {"frames_not_ok", s.frames_not_ok},
      {"held_fraction", interval_json(s.held_fraction)},
      {"worst_held_fraction", number_or_null(s.worst_held_fraction)},
      {"loss_episodes", interval_json(s.loss_episodes)},
      {"track_ids_on_target", interval_json(s.track_ids_on_target)},
      {"max_track_ids_on_target", s.max_track_ids_on_target},
      {"false_confirmed_tracks_per_run", interval_json(s.false_tracks)},
      {"step_ns", step_ns_json(s.timing)},
  };
}

nlohmann::json summary_entry(const EntryContext& c, const MonteCarloSummary& s) {
  nlohmann::json parameters = nlohmann::json::object();
  for (const auto& [name, value] : c.setup.parameters) parameters[name] = value;
  nlohmann::json entry = summary_metrics(s);
  entry["kind"] = sensor_kind_name(hal::FrameKind::kRadar);
  entry["scenario"] = c.scenario;
  entry["filter"] = c.filter;
  entry["filter_label"] = c.setup.label;
  entry["parameters"] = parameters;
  entry["base_seed"] = c.base_seed;
  entry["frame_period_s"] = c.frame_period_s;
  entry["loss_threshold_m"] = c.loss_threshold_m;
  entry["first_scored_step"] = c.first_scored_step;
  entry["step_ns"]["jobs"] = c.jobs;
  return entry;
}

void write_summary_file(const std::filesystem::path& path, const nlohmann::json& results) {
  write_json_file(path, {{"schema", kSchema}, {"results", results}});
}

void merge_summary_file(const std::filesystem::path& path, const std::string& scenario, const std::string& filter,
                        const nlohmann::json& entry) {
  nlohmann::json results = nlohmann::json::object();
  std::ifstream in(path);
  if (in) {
    const nlohmann::json old = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    if (old.is_object() && old.value("schema", "") == kSchema && old.contains("results") &&
        old["results"].is_object()) {
      results = old["results"];
    }
  }
  results[scenario][filter] = entry;
  write_summary_file(path, results);
}

}  // namespace kestrel::sim
