// SPDX-License-Identifier: Apache-2.0
#include "montecarlo/pcl_run.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "kestrel/association/global_nearest_neighbour.hpp"
#include "kestrel/hal/frame_codec.hpp"
#include "kestrel/hal/frame_format.hpp"
#include "kestrel/hal/pcl_adapter.hpp"
#include "kestrel/host/board.hpp"
#include "pipeline/poll_frames.hpp"
#include "stream/stream_writer.hpp"

namespace kestrel::sim {

std::vector<std::uint8_t> encode_pcl_stream(const PclScenarioRun& run) {
  std::vector<std::uint8_t> bytes;
  for (const PclFrameRecord& f : run.frames) append_encoded(f.wire, bytes);
  return bytes;
}

namespace {

/// Which candidate of a frame is the target's, looked up by the frame's
/// content (count and every candidate), so that a stream with frames
/// dropped, repeated or re-timed still finds it; -1 when unknown.
class TargetIndexByContent {
 public:
  explicit TargetIndexByContent(const std::vector<PclFrameRecord>& frames) {
    for (const PclFrameRecord& f : frames) index_.emplace(key(f.wire), f.target_index);
  }
  int operator()(const hal::Frame& frame) const {
    const auto it = index_.find(key(frame));
    return it == index_.end() ? -1 : it->second;
  }

