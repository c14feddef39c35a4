// SPDX-License-Identifier: Apache-2.0
// `kestrel-sim generate`: one seeded run of a scenario as files a user can
// replay or inspect: the wire stream, its truth (any kind) and its plots
// (radar) as CSV, and with --asterix the plots as ASTERIX CAT048 data blocks.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "csv/radar_plot_csv.hpp"
#include "csv/sensor_truth_csv.hpp"
#include "csv/truth_csv.hpp"
#include "montecarlo/pcl_run.hpp"
#include "montecarlo/sonar_run.hpp"
#include "scenarios/registry.hpp"
#include "stream/asterix_stream.hpp"
#include "stream/quantise.hpp"
#include "stream/stream_writer.hpp"

namespace kestrel::sim::cli {

namespace {

bool is_name_of(const std::string& name, const std::vector<std::string>& names) {
  std::string key(name);
  for (char& ch : key) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return std::find(names.begin(), names.end(), key) != names.end();
}

// PCL and sonar scenarios: the wire stream and its truth, in the layout
// `run` writes for run 0 (csv/sensor_truth_csv.hpp), which `replay
// --truth` scores against.
int generate_other_kind(const GenerateOptions& o) {
  std::vector<std::uint8_t> bytes;
  std::size_t frames = 0;
  std::string name;
  const std::filesystem::path stream_path(o.out);
  const auto truth_path = std::filesystem::path(stream_path).replace_extension(".truth.csv");
  if (is_name_of(o.scenario, pcl_scenario_names())) {
    const PclScenarioParams c = pcl_config_by_name(o.scenario);
    name = c.name;
    if (o.asterix) throw std::invalid_argument("--asterix: CAT048 carries radar plots only, not " + name);
    const PclScenarioRun run = generate_pcl(c, o.seed);
    bytes = encode_pcl_stream(run);
    frames = run.frames.size();
    if (stream_path.has_parent_path()) std::filesystem::create_directories(stream_path.parent_path());
    write_pcl_truth_csv(truth_path, run);
  } else {
    const SonarScenarioParams c = sonar_config_by_name(o.scenario);
    name = c.name;
    if (o.asterix) throw std::invalid_argument("--asterix: CAT048 carries radar plots only, not " + name);
    const SonarScenarioRun run = generate_sonar(c, o.seed);
    bytes = encode_sonar_stream(run);
    frames = run.frames.size();
    if (stream_path.has_parent_path()) std::filesystem::create_directories(stream_path.parent_path());
    write_sonar_truth_csv(truth_path, run);
  }
  write_bytes(stream_path, bytes);
  std::printf("%s seed %llu: %zu frames, %zu bytes\n  stream %s\n  truth  %s\n", name.c_str(),
              static_cast<unsigned long long>(o.seed), frames, bytes.size(), stream_path.c_str(), truth_path.c_str());
  return 0;
}

}  // namespace

int cmd_generate(const GenerateOptions& o) {
  if (is_name_of(o.scenario, pcl_scenario_names()) || is_name_of(o.scenario, sonar_scenario_names())) {
    return generate_other_kind(o);
  }
  const auto scenario = make_scenario(o.scenario);
  const ScenarioRun run = scenario->generate(o.seed);
  const std::filesystem::path stream_path(o.out);
  if (stream_path.has_parent_path()) std::filesystem::create_directories(stream_path.parent_path());
  const std::vector<std::uint8_t> bytes = encode_stream(run.frames);
  write_bytes(stream_path, bytes);

  // The plot CSV carries the values as quantised on the wire, so replaying
  // it gives exactly the frames of the stream.
  std::vector<MeasurementFrame> wire_frames;
  for (const MeasurementFrame& f : run.frames) wire_frames.push_back(from_wire_frame(to_wire_frame(f)));
  const auto truth_path = std::filesystem::path(stream_path).replace_extension(".truth.csv");
  const auto plots_path = std::filesystem::path(stream_path).replace_extension(".plots.csv");
  // Several targets: every one of them, which `replay --truth` then scores
  // as `run` scores the scenario (OSPA, GOSPA, swaps).
  if (run.targets.size() > 1) {
    write_targets_truth_csv(truth_path, run.targets);
  } else {
    write_truth_csv(truth_path, run.truth);
  }
  write_radar_plot_csv(plots_path, wire_frames);

  std::printf("%s seed %llu: %zu frames, %zu bytes\n  stream %s\n  truth  %s\n  plots  %s\n",
              scenario->info().name.c_str(), static_cast<unsigned long long>(o.seed), run.frames.size(),
              bytes.size(), stream_path.c_str(), truth_path.c_str(), plots_path.c_str());
  if (o.asterix) {
    // From the scenario's own plots, not the wire-quantised ones: ASTERIX
    // is a sensor's output format in its own right, rounded once.
    const std::vector<std::uint8_t> ast = encode_cat048_stream(run.frames, static_cast<std::uint8_t>(o.asterix_sac));
    const auto ast_path = std::filesystem::path(stream_path).replace_extension(".ast");
    write_bytes(ast_path, ast);
    std::printf("  cat048 %s (%zu bytes, one data block per frame)\n", ast_path.c_str(), ast.size());
  }
  return 0;
}

}  // namespace kestrel::sim::cli
