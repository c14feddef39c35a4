// SPDX-License-Identifier: Apache-2.0
// `kestrel-sim replay`: run a tracker over recorded data, a wire stream file,
// a radar plot CSV (docs/host_sim.md) or an ASTERIX CAT048 recording, through
// the same board loop as the simulation. A radar run takes a radar filter and,
// with a truth CSV, is scored like a scenario run; with --asterix-out its
// reports are also CAT062. A PCL or sonar stream runs the tracker of its kind
// with a scenario's sensor parameters and, with the truth CSV of its kind,
// is scored with that kind's metrics, as `run` scores a run of its scenarios.
// --config and --set take the keys of the stream's kind.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <optional>
#include <set>
#include <stdexcept>

#include "cli/commands.hpp"
#include "cli/scenario_report.hpp"
#include "csv/radar_plot_csv.hpp"
#include "csv/sensor_truth_csv.hpp"
#include "csv/step_csv.hpp"
#include "csv/truth_csv.hpp"
#include "filters/filter_registry.hpp"
#include "filters/sensor_settings.hpp"
#include "metrics/replay_scoring.hpp"
#include "montecarlo/pcl_run.hpp"
#include "montecarlo/single_run.hpp"
#include "montecarlo/sonar_run.hpp"
#include "plots/plot_runner.hpp"
#include "report/pcl_files.hpp"
#include "report/output_files.hpp"
#include "report/results_table.hpp"
#include "report/run_files.hpp"
#include "report/summary_json.hpp"
#include "report/sonar_files.hpp"
#include "scenarios/sensor_kind.hpp"
#include "stream/asterix_stream.hpp"
#include "stream/quantise.hpp"
#include "stream/stream_writer.hpp"
#include "timing/step_timing.hpp"

