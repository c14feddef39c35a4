// SPDX-License-Identifier: Apache-2.0
// results/report.md of the main job (`kestrel-sim suite`): one page with the
// table of each paper's system and links to its figures and files.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "report/results_table.hpp"

namespace kestrel::sim {

/// What the suite ran; paths are relative to the report's directory and a
/// part that did not run has an empty directory.
struct MainReport {
  struct RadarRow {
    TableRow row;
    std::string label;                  ///< Filter and parameters.
    std::vector<std::string> figures;   ///< Written by this run only.
  };
  std::uint64_t seed = 0;
  std::size_t runs = 0;
  std::uint64_t mc_runs = 0;
  double wall_s = 0.0;
  std::vector<RadarRow> radar;
  std::string radar_summary_figure;
  std::string mc001_dir;
  std::vector<std::filesystem::path> mc001_figures;
  std::string pcl_dir;
  std::vector<std::filesystem::path> pcl_figures;
  std::string sonar_dir;
  std::vector<std::filesystem::path> sonar_figures;
};

/// Write `path` (markdown) from `report` and the summaries the parts wrote
/// under `root` (the PCL and sonar parts' summary.json, mc001_table.md).
void write_main_report(const std::filesystem::path& path, const std::filesystem::path& root,
                       const MainReport& report);

}  // namespace kestrel::sim
