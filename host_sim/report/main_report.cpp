// SPDX-License-Identifier: Apache-2.0
#include "report/main_report.hpp"

#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "kestrel/version.hpp"
#include "report/output_files.hpp"
#include "scenarios/sensor_kind.hpp"

namespace kestrel::sim {

namespace {

// interval_text of a summary JSON's {"mean", "ci95_low", "ci95_high"}
// (null where a value was not finite).
std::string interval(const nlohmann::json& j, const char* key, const char* f) {
  if (!j.contains(key) || !j[key].is_object()) return "-";
  const auto number = [&](const char* name) {
    const nlohmann::json& v = j[key].value(name, nlohmann::json());
    return v.is_number() ? v.get<double>() : std::numeric_limits<double>::quiet_NaN();
  };
  return interval_text({number("mean"), number("ci95_low"), number("ci95_high"), 0}, f);
}

nlohmann::json read_json(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("report: cannot read '" + path.string() + "'");
  return nlohmann::json::parse(in);
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("report: cannot read '" + path.string() + "'");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void figures(std::ostream& out, const std::vector<std::filesystem::path>& files) {
  for (const auto& f : files) out << "![" << f.filename().string() << "](" << f.generic_string() << ")\n";
  if (!files.empty()) out << "\n";
}

void radar_section(std::ostream& out, const MainReport& r) {
  out << "## Paper 000: adaptive EKF on manoeuvring radar targets (S1, S2)\n\n"
      << "Park et al., \"An Adaptive Extended Kalman Filter Incorporating Noise Adaptation and Maneuver "
         "Awareness\". EKF-CA at the paper's qj 1.6 m^2/s^5, EKF-CA with a tuned qj, R2-AEKF and Kestrel's IMM "
         "(CV/CA/CT, docs/imm.md), each "
      << r.runs << " seeded runs from seed " << r.seed
      << ", scored ungated as the paper scores filters (docs/host_sim.md, \"Metrics\"; docs/r2aekf.md).\n\n"
      << "| scenario | filter | runs | RMSE m [95 % CI] | peak m | position NEES | NIS | runs without loss | "
         "step us median / p99 |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& row : r.radar) {
    const MonteCarloSummary& s = row.row.summary;
    out << "| " << row.row.scenario << " | " << row.label << " | " << s.runs << " | " << interval_text(s.rmse_m, "%.1f")
        << " | " << interval_text(s.peak_m, "%.0f") << " | " << interval_text(s.nees_pos, "%.1f") << " | "
        << interval_text(s.nis, "%.2f") << " | " << s.runs_without_loss << "/" << s.runs << " | "
        << format_number("%.1f", static_cast<double>(s.timing.median_ns) * 1e-3) << " / "
        << format_number("%.1f", static_cast<double>(s.timing.p99_ns) * 1e-3) << " |\n";
  }
  out << "\nPer-scenario files: `<scenario>/<filter>_{tracks,steps,runs}.csv`, `summary.json`.\n\n";
  if (!r.radar_summary_figure.empty()) out << "![summary](" << r.radar_summary_figure << ")\n\n";
  for (const auto& row : r.radar) {
    std::vector<std::filesystem::path> f(row.figures.begin(), row.figures.end());
    figures(out, f);
  }
}

void mc001_section(std::ostream& out, const std::filesystem::path& root, const MainReport& r) {
  out << "## Paper 001: EKF family and cost-reference particle filter (MC-001)\n\n"
      << "\"Performance Comparison of Various Extended Kalman Filter and Cost-Reference Particle Filter for "
         "Target Tracking with Unknown Noise\". The MC-001 grid at "
      << r.mc_runs << " runs per cell (the full campaign is 3000: `kestrel-sim montecarlo`; docs/filters.md).\n\n"
      << read_text(root / r.mc001_dir / "mc001_table.md") << "\n"
      << "Files: `" << r.mc001_dir << "/mc001_mse.csv`, `mc001_timing.csv`, `mc001_runs.bin`.\n\n";
  figures(out, r.mc001_figures);
}

/// The entry of `filter` in a summary.json of one scenario (results[*][filter]).
nlohmann::json summary_entry_of(const std::filesystem::path& path, std::string_view filter) {
  const nlohmann::json j = read_json(path);
  const std::string key(filter);
  if (j.contains("results") && j["results"].is_object()) {
    for (const auto& entries : j["results"]) {
      if (entries.is_object() && entries.contains(key)) return entries[key];
    }
  }
  throw std::runtime_error(path.string() + ": no '" + std::string(filter) + "' entry");
}

void pcl_section(std::ostream& out, const std::filesystem::path& root, const MainReport& r) {
  const nlohmann::json j = summary_entry_of(root / r.pcl_dir / "summary.json", kPclFilterName);
  const nlohmann::json& t = j["tracker"];
  out << "## Paper 002: passive bistatic radar, range and range-rate tracking (PCL-002)\n\n"
      << "Range and range-rate Kalman filter tracking in a bistatic environment. "
      << j["runs"].get<std::size_t>() << " runs of " << j["scenario"]["name"].get<std::string>() << ", associator "
      << t["associator"].get<std::string>() << ", manager " << t["manager"].get<std::string>()
      << " (docs/pcl.md).\n\n"
      << "| association accuracy | coverage after confirmation | false confirmed tracks per run | Rb RMSE m | "
         "dRb RMSE m/s | time to first confirmation s |\n|---|---|---|---|---|---|\n"
      << "| " << interval(j, "association_accuracy", "%.4f") << " | "
      << interval(j, "coverage_after_confirmation", "%.4f") << " | "
      << interval(j, "false_confirmed_tracks_per_run", "%.3f") << " | " << interval(j, "rb_rmse_m", "%.2f")
      << " | " << interval(j, "drb_rmse_mps", "%.2f") << " | " << interval(j, "time_to_first_confirmation_s", "%.2f")
      << " |\n\nFiles: `" << r.pcl_dir << "/pcl_{runs,truth,candidates,tracks}.csv`, `summary.json`.\n\n";
  figures(out, r.pcl_figures);
}

void sonar_section(std::ostream& out, const std::filesystem::path& root, const MainReport& r) {
  const nlohmann::json j = summary_entry_of(root / r.sonar_dir / "summary.json", kSonarFilterName);
  out << "## Paper 003: underwater multipath TOA tracking (UW-003)\n\n"
      << "\"A Study on Real-time Target Tracking Algorithm for Multipath Underwater Acoustic Signals Using "
         "Extended Kalman Filter\". "
      << j["runs"].get<std::size_t>() << " runs of " << j["scenario"]["name"].get<std::string>()
      << " with the default gate (docs/sonar.md).\n\n"
      << "| 3D RMSE m | horizontal RMSE m | depth RMSE m | peak 3D m | NEES | re-initialisations |\n"
      << "|---|---|---|---|---|---|\n"
      << "| " << interval(j, "rmse_3d_m", "%.2f") << " | " << interval(j, "rmse_h_m", "%.2f") << " | "
      << interval(j, "rmse_depth_m", "%.2f") << " | " << interval(j, "peak_3d_m", "%.1f") << " | "
      << interval(j, "nees", "%.2f") << " | " << j["reinitialisations"].dump() << " |\n\n"
      << "Files: `" << r.sonar_dir << "/sonar_{runs,steps,truth,arrivals,track}.csv`, `summary.json`.\n\n";
  figures(out, r.sonar_figures);
}

}  // namespace

void write_main_report(const std::filesystem::path& path, const std::filesystem::path& root,
                       const MainReport& r) {
  std::ostringstream out;
  out << "# Kestrel: the four papers' systems, one run of each\n\n"
      << "`kestrel-sim suite` (kestrel-sim " << KESTREL_VERSION_STRING << "), " << format_number("%.1f", r.wall_s)
      << " s. Every run drives the tracker core through the HAL's wire frames, as a board does.\n\n";
  if (!r.radar.empty()) out << "- [Paper 000: radar, S1 and S2](#paper-000-adaptive-ekf-on-manoeuvring-radar-targets-s1-s2)\n";
  if (!r.mc001_dir.empty()) {
    out << "- [Paper 001: MC-001](#paper-001-ekf-family-and-cost-reference-particle-filter-mc-001)\n";
  }
  if (!r.pcl_dir.empty()) {
    out << "- [Paper 002: PCL-002](#paper-002-passive-bistatic-radar-range-and-range-rate-tracking-pcl-002)\n";
  }
  if (!r.sonar_dir.empty()) out << "- [Paper 003: UW-003](#paper-003-underwater-multipath-toa-tracking-uw-003)\n";
  out << "\n";
  if (!r.radar.empty()) radar_section(out, r);
  if (!r.mc001_dir.empty()) mc001_section(out, root, r);
  if (!r.pcl_dir.empty()) pcl_section(out, root, r);
  if (!r.sonar_dir.empty()) sonar_section(out, root, r);

  std::ofstream file(path);
  file << out.str();
  if (!file) throw std::runtime_error("cannot write '" + path.string() + "'");
}

}  // namespace kestrel::sim