namespace kestrel::sim::cli {

namespace {

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

nlohmann::json status_counts_json(const hal::RunnerStats& s) {
  nlohmann::json j = nlohmann::json::object();
  for (std::uint8_t i = 0; i < kStatusCount; ++i) {
    if (s.by_status[i] != 0) j[to_string(static_cast<Status>(i))] = s.by_status[i];
  }
  return j;
}

/// What every PCL or sonar replay reports, whichever tracker ran.
struct OtherKindResult {
  hal::RunnerStats stats;
  std::vector<std::uint64_t> step_ns;
  std::size_t frames_not_ok = 0;
  std::filesystem::path tracks_csv;
  nlohmann::json entry;  ///< Kind-specific summary fields.
  std::string counts;    ///< Kind-specific line for stdout.
  std::string scored;    ///< With truth: the metrics, for stdout.
};

/// A replay's truth of any kind, read once; `times_s` for the overlap check.
struct ReplayTruth {
  hal::FrameKind kind = hal::FrameKind::kRadar;
  std::vector<TruthSample> radar;
  /// A radar truth of several targets (its `target` column): [i] target i.
  std::vector<std::vector<TruthSample>> radar_targets;
  std::vector<PclTruthRow> pcl;
  std::vector<SonarTruthRow> sonar;
  std::vector<double> times_s;
};

/// The kind's metrics of one run as summary fields: the figures `run` of a
/// PCL or sonar scenario writes into its summary, without its run-count and
/// settings fields (the replay entry has its own).
nlohmann::json metric_fields(nlohmann::json j, std::initializer_list<const char*> drop) {
  for (const char* key : drop) j.erase(key);
  return j;
}

std::string truth_match_text(const TruthMatch& m) {
  return std::to_string(m.matched) + " frames scored, " + std::to_string(m.without_truth) +
         " at a time without truth, " + std::to_string(m.without_time) + " that did not reach the tracker";
}

nlohmann::json truth_match_json(const TruthMatch& m) {
  return {{"matched", m.matched}, {"without_truth", m.without_truth}, {"without_time", m.without_time}};
}

OtherKindResult replay_pcl(std::vector<std::uint8_t> bytes, const std::string& scenario_name,
                           const PclTrackerParams& params, std::uint64_t budget_ns,
                           const std::filesystem::path& dir, const ReplayTruth* truth) {
  const PclScenarioParams sc = pcl_config_by_name(scenario_name);
  const TrackerPolicies policies{};  // run's PCL defaults: nearest neighbour, M-of-N
  // The truth names the target's detection of each frame; without it which
  // candidate is the target's is unknown.
  const PclTargetLocator locate =
      truth != nullptr ? pcl_target_locator(truth->pcl) : PclTargetLocator([](const hal::Frame&) { return -1; });
  const PclRunOutput out = run_pcl_stream(std::move(bytes), locate, sc, params, policies, budget_ns);
  OtherKindResult r;
  r.stats = out.stats;
  r.tracks_csv = dir / "pcl_tracks.csv";
  std::vector<double> time_s;
  std::size_t rows = 0, frames_with_track = 0;
  std::set<std::uint32_t> ids;
  for (const PclFrameOutcome& f : out.frames) {
    time_s.push_back(f.t_s);
    if (f.stepped) r.step_ns.push_back(f.step_ns);
    if (f.status != Status::kOk) ++r.frames_not_ok;
    rows += f.tracks.size();
    frames_with_track += f.tracks.empty() ? 0 : 1;
    for (const PclTrackRow& t : f.tracks) ids.insert(t.id);
  }
  const PclTolerance tolerance{};
  std::optional<PclReplayScore> score;
  if (truth != nullptr) score = score_pcl_replay(out, truth->pcl, tolerance);
  write_pcl_tracks_csv(r.tracks_csv, out.frames, time_s, pcl_lambda_m(sc), score ? &score->truth_per_frame : nullptr,
                       tolerance);
  if (score) {
    const PclRunMetrics& m = score->metrics;
    PclMonteCarloParams config;
    config.runs = 1;
    config.budget_ns = budget_ns;
    config.policies = policies;
    config.tolerance = tolerance;
    r.entry.update(metric_fields(pcl_summary_json(sc, params, config, summarise_pcl({m}, budget_ns)),
                                 {"kind", "scenario", "tracker", "runs", "base_seed", "step_ns", "frames_refused"}));
    r.entry["truth_frames"] = truth_match_json(score->match);
    r.entry["target_tracks"] = m.target_tracks;
    r.entry["confirmed_tracks"] = m.confirmed_tracks;
    r.scored = truth_match_text(score->match) + "\n  association accuracy " +
               format_number("%.4f", m.association_accuracy) + " (" + std::to_string(m.assoc_correct) + " of " +
               std::to_string(m.assoc_frames) + " frames), coverage after confirmation " + format_number("%.4f", m.coverage) +
               " (" + std::to_string(m.covered_frames) + " of " + std::to_string(m.coverage_frames) + ")\n  " +
               "confirmed tracks " + std::to_string(m.confirmed_tracks) + ": on the target " +
               std::to_string(m.target_tracks) + ", false " + std::to_string(m.false_tracks) + "; Rb RMSE " +
               format_number("%.3f", m.rb_rmse_m) + " m, dRb RMSE " + format_number("%.3f", m.drb_rmse_mps) +
               " m/s over " + std::to_string(m.rmse_frames) + " frames; first confirmation at " +
               format_number("%g", m.time_to_confirm_s) + " s";
  }
  r.entry["sensor"] = pcl_scenario_json(sc);
  r.entry["tracker"] = pcl_tracker_json(params, policies);
  r.entry["parameters"] = pcl_parameters(params);  // every key, as the run used it
  r.entry["confirmed_track_rows"] = rows;
  r.entry["frames_with_confirmed_track"] = frames_with_track;
  r.entry["track_ids"] = ids.size();
  r.counts = "confirmed-track rows " + std::to_string(rows) + " in " + std::to_string(frames_with_track) +
             " frames, " + std::to_string(ids.size()) + " track ids";
  return r;
}

OtherKindResult replay_sonar(std::vector<std::uint8_t> bytes, const std::string& scenario_name,
                             const SonarTrackerParams& params, std::uint64_t budget_ns,
                             const std::filesystem::path& dir, const ReplayTruth* truth) {
  const SonarScenarioParams sc = sonar_config_by_name(scenario_name);
  const SonarRunOutput out = run_sonar_stream(std::move(bytes), params, budget_ns);
  OtherKindResult r;
  r.stats = out.stats;
  r.tracks_csv = dir / "sonar_track.csv";
  std::vector<double> time_s;
  std::size_t reported = 0, fixes = 0, predict_only = 0;
  std::set<std::uint32_t> ids;
  for (const SonarFrameOutcome& f : out.frames) {
    time_s.push_back(f.t_s);
    if (f.stepped) r.step_ns.push_back(f.step_ns);
    if (f.status != Status::kOk) ++r.frames_not_ok;
    if (f.reported) {
      ++reported;
      ids.insert(f.track_id);
    }
    fixes += f.initialised ? 1 : 0;
    predict_only += f.predict_only ? 1 : 0;
  }
  write_sonar_track_csv(r.tracks_csv, out.frames, time_s);
  if (truth != nullptr) {
    const SonarReplayScore score = score_sonar_replay(out, truth->sonar);
    const SonarRunMetrics& m = score.metrics;
    SonarMonteCarloParams config;
    config.runs = 1;
    config.budget_ns = budget_ns;
    r.entry.update(metric_fields(sonar_summary_json(sc, params, config, summarise_sonar({m}, budget_ns)),
                                 {"kind", "scenario", "tracker", "runs", "seeds", "per_step", "step_ns",
                                  "frames_refused", "depth_reflections"}));
    r.entry["truth_frames"] = truth_match_json(score.match);
    r.entry["scored_frames"] = m.scored_frames;
    r.entry["init_frame"] = m.init_frame;
    r.scored = truth_match_text(score.match) + "\n  3D RMSE " + format_number("%.3f", m.rmse_3d_m) + " m, horizontal " +
               format_number("%.3f", m.rmse_h_m) + " m, depth " + format_number("%.3f", m.rmse_depth_m) + " m, 3D peak " +
               format_number("%.3f", m.peak_3d_m) + " m, position NEES " + format_number("%.3f", m.nees) + " (3 dof) over " +
               std::to_string(m.scored_frames) + " frames after the fix\n  sound-speed error mean " +
               format_number("%.3f", m.c_err_mean_mps) + " m/s, std " + format_number("%.3f", m.c_err_std_mps) + " m/s; arrivals " +
               std::to_string(m.arrivals) + ": true outliers " + std::to_string(m.outliers) + ", of which gated " +
               std::to_string(m.outliers_gated) + "; good arrivals gated " + std::to_string(m.good_gated);
  }
  r.entry["sensor"] = sonar_scenario_json(sc);
  r.entry["tracker"] = sonar_params_json(params);
  r.entry["parameters"] = sonar_parameters(params);  // every key, as the run used it
  r.entry["frames_with_estimate"] = reported;
  r.entry["track_ids"] = ids.size();
  r.entry["initialisations"] = fixes;
  r.entry["predict_only_frames"] = predict_only;
  r.counts = "frames with an estimate " + std::to_string(reported) + ", track ids " + std::to_string(ids.size()) +
             ", (re)initialisations " + std::to_string(fixes) + ", predict-only frames " + std::to_string(predict_only);
  return r;
}

/// `replay --stream` of a PCL or sonar stream: its one tracker through the
/// same board loop, with the sensor parameters of a scenario of its kind
/// and then `settings` (--config, then --set) of that tracker's keys.
int replay_other_kind(const ReplayOptions& o, hal::FrameKind kind, std::vector<std::uint8_t> bytes,
                      std::size_t frame_count, const std::string& source, const ReplayTruth* truth,
                      const std::vector<Setting>& settings) {
  const std::string kind_name = sensor_kind_name(kind);
  check_filter_fits(o.filter, kind,
                    source + ": its " + std::to_string(frame_count) + " frames are " + kind_name + " frames");
  const std::string scenario = o.scenario.empty() ? (kind == hal::FrameKind::kPcl ? "pcl002" : "uw003") : o.scenario;
  const std::optional<hal::FrameKind> scenario_is = scenario_kind(scenario);
  if (scenario_is != kind) {
    throw std::invalid_argument(
        "--scenario '" + scenario + "' is " +
        (scenario_is ? std::string("a ") + sensor_kind_name(*scenario_is) + " scenario" : std::string("no scenario")) +
        "; " + source + " holds " + kind_name + " frames (" + kind_name +
        " scenarios: " + join_names(scenario_names_of_kind(kind)) + ")");
  }
  check_settings_kind(settings, kind, source + " holds " + kind_name + " frames");
  // The scenario's parameters under the settings, before anything is
  // written: a value out of range stops the replay with no directory made.
  PclTrackerParams pcl_params;
  SonarTrackerParams sonar_params;
  if (kind == hal::FrameKind::kPcl) {
    pcl_params = pcl_params_for(pcl_config_by_name(scenario));
    apply_pcl_settings(settings, pcl_params);
  } else {
    sonar_params = sonar_params_for(sonar_config_by_name(scenario));
    apply_sonar_settings(settings, sonar_params);
  }
  const std::uint64_t budget_ns = budget_ns_from_us(o.filter.budget_us);
  const std::filesystem::path dir(o.out);
  std::filesystem::create_directories(dir);
  const std::string filter(kind == hal::FrameKind::kPcl ? kPclFilterName : kSonarFilterName);
  OtherKindResult r = kind == hal::FrameKind::kPcl
                          ? replay_pcl(std::move(bytes), scenario, pcl_params, budget_ns, dir, truth)
                          : replay_sonar(std::move(bytes), scenario, sonar_params, budget_ns, dir, truth);
  const StepTiming timing = summarise_step_times(r.step_ns, budget_ns);
  const std::string sensor_scenario = r.entry["sensor"]["name"].get<std::string>();

  nlohmann::json entry = r.entry;
  entry["kind"] = kind_name;
  entry["filter"] = filter;
  entry["source"] = source;
  entry["sensor_scenario"] = sensor_scenario;
  entry["frames"] = r.stats.frames;
  entry["steps"] = r.stats.steps;
  entry["frames_not_ok"] = r.frames_not_ok;
  entry["status_counts"] = status_counts_json(r.stats);
  entry["step_ns"] = step_ns_json(timing);
  entry["tracks_csv"] = r.tracks_csv.string();
  entry["scored"] = truth != nullptr;
  entry["truth"] = o.truth;
  merge_summary_file(dir / "summary.json", "replay", filter, entry);

  std::printf("replay %s: %s stream, %s tracker (%s) with the sensor parameters of %s%s\n", source.c_str(),
              kind_name.c_str(), kind == hal::FrameKind::kPcl ? "PCL" : "sonar", filter.c_str(),
              sensor_scenario.c_str(),
              o.scenario.empty() ? " (the default; --scenario chooses another)" : "");
  if (!settings.empty()) {
    std::printf("  parameters set by --config/--set:");
    for (const Setting& st : settings) std::printf(" %s=%g", st.key.c_str(), st.value);
    std::printf("\n");
  }
  print_status_counts(r.stats);
  std::printf("%s\n", r.counts.c_str());
  print_timing(stdout, "replay " + source, timing);
  if (truth != nullptr) {
    std::printf("scored against %s: %s\n", o.truth.c_str(), r.scored.c_str());
  } else {
    std::printf("not scored (no --truth). ");
  }
  std::printf("wrote %s, %s\n", r.tracks_csv.c_str(), (dir / "summary.json").c_str());
  return 0;
}

/// The truth CSV at `path`, which must be of the stream's kind (told by its
/// columns, csv/sensor_truth_csv.hpp): a radar truth cannot score PCL
/// tracks, nor a PCL truth sonar estimates.
ReplayTruth read_replay_truth(const std::string& path, hal::FrameKind stream_kind, const std::string& source) {
  ReplayTruth t;
  t.kind = truth_csv_kind(path);
  if (t.kind != stream_kind) {
    static const char* const kColumns[] = {"time_s,x_m,y_m", "rb_m,drb_mps", "c_mps"};
    const auto columns = [](hal::FrameKind k) {
      return std::string(k == hal::FrameKind::kRadar ? kColumns[0] : k == hal::FrameKind::kPcl ? kColumns[1] : kColumns[2]);
    };
    throw std::invalid_argument("--truth " + path + " is a " + sensor_kind_name(t.kind) + " truth (by its columns" +
                                (t.kind == hal::FrameKind::kRadar ? ", without " + columns(hal::FrameKind::kPcl) +
                                                                        " or " + columns(hal::FrameKind::kSonar)
                                                                  : std::string(" ") + columns(t.kind)) +
                                "); " + source + " holds " + sensor_kind_name(stream_kind) +
                                " frames: give the truth CSV `kestrel-sim generate` wrote beside that stream");
  }
  switch (t.kind) {
    case hal::FrameKind::kPcl:
      t.pcl = read_pcl_truth_csv(path);
      for (const PclTruthRow& r : t.pcl) t.times_s.push_back(r.truth.t_s);
      break;
    case hal::FrameKind::kSonar:
      t.sonar = read_sonar_truth_csv(path);
      for (const SonarTruthRow& r : t.sonar) t.times_s.push_back(r.truth.t_s);
      break;
    default:
      if (truth_csv_has_targets(path)) {
        t.radar_targets = read_targets_truth_csv(path);
        for (const TruthSample& r : t.radar_targets.front()) t.times_s.push_back(r.t_s);
      } else {
        t.radar = read_truth_csv(std::filesystem::path(path));
        for (const TruthSample& r : t.radar) t.times_s.push_back(r.t_s);
      }
      break;
  }
  return t;
}

/// A truth none of whose times is a frame time would score nothing: an
/// error naming both spans, not a run with every figure empty.
void check_truth_overlap(const ReplayTruth& truth, const std::vector<MeasurementFrame>& frames,
                         const std::string& truth_path, const std::string& source) {
  std::vector<double> frame_times;
  for (const MeasurementFrame& f : frames) frame_times.push_back(f.t_s);
  if (count_truth_times(frame_times, truth.times_s) > 0) return;
  const auto span = [](const std::vector<double>& t) {
    double lo = std::nan(""), hi = std::nan("");
    for (const double v : t) {
      if (!std::isfinite(v)) continue;
      lo = std::isfinite(lo) ? std::min(lo, v) : v;
      hi = std::isfinite(hi) ? std::max(hi, v) : v;
    }
    return std::isfinite(lo) ? format_number("%.6f", lo) + " .. " + format_number("%.6f", hi) + " s" : std::string("none");
  };
  throw std::invalid_argument("--truth " + truth_path + ": no frame of " + source +
                              " is at a time of the truth (to the microsecond): frames " + span(frame_times) +
                              ", truth " + span(truth.times_s) + " (" + std::to_string(truth.times_s.size()) +
                              " rows); nothing could be scored");
}

}  // namespace

int cmd_replay(const ReplayOptions& o) {
  if (int{!o.stream.empty()} + int{!o.csv.empty()} + int{!o.asterix.empty()} != 1) {
    throw std::invalid_argument("give exactly one of --stream, --csv and --asterix");
  }
  for (const char* gate : {"--board-gate", "--gate-d2"}) {
    if (o.ungated && std::find(o.filter.radar_only_given.begin(), o.filter.radar_only_given.end(), gate) !=
                         o.filter.radar_only_given.end()) {
      throw std::invalid_argument(std::string("--ungated and ") + gate + " contradict each other");
    }
  }
  // Read (file, syntax) now; whose keys they are is known with the stream's kind.
  const std::vector<Setting> settings = read_settings(o.filter.config, o.filter.sets);
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
  // One kind per stream: a mixed one would have its other frames refused
  // one by one, a run of half the data that looks like a result.
  const FrameKindCounts kinds = count_frame_kinds(frames);
  if (kinds.kinds() > 1) {
    throw std::runtime_error(source + ": mixes sensor kinds: " + kinds.describe() + " frames" +
                             (kinds.undecoded > 0 ? " (and " + std::to_string(kinds.undecoded) + " that did not decode)"
                                                  : std::string()) +
                             "; replay takes a stream of one kind");
  }
  const hal::FrameKind kind = kinds.pcl > 0     ? hal::FrameKind::kPcl
                              : kinds.sonar > 0 ? hal::FrameKind::kSonar
                                                : hal::FrameKind::kRadar;
  const std::optional<ReplayTruth> replay_truth =
      o.truth.empty() ? std::nullopt : std::optional<ReplayTruth>(read_replay_truth(o.truth, kind, source));
  const std::vector<TruthSample> truth = replay_truth ? replay_truth->radar : std::vector<TruthSample>{};
  if (frames.size() == skipped) {
    // Not malformed (a bad truth CSV above is still an error), but nothing
    // would be replayed: a script must not take it for a run. Stop before
    // writing files, so no empty summary replaces a real one.
    std::fprintf(stderr, "kestrel-sim: warning: %s held no frames%s, nothing to replay\n", source.c_str(),
                 skipped > 0 ? " that decode" : "");
    return kExitNoFrames;
  }

  if (kind != hal::FrameKind::kRadar) {
    if (!o.associator.empty()) {
      throw std::invalid_argument("--associator " + o.associator + ": " + source + " holds " +
                                  sensor_kind_name(kind) + " frames; the option picks the tracker of a radar stream");
    }
    if (replay_truth) check_truth_overlap(*replay_truth, frames, o.truth, source);
    return replay_other_kind(o, kind, std::move(bytes), frames.size() - skipped, source,
                             replay_truth ? &*replay_truth : nullptr, settings);
  }
  if (!o.scenario.empty()) {
    throw std::invalid_argument("--scenario " + o.scenario + ": " + source +
                                " holds radar frames, which the radar filters replay without a scenario (--scenario "
                                "chooses the sensor parameters of a PCL or sonar stream)");
  }
  check_filter_fits(o.filter, kind, source + ": its " + std::to_string(frames.size() - skipped) + " frames are radar frames");
  check_settings_kind(settings, kind, source + " holds radar frames");
  FilterChoice choice = o.filter;
  apply_filter_settings(choice, settings);
  if (replay_truth) check_truth_overlap(*replay_truth, frames, o.truth, source);
  const bool several_targets = replay_truth && !replay_truth->radar_targets.empty();
  if (several_targets || !o.associator.empty()) {
    // The tracker and scoring of `run` on a multi-target scenario
    // (run_multi.cpp), over this stream; a one-target truth is one target.
    const std::vector<std::string> refused = multi_target_replay_refuses(o);
    if (!refused.empty()) {
      const std::string why = several_targets ? "--truth " + o.truth + " holds " +
                                                    std::to_string(replay_truth->radar_targets.size()) +
                                                    " targets, scored by the multi-target tracker"
                                              : "--associator runs the multi-target tracker";
      throw std::invalid_argument(why + "; " + join_names(refused) +
                                  (refused.size() == 1 ? " does not apply to it" : " do not apply to it"));
    }
    std::vector<std::vector<TruthSample>> targets;
    if (several_targets) {
      targets = replay_truth->radar_targets;
    } else if (replay_truth) {
      targets.push_back(replay_truth->radar);
    }
    return replay_multi_target(o, choice, StreamInput(std::move(bytes), format), targets, source);
  }
  const FilterEntry& filter = find_filter(choice.filter);

  FilterOptions options = choice.options;
  // Gated as a board by default; --ungated or a board_gate setting say otherwise.
  if (o.ungated && choice.board_gate_set && options.board_gate) {
    throw std::invalid_argument("--ungated and the setting board_gate=true contradict each other");
  }
  if (o.ungated || !choice.board_gate_set) options.board_gate = !o.ungated;
  const std::uint64_t budget_ns = budget_ns_from_us(o.filter.budget_us);
  ScoringParams scoring;
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
