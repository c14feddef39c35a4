#include "montecarlo/pcl_run.hpp"

#include <array>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "kestrel/association/global_nearest_neighbour.hpp"
#include "kestrel/hal/frame_codec.hpp"
#include "kestrel/hal/frame_format.hpp"
#include "kestrel/hal/pcl_adapter.hpp"
#include "kestrel/host/board.hpp"

namespace kestrel::sim {

namespace {

std::vector<std::uint8_t> encode_pcl_stream(const PclScenarioRun& run) {
  std::vector<std::uint8_t> bytes;
  std::array<std::uint8_t, hal::wire::kMaxEncodedFrameBytes> buffer{};
  for (const PclFrameRecord& f : run.frames) {
    std::size_t written = 0;
    const Status s = hal::encode(f.wire, buffer, written);
    if (s != Status::kOk) throw std::runtime_error(std::string("cannot encode a PCL frame: ") + to_string(s));
    bytes.insert(bytes.end(), buffer.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(written));
  }
  return bytes;
}

template <std::size_t kTracks, std::size_t kCandidates, template <class, std::size_t, std::size_t> class Associator,
          template <class> class Manager>
PclRunOutput run_typed(const PclScenarioRun& run, const PclTrackerParams& params, std::uint64_t budget_ns) {
  using Tracker = PclTracker<PclKf<double>, kTracks, kCandidates, Associator, Manager>;
  using Report = typename Tracker::Report;
  using Adapter = hal::PclAdapter<Tracker>;
  using Sink = host::MemorySink<Report>;
  using Runner = hal::Runner<host::Feed, host::Clock, Tracker, Adapter, Sink>;

  // The tracker holds the whole track table: keep it off the stack.
  auto tracker =
      std::make_unique<Tracker>(make_pcl_tracker<double, kTracks, kCandidates, Associator, Manager>(params));
  host::StreamFileFeed feed(encode_pcl_stream(run));
  host::SteadyClock clock;
  Sink sink(run.frames.size() * kTracks);
  hal::PclAdapterConfig adapter_config;
  adapter_config.carrier_hz = params.carrier_hz;
  const Adapter adapter(tracker.get(), adapter_config);
  auto runner = std::make_unique<Runner>(feed, clock, *tracker, adapter, sink, budget_ns);

  PclRunOutput out;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<PclTrackRow> previous;
  double previous_t_s = 0.0;
  for (std::size_t k = 0; k < run.frames.size(); ++k) {
    const std::size_t first = sink.size();
    const std::uint32_t steps_before = runner->stats().steps;
    PclFrameOutcome f;
    f.status = runner->poll_once();
    if (f.status == Status::kNoData) throw std::runtime_error("PCL stream ended early");
    f.stepped = runner->stats().steps != steps_before;
    f.step_ns = f.stepped ? runner->stats().last_cycles : 0;
    const double t_s = static_cast<double>(run.frames[k].wire.t_us) * 1e-6;
    // Scan entry -> wire index: the adapter keeps candidates in frame order,
    // so walk both lists (exact compare: the same conversion, bit for bit).
    std::vector<int> wire_index;
    if (f.stepped) {
      const hal::Frame& frame = runner->last_frame();
      const auto& scan = runner->last_scan();
      f.scan_count = scan.count;
      f.refused_starts = tracker->last_step().refused;
      f.dropped_starts = tracker->last_step().dropped;
      f.tracks_in_table = tracker->tracks().size();
      std::size_t j = 0;
      for (std::size_t i = 0; i < scan.count; ++i) {
        while (j < frame.count && !(hal::to_measurement(frame.pcl[j], adapter.lambda_m()) == scan.z[i])) ++j;
        wire_index.push_back(j < frame.count ? static_cast<int>(j) : -1);
        if (static_cast<int>(j) == run.frames[k].target_index) f.target_in_scan = true;
        ++j;
      }
    }
    const auto reports = sink.reports();
    for (std::size_t i = first; i < sink.size(); ++i) {
      const Report& r = reports[i];
      PclTrackRow row;
      row.id = r.track_id;
      row.associated = r.associated;
      row.frame_index = r.associated && r.measurement_index >= 0 &&
                                static_cast<std::size_t>(r.measurement_index) < wire_index.size()
                            ? wire_index[static_cast<std::size_t>(r.measurement_index)]
                            : -1;
      row.rb_m = r.x(0);
      row.drb_mps = r.x(1);
      row.p_rr = r.P(0, 0);
      row.p_rd = r.P(0, 1);
      row.p_dd = r.P(1, 1);
      row.nis = r.associated ? r.nis : nan;
      row.test_ratio = r.test_ratio;
      row.age = r.age;
      row.hits = r.hits;
      row.misses = r.misses;
      for (const PclTrackRow& p : previous) {
        if (p.id != row.id) continue;
        row.has_prediction = true;
        row.pred_rb_m = p.rb_m + (t_s - previous_t_s) * p.drb_mps;
        row.pred_drb_mps = p.drb_mps;
      }
      f.tracks.push_back(row);
    }
    if (f.stepped) {
      previous = f.tracks;
      previous_t_s = t_s;
    }
    out.frames.push_back(std::move(f));
  }
  out.stats = runner->stats();
  return out;
}

}  // namespace

std::size_t pcl_track_capacity(std::size_t scan_capacity) {
  if (scan_capacity == 32) return kPclMaxTracks;
  if (scan_capacity == 64) return 2 * kPclMaxTracks;
  throw std::invalid_argument("PCL scan capacity must be 32 or 64, not " + std::to_string(scan_capacity));
}

PclTrackerParams pcl_params_for(const PclScenarioConfig& scenario) {
  PclTrackerParams p;
  p.carrier_hz = scenario.carrier_hz;
  p.sigma_rb_m = scenario.sigma_rb_m;
  p.sigma_doppler_hz = scenario.sigma_fd_hz;
  // Clutter is uniform over Rb x fD; the tracker measures dRb = -lambda fD.
  const double volume = scenario.clutter_rb_max_m * 2.0 * scenario.clutter_fd_max_hz * pcl_lambda_m(scenario);
  p.detection_probability = scenario.pd;
  p.clutter_density = scenario.clutter_mean / volume;
  return p;
}

namespace {

template <std::size_t kTracks, std::size_t kCandidates, template <class, std::size_t, std::size_t> class Associator>
PclRunOutput run_with_manager(const PclScenarioRun& run, const PclTrackerParams& params, ManagerChoice manager,
                              std::uint64_t budget_ns) {
  if (manager == ManagerChoice::kScore)
    return run_typed<kTracks, kCandidates, Associator, SequentialLlr>(run, params, budget_ns);
  return run_typed<kTracks, kCandidates, Associator, MOfN>(run, params, budget_ns);
}

template <std::size_t kTracks, std::size_t kCandidates>
PclRunOutput run_composed(const PclScenarioRun& run, const PclTrackerParams& params, const TrackerPolicies& policies,
                          std::uint64_t budget_ns) {
  switch (policies.associator) {
    case AssociatorChoice::kGlobalNearestNeighbour:
      return run_with_manager<kTracks, kCandidates, GlobalNearestNeighbour>(run, params, policies.manager, budget_ns);
    case AssociatorChoice::kPda:
      return run_with_manager<kTracks, kCandidates, ProbabilisticDataAssociation>(run, params, policies.manager,
                                                                                   budget_ns);
    case AssociatorChoice::kNearestNeighbour:
      break;
  }
  return run_with_manager<kTracks, kCandidates, NearestNeighbour>(run, params, policies.manager, budget_ns);
}

}  // namespace

PclRunOutput run_pcl(const PclScenarioRun& run, const PclScenarioConfig& scenario, const PclTrackerParams& params,
                     const TrackerPolicies& policies, std::uint64_t budget_ns) {
  if (scenario.scan_capacity == 32) return run_composed<kPclMaxTracks, 32>(run, params, policies, budget_ns);
  if (scenario.scan_capacity == 64) return run_composed<2 * kPclMaxTracks, 64>(run, params, policies, budget_ns);
  (void)pcl_track_capacity(scenario.scan_capacity);  // throws with the message
  return {};
}

}  // namespace kestrel::sim
