// SPDX-License-Identifier: Apache-2.0
#include "report/summary_json.hpp"

#include <cmath>
#include <fstream>
#include <stdexcept>

namespace kestrel::sim {

namespace {
constexpr const char* kSchema = "kestrel-sim-summary/1";

nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json interval(const MeanCi& m) {
  return {{"mean", number_or_null(m.mean)},
          {"ci95_low", number_or_null(m.ci95_low)},
          {"ci95_high", number_or_null(m.ci95_high)},
          {"n", m.n}};
}
}  // namespace

nlohmann::json summary_entry(const EntryContext& c, const MonteCarloSummary& s) {
  nlohmann::json parameters = nlohmann::json::object();
  for (const auto& [name, value] : c.setup.parameters) parameters[name] = value;
  return {
      {"scenario", c.scenario},
      {"filter", c.filter},
      {"filter_label", c.setup.label},
      {"parameters", parameters},
      {"runs", s.runs},
      {"base_seed", c.base_seed},
      {"frame_period_s", c.frame_period_s},
      {"loss_threshold_m", c.loss_threshold_m},
      {"first_scored_step", c.first_scored_step},
      {"rmse_m", interval(s.rmse_m)},
      {"peak_m", interval(s.peak_m)},
      {"nees_pos", interval(s.nees_pos)},
      {"nis", interval(s.nis)},
      {"track_loss_s", interval(s.track_loss_s)},
      {"recovery_s", interval(s.recovery_s)},
      {"runs_without_loss", s.runs_without_loss},
      {"runs_with_missing_track", s.runs_with_missing},
      {"missing_steps", s.missing_steps},
      {"max_confirmed_tracks", s.max_confirmed_tracks},
      {"track_switches", interval(s.track_switches)},
      {"frames_not_ok", s.frames_not_ok},
      {"held_fraction", interval(s.held_fraction)},
      {"worst_held_fraction", number_or_null(s.worst_held_fraction)},
      {"loss_episodes", interval(s.loss_episodes)},
      {"track_ids_on_target", interval(s.track_ids_on_target)},
      {"max_track_ids_on_target", s.max_track_ids_on_target},
      {"false_confirmed_tracks", interval(s.false_tracks)},
      {"step_ns",
       {{"min", s.timing.min_ns},
        {"median", s.timing.median_ns},
        {"p99", s.timing.p99_ns},
        {"max", s.timing.max_ns},
        {"mean", s.timing.mean_ns},
        {"steps", s.timing.steps},
        {"budget_ns", s.timing.budget_ns},
        {"overruns", s.timing.overruns},
        {"jobs", c.jobs}}},
  };
}

void write_summary_file(const std::filesystem::path& path, const nlohmann::json& results) {
  const nlohmann::json doc = {{"schema", kSchema}, {"results", results}};
  std::ofstream out(path, std::ios::trunc);
  if (!out) throw std::runtime_error("cannot create '" + path.string() + "'");
  out << doc.dump(2) << '\n';
  if (!out) throw std::runtime_error("cannot write '" + path.string() + "'");
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
