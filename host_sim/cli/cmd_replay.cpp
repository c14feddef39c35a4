// SPDX-License-Identifier: Apache-2.0
// `kestrel-sim replay`: run a filter over recorded data, a wire stream file,
// a radar plot CSV (docs/host_sim.md) or an ASTERIX CAT048 recording, through
// the same board loop as the simulation. With a truth CSV the run is scored
// like a scenario run; with --asterix-out its reports are also CAT062.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "cli/commands.hpp"
#include "cli/scenario_report.hpp"
#include "csv/radar_plot_csv.hpp"
#include "csv/step_csv.hpp"
#include "csv/truth_csv.hpp"
#include "filters/filter_registry.hpp"
#include "montecarlo/single_run.hpp"
#include "plots/plot_runner.hpp"
#include "report/run_files.hpp"
#include "report/summary_json.hpp"
#include "stream/asterix_stream.hpp"
#include "stream/quantise.hpp"
#include "stream/stream_writer.hpp"

namespace kestrel::sim::cli {

namespace {

const char* frame_kind_name(hal::FrameKind kind) {
  switch (kind) {
    case hal::FrameKind::kRadar: return "radar";
    case hal::FrameKind::kSonar: return "sonar";
    case hal::FrameKind::kPcl: return "PCL";
  }
  return "unknown";
}

std::vector<std::uint8_t> read_file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open '" + path.string() + "'");
  return std::vector<std::uint8_t>((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// T for the loss time: the median interval between decoded frames (robust
// to a missing or damaged frame); NaN with fewer than two frames.
double median_frame_period_s(const std::vector<MeasurementFrame>& frames) {
  std::vector<double> dt;
  double last = std::nan("");
  for (const MeasurementFrame& f : frames) {
    if (!std::isfinite(f.t_s)) continue;
    if (std::isfinite(last) && f.t_s > last) dt.push_back(f.t_s - last);
    last = f.t_s;
  }
  if (dt.empty()) return std::nan("");
  std::nth_element(dt.begin(), dt.begin() + static_cast<std::ptrdiff_t>(dt.size() / 2), dt.end());
  return dt[dt.size() / 2];
}

void print_status_counts(const hal::RunnerStats& s) {
  std::printf("frames %u, steps %u; final status per frame:", s.frames, s.steps);
  for (std::uint8_t i = 0; i < kStatusCount; ++i) {
    if (s.by_status[i] != 0) std::printf(" %s %u", to_string(static_cast<Status>(i)), s.by_status[i]);
  }
  std::printf("\n");
}

void print_asterix_counts(const std::string& source, const AsterixReadCounts& c) {
  std::printf("ASTERIX %s: %u CAT048 blocks, %u records, %u plots in %u frames; %u blocks of other categories "
              "skipped, %u malformed, %u truncated, %u records without a plot, %u plots over a frame's capacity\n",
              source.c_str(), c.feed.blocks, c.reader.records, c.reader.plots, c.feed.frames, c.feed.unknown_category,
              c.feed.malformed, c.feed.truncated, c.reader.skipped_no_plot, c.reader.dropped_over_capacity);
}

nlohmann::json asterix_json(const AsterixReadCounts& c) {
  return {{"cat048_blocks", c.feed.blocks},          {"records", c.reader.records},
          {"plots", c.reader.plots},                 {"frames", c.feed.frames},
          {"other_category_blocks", c.feed.unknown_category}, {"malformed", c.feed.malformed},
          {"truncated", c.feed.truncated},           {"records_without_plot", c.reader.skipped_no_plot},
          {"plots_over_capacity", c.reader.dropped_over_capacity}};
}

}  // namespace

int cmd_replay(const ReplayOptions& o) {
  if (int{!o.stream.empty()} + int{!o.csv.empty()} + int{!o.asterix.empty()} != 1) {
    throw std::invalid_argument("give exactly one of --stream, --csv and --asterix");
  }
  const FilterEntry& filter = find_filter(o.filter.filter);

  std::vector<std::uint8_t> bytes;
  std::vector<MeasurementFrame> frames;
  std::string source;
  std::size_t skipped = 0;  // stream frames that did not decode
  StreamFormat format = StreamFormat::kWire;
  std::optional<AsterixReadCounts> asterix_counts;
  if (!o.asterix.empty()) {
    source = o.asterix;
    format = StreamFormat::kAsterixCat048;
    bytes = read_file_bytes(o.asterix);
    AsterixReadCounts counts;
    frames = decode_cat048_stream(bytes, skipped, counts);
    asterix_counts = counts;
    if (!bytes.empty()) print_asterix_counts(source, counts);
    if (!bytes.empty() && counts.reader.plots == 0) {
      // Not a recording with nothing in it: a file that is not CAT048 at
      // all (a wire stream, another category, garbage) must not pass as a run.
      char first[8];
      std::snprintf(first, sizeof first, "0x%02X", bytes.front());
      throw std::runtime_error(source + ": no CAT048 plot in " + std::to_string(bytes.size()) +
                               " bytes: not an ASTERIX CAT048 recording? (first byte " + first +
                               ", CAT048 blocks start with 0x30; " + std::to_string(counts.feed.unknown_category) +
                               " blocks of other categories, " + std::to_string(counts.feed.malformed) +
                               " malformed, " + std::to_string(counts.feed.truncated) + " truncated)");
    }
  } else if (!o.csv.empty()) {
    source = o.csv;
    const std::vector<MeasurementFrame> plots = read_radar_plot_csv(std::filesystem::path(o.csv));
    bytes = encode_stream(plots);
    for (const MeasurementFrame& f : plots) frames.push_back(from_wire_frame(to_wire_frame(f)));
  } else {
    source = o.stream;
    bytes = read_file_bytes(o.stream);
    frames = decode_stream(bytes, skipped);
    if (skipped > 0) std::printf("note: %zu frames of %s did not decode (see the status counts)\n", skipped, source.c_str());
  }
  const std::vector<TruthSample> truth =
      o.truth.empty() ? std::vector<TruthSample>{} : read_truth_csv(std::filesystem::path(o.truth));
  if (frames.size() == skipped) {
    // Not malformed (a bad truth CSV above is still an error), but nothing
    // would be replayed: a script must not take it for a run. Stop before
    // writing files, so no empty summary replaces a real one.
    std::fprintf(stderr, "kestrel-sim: warning: %s held no frames%s, nothing to replay\n", source.c_str(),
                 skipped > 0 ? " that decode" : "");
    return kExitNoFrames;
  }

  // A stream of another sensor kind decodes, but every frame would be
  // refused as the wrong kind: an empty run, never a result.
  const std::size_t of_filter_kind = static_cast<std::size_t>(
      std::count_if(frames.begin(), frames.end(), [&](const MeasurementFrame& f) { return f.kind == filter.kind; }));
  if (of_filter_kind == 0) {
    throw std::runtime_error(source + ": its " + std::to_string(frames.size()) + " frames are " +
                             frame_kind_name(frames.front().kind) + " frames; filter '" + std::string(filter.name) +
                             "' takes " + frame_kind_name(filter.kind) +
                             " frames (replay runs the radar filters of `kestrel-sim list`; PCL and sonar streams "
                             "are not replayed yet)");
  }

  FilterOptions options = o.filter.options;
  // Gated as a board by default; --ungated or a board_gate setting say otherwise.
  if (o.ungated && o.filter.board_gate_set && options.board_gate) {
    throw std::invalid_argument("--ungated and the setting board_gate=true contradict each other");
  }
  if (o.ungated || !o.filter.board_gate_set) options.board_gate = !o.ungated;
  const std::uint64_t budget_ns = budget_ns_from_us(o.filter.budget_us);
  ScoringConfig scoring;
  scoring.first_scored_step = o.first_scored_step;
  const double period_s = median_frame_period_s(frames);
  StreamInput input(std::move(bytes), format);
  if (!o.asterix_out.path.empty()) {
    input.cat062 = hal::asterix::Cat062Source{static_cast<std::uint8_t>(o.asterix_out.sac),
                                              static_cast<std::uint8_t>(o.asterix_out.sic), false, 0};
  }
  RunDetail d = evaluate_stream(std::move(input), frames, truth, filter, options, budget_ns, scoring, period_s,
                                o.loss_threshold_m);

  const std::filesystem::path dir(o.out);
  std::filesystem::create_directories(dir);
  const RunFileNames names = run_file_names(dir, std::string(filter.name));
  write_track_csv(names.tracks_csv, d.stream);

  const std::vector<RunRecord> runs{record_of(d)};
  TableRow row{"replay", std::string(filter.name), summarise(runs, budget_ns)};
  EntryContext context;
  context.scenario = "replay";
  context.filter = row.filter;
  context.setup = filter.setup(options);
  context.frame_period_s = period_s;
  context.loss_threshold_m = o.loss_threshold_m;
  context.first_scored_step = o.first_scored_step;
  nlohmann::json entry = summary_entry(context, row.summary);
  entry["source"] = source;
  entry["truth"] = o.truth;
  if (asterix_counts.has_value()) entry["asterix"] = asterix_json(*asterix_counts);
  if (!o.asterix_out.path.empty()) {
    write_bytes(o.asterix_out.path, d.stream.cat062);
    entry["asterix_out"] = {{"path", o.asterix_out.path},
                            {"bytes", d.stream.cat062.size()},
                            {"reports_not_written", d.stream.cat062_refused}};
  }
  merge_summary_file(dir / "summary.json", context.scenario, context.filter, entry);

  print_status_counts(d.stream.stats);
  if (!o.asterix_out.path.empty()) print_cat062_written(o.asterix_out.path, d.stream);
  if (!truth.empty()) {
    write_step_csv(names.steps_csv, d.steps, d.frames, o.loss_threshold_m);
    std::printf("scored %zu frames against %s (T = %g s, L = %g m)\n", d.steps.size(), o.truth.c_str(), period_s,
                o.loss_threshold_m);
    print_table_header(stdout);
    print_table_row(stdout, row);
    if (o.plots) plot_run(names.steps_csv, names.tracks_csv, names.plot_prefix, "replay " + source, o.loss_threshold_m);
    std::printf("wrote %s, %s, %s\n", names.tracks_csv.c_str(), names.steps_csv.c_str(), (dir / "summary.json").c_str());
  } else {
    print_timing(stdout, "replay " + source, row.summary.timing);
    std::printf("no --truth: tracks only. wrote %s, %s\n", names.tracks_csv.c_str(), (dir / "summary.json").c_str());
  }
  return 0;
}

}  // namespace kestrel::sim::cli
