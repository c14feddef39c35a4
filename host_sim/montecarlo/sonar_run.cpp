// SPDX-License-Identifier: Apache-2.0
#include "montecarlo/sonar_run.hpp"

#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "kestrel/hal/frame_codec.hpp"
#include "kestrel/hal/frame_format.hpp"
#include "kestrel/hal/sonar_adapter.hpp"
#include "kestrel/host/board.hpp"
#include "pipeline/poll_frames.hpp"
#include "stream/stream_writer.hpp"

namespace kestrel::sim {

namespace {

/// UW-003 has four beacons: the tracker's channel table is sized for them.
constexpr int kSonarBeacons = 4;
using DoubleSonarTracker = SonarTracker<double, kSonarBeacons>;

}  // namespace

std::vector<std::uint8_t> encode_sonar_stream(const SonarScenarioRun& run) {
  std::vector<std::uint8_t> bytes;
  for (const SonarFrameRecord& f : run.frames) append_encoded(f.wire, bytes);
  return bytes;
}

SonarTrackerParams sonar_params_for(const SonarScenarioParams& scenario, const SonarTrackerParams& base) {
  if (scenario.beacons_m.size() > static_cast<std::size_t>(kSonarBeacons)) {
    throw std::invalid_argument("the UW runner is built for at most 4 beacons");
  }
  SonarTrackerParams p = base;
  p.beacon_count = static_cast<std::uint8_t>(scenario.beacons_m.size());
  for (std::size_t i = 0; i < scenario.beacons_m.size(); ++i) {
    for (std::size_t a = 0; a < 3; ++a) p.beacons_m[i][a] = scenario.beacons_m[i][a];
  }
  p.seabed_depth_m = scenario.seabed_depth_m;
  p.sigma_toa_s = scenario.sigma_toa_s;
  return p;
}

SonarRunOutput run_sonar(const SonarScenarioRun& run, const SonarTrackerParams& params, std::uint64_t budget_ns) {
  SonarRunOutput out = run_sonar_stream(encode_sonar_stream(run), params, budget_ns);
  if (out.frames.size() != run.frames.size()) throw std::runtime_error("sonar stream ended early");
  return out;
}

SonarRunOutput run_sonar_stream(std::vector<std::uint8_t> stream, const SonarTrackerParams& params,
                                std::uint64_t budget_ns) {
  using Report = DoubleSonarTracker::Report;
  using Sink = host::MemorySink<Report>;
  using Runner = hal::Runner<host::Feed, host::Clock, DoubleSonarTracker, hal::SonarAdapter, Sink>;

  auto tracker = std::make_unique<DoubleSonarTracker>(make_sonar_tracker<double, kSonarBeacons>(params));
  // Every poll that does not return kNoData consumes at least one byte.
  const std::size_t max_polls = stream.size() + 1;
  host::StreamFileFeed feed(std::move(stream));
  host::SteadyClock clock;
  Sink sink(max_polls);
  const hal::SonarAdapter adapter;
  auto runner = std::make_unique<Runner>(feed, clock, *tracker, adapter, sink, budget_ns);

  SonarRunOutput out;
  poll_frames(*runner, sink, max_polls, [&](const PolledFrame& polled) {
    SonarFrameOutcome f;
    f.status = polled.status;
    f.stepped = polled.stepped;
    f.step_ns = polled.step_ns;
    f.t_s = f.stepped ? static_cast<double>(runner->last_frame().t_us) * 1e-6 : std::nan("");
    if (f.stepped) {
      const SonarStepStats& st = tracker->last_step();
      f.initialised = st.initialised;
      f.predict_only = st.predict_only;
      f.present = st.present;
      f.fused = st.fused_mask;
      f.gated = st.gated_mask;
    }
    if (polled.end_report > polled.first_report) {
      const Report& r = sink.reports()[polled.first_report];
      f.reported = true;
      f.track_id = r.track_id;
      for (int i = 0; i < 7; ++i) {
        f.x[static_cast<std::size_t>(i)] = r.x(i);
        f.sd[static_cast<std::size_t>(i)] = std::sqrt(r.P(i, i));
      }
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) f.p_pos[static_cast<std::size_t>(3 * i + j)] = r.P(i, j);
      }
      f.nis = r.nis;
    }
    out.frames.push_back(f);
  });
  out.stats = runner->stats();
  return out;
}

}  // namespace kestrel::sim