 private:
  static std::vector<std::int64_t> key(const hal::Frame& f) {
    std::vector<std::int64_t> k{static_cast<std::int64_t>(f.count)};
    for (std::size_t i = 0; i < f.count && i < hal::kMaxPclCandidates; ++i) {
      k.push_back(f.pcl[i].bistatic_range_mm);
      k.push_back(f.pcl[i].doppler_mhz);
      k.push_back(f.pcl[i].snr_cdb);
    }
    return k;
  }
  std::map<std::vector<std::int64_t>, int> index_;
};

template <std::size_t kTracks, std::size_t kCandidates, template <class, std::size_t, std::size_t> class Associator,
          template <class> class Manager>
PclRunOutput run_typed(std::vector<std::uint8_t> stream, const PclTargetLocator& target_index_of,
                       const PclTrackerParams& params, std::uint64_t budget_ns) {
  using Tracker = PclTracker<PclKf<double>, kTracks, kCandidates, Associator, Manager>;
  using Report = typename Tracker::Report;
  using Adapter = hal::PclAdapter<Tracker>;
  using Sink = host::MemorySink<Report>;
  using Runner = hal::Runner<host::Feed, host::Clock, Tracker, Adapter, Sink>;

  // The tracker holds the whole track table: keep it off the stack.
  auto tracker =
      std::make_unique<Tracker>(make_pcl_tracker<double, kTracks, kCandidates, Associator, Manager>(params));
  // Every poll that does not return kNoData consumes at least one byte.
  const std::size_t max_polls = stream.size() + 1;
  // Room for every track in every frame: count the stream's frames (a sink
  // too small drops reports).
  std::size_t frames_in_stream = 0;
  {
    host::StreamFileFeed counter(stream);
    hal::Frame scratch{};
    while (counter.poll(scratch) != Status::kNoData && frames_in_stream < max_polls) ++frames_in_stream;
  }
  host::StreamFileFeed feed(std::move(stream));
  host::SteadyClock clock;
  Sink sink(std::max<std::size_t>(frames_in_stream, 1) * kTracks);
  hal::PclAdapterParams adapter_config;
  adapter_config.carrier_hz = params.carrier_hz;
  const Adapter adapter(tracker.get(), adapter_config);
  auto runner = std::make_unique<Runner>(feed, clock, *tracker, adapter, sink, budget_ns);

  PclRunOutput out;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<PclTrackRow> previous;
  double previous_t_s = 0.0;
  poll_frames(*runner, sink, max_polls, [&](const PolledFrame& polled) {
    PclFrameOutcome f;
    f.status = polled.status;
    f.stepped = polled.stepped;
    f.step_ns = polled.step_ns;
    const double t_s = f.stepped ? static_cast<double>(runner->last_frame().t_us) * 1e-6 : previous_t_s;
    f.t_s = f.stepped ? t_s : nan;
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
      f.target_index = target_index_of(frame);
      std::size_t j = 0;
      for (std::size_t i = 0; i < scan.count; ++i) {
        while (j < frame.count && !(hal::to_measurement(frame.pcl[j], adapter.lambda_m()) == scan.z[i])) ++j;
        wire_index.push_back(j < frame.count ? static_cast<int>(j) : -1);
        if (static_cast<int>(j) == f.target_index) f.target_in_scan = true;
        ++j;
      }
    }
    const auto reports = sink.reports();
    for (std::size_t i = polled.first_report; i < polled.end_report; ++i) {
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
  });
  out.stats = runner->stats();
  return out;
}

}  // namespace

std::size_t pcl_track_capacity(std::size_t scan_capacity) {
  if (scan_capacity == 32) return kPclMaxTracks;
  if (scan_capacity == 64) return 2 * kPclMaxTracks;
  throw std::invalid_argument("PCL scan capacity must be 32 or 64, not " + std::to_string(scan_capacity));
}

PclTrackerParams pcl_params_for(const PclScenarioParams& scenario) {
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
PclRunOutput run_with_manager(std::vector<std::uint8_t> stream, const PclTargetLocator& reference,
                              const PclTrackerParams& params, ManagerChoice manager, std::uint64_t budget_ns) {
  if (manager == ManagerChoice::kScore)
    return run_typed<kTracks, kCandidates, Associator, SequentialLlr>(std::move(stream), reference, params, budget_ns);
  return run_typed<kTracks, kCandidates, Associator, MOfN>(std::move(stream), reference, params, budget_ns);
}

template <std::size_t kTracks, std::size_t kCandidates>
PclRunOutput run_composed(std::vector<std::uint8_t> stream, const PclTargetLocator& reference,
                          const PclTrackerParams& params, const TrackerPolicies& policies, std::uint64_t budget_ns) {
  switch (policies.associator) {
    case AssociatorChoice::kGlobalNearestNeighbour:
      return run_with_manager<kTracks, kCandidates, GlobalNearestNeighbour>(std::move(stream), reference, params,
                                                                            policies.manager, budget_ns);
    case AssociatorChoice::kPda:
      return run_with_manager<kTracks, kCandidates, ProbabilisticDataAssociation>(std::move(stream), reference, params,
                                                                                   policies.manager, budget_ns);
    case AssociatorChoice::kNearestNeighbour:
      break;
  }
  return run_with_manager<kTracks, kCandidates, NearestNeighbour>(std::move(stream), reference, params,
                                                                  policies.manager, budget_ns);
}

}  // namespace

PclRunOutput run_pcl_stream(std::vector<std::uint8_t> stream, const std::vector<PclFrameRecord>& reference,
                            const PclScenarioParams& scenario, const PclTrackerParams& params,
                            const TrackerPolicies& policies, std::uint64_t budget_ns) {
  const TargetIndexByContent by_content(reference);
  return run_pcl_stream(std::move(stream), PclTargetLocator(std::cref(by_content)), scenario, params, policies,
                        budget_ns);
}

PclRunOutput run_pcl_stream(std::vector<std::uint8_t> stream, const PclTargetLocator& reference,
                            const PclScenarioParams& scenario, const PclTrackerParams& params,
                            const TrackerPolicies& policies, std::uint64_t budget_ns) {
  if (scenario.scan_capacity == 32) {
    return run_composed<kPclMaxTracks, 32>(std::move(stream), reference, params, policies, budget_ns);
  }
  if (scenario.scan_capacity == 64) {
    return run_composed<2 * kPclMaxTracks, 64>(std::move(stream), reference, params, policies, budget_ns);
  }
  (void)pcl_track_capacity(scenario.scan_capacity);  // throws with the message
  return {};
}

PclRunOutput run_pcl(const PclScenarioRun& run, const PclScenarioParams& scenario, const PclTrackerParams& params,
                     const TrackerPolicies& policies, std::uint64_t budget_ns) {
  PclRunOutput out = run_pcl_stream(encode_pcl_stream(run), run.frames, scenario, params, policies, budget_ns);
  if (out.frames.size() != run.frames.size()) throw std::runtime_error("PCL stream ended early");
  return out;
}

}  // namespace kestrel::sim
