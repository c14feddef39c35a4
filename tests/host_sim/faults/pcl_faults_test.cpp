// SPDX-License-Identifier: Apache-2.0
// Faults injected into a passive-radar stream on the path a board receives
// it: pcl002 (seed 1: one drone among about 21 clutter candidates a frame,
// 120 frames at 0.5 s) -> wire bytes -> StreamFileFeed (frame assembler) ->
// PclAdapter -> the default PCL tracker (nearest neighbour, 5-of-6), inside
// hal::Runner (sim::run_pcl_stream). The radar and sonar counterparts are
// fault_injection_test.cpp and sonar_faults_test.cpp; the table is in
// docs/robustness.md. Each fault has its expected count of every status
// and of the drone tracks that replace the first one (only where a rule
// deletes it: a gap over max_predict_us, a clock taken by the resync rule),
// and every run is checked for:
//   - the drone held: the confirmed tracks that take the drone's detection
//     in 3 frames or more are the first one plus the documented restarts,
//     and the last of them takes it in at least 80 % of the last 20 frames
//     that carry it;
//   - no ghost from the fault: confirmed tracks that never take the
//     drone's detection (clutter that passed 5-of-6) are at most the clean
//     run's count.
#include <array>
#include <catch2/catch.hpp>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "host_sim/faults/wire_faults.hpp"
#include "montecarlo/pcl_run.hpp"

using namespace kestrel::sim;  // NOLINT(google-build-using-namespace)
using kestrel::Status;

namespace {

constexpr std::size_t kFaultAt = 60;  // frame index where each fault starts (t = 30 s)
constexpr std::int64_t kSecondUs = 1'000'000;

using namespace kestrel::test::faults;  // NOLINT(google-build-using-namespace): the stream builders
using Fault = WireFault;

std::vector<Fault> make_faults(const PclScenarioRun& run) {
  const std::size_t n = run.frames.size();
  std::vector<Fault> faults;
  const auto each = [&](auto&& per_frame) { return each_frame(run.frames, per_frame); };

  faults.push_back({"none", send_all(run.frames), {}, n, 0});

  // Dropout burst: 6 frames missing (a 3.5 s gap, under max_predict_us = 10 s).
  faults.push_back({"dropout burst, 3 s", drop_frames(run.frames, kFaultAt, 6), {}, n - 6, 0});

  // Sensor stall: 24 frames missing (a 12.5 s gap, over max_predict_us):
  // every track is deleted as stale and the drone's detections restart it.
  faults.push_back({"stall, 12 s", drop_frames(run.frames, kFaultAt, 24), {}, n - 24, 1});

  // Duplicated frames: 5 frames each sent twice (same time, same candidates).
  faults.push_back({"duplicated frames x 5", repeat_frames(run.frames, kFaultAt, 5), {}, n + 5, 0});

  // Sensor reset: from frame 80 the clock is 30 s behind. The first
  // resync_frames - 1 = 2 frames of the new clock are refused, the third
  // is taken (resync: every track deleted) and the drone's track restarts.
  faults.push_back({"sensor reset, clock back 30 s", shift_times(run.frames, 80, 0, -30 * kSecondUs),
                    {{Status::kTimeWentBackwards, 2}}, n, 1});

  // One corrupted timestamp a day ahead (CRC valid): refused, nothing else.
  faults.push_back({"one frame 1 day ahead", shift_times(run.frames, kFaultAt, 1, 86400 * kSecondUs),
                    {{Status::kTimeJumpedForward, 1}}, n, 0});

  // Over capacity: 3 frames padded to 40 candidates (copies of their own
  // clutter, each moved 300 m in range) where the scan holds 32: the
  // adapter keeps 32 by its rule and the frame reports kTooManyCandidates.
  faults.push_back({"3 frames over capacity (40 candidates)",
                    each([&](std::size_t k, kestrel::hal::Frame f, Bytes& out) {
                      if (k >= kFaultAt && k < kFaultAt + 3) {
                        const std::size_t have = f.count;
                        for (std::size_t i = have; i < 40; ++i) {
                          f.pcl[i] = f.pcl[(i - have) % have];
                          f.pcl[i].bistatic_range_mm += 300'000u;
                        }
                        f.count = 40;
                      }
                      append(out, encode_frame(f));
                    }),
                    {{Status::kTooManyCandidates, 3}}, n, 0});

  // Corrupted bytes: one payload byte flipped in 3 frames (CRC fails), and
  // 7 bytes of line noise before another frame: the assembler reports the
  // noise once (kBadMagic, one more Runner frame) and resyncs.
  faults.push_back({"corrupted bytes in 4 frames", corrupt_frames(run.frames, {kFaultAt, kFaultAt + 10, kFaultAt + 11}, kFaultAt + 20),
                    {{Status::kBadCrc, 3}, {Status::kBadMagic, 1}}, n + 1, 0});
  return faults;
}

struct Observed {
  std::map<Status, std::size_t> not_ok;
  std::size_t frames = 0;
  std::vector<std::uint32_t> drone_tracks;  ///< Took the drone's detection in >= 3 frames, in order of first take.
  std::size_t false_tracks = 0;             ///< Confirmed, never took the drone's detection.
  double end_rate = 0.0;  ///< Last drone track: share of the last 20 frames carrying the detection that it took.
};

Observed observe(const PclRunOutput& out) {
  Observed o;
  o.frames = out.frames.size();
  std::map<std::uint32_t, std::size_t> takes;
  std::vector<std::uint32_t> first_take_order;
  std::set<std::uint32_t> confirmed;
  for (const PclFrameOutcome& f : out.frames) {
    if (f.status != Status::kOk) ++o.not_ok[f.status];
    for (const PclTrackRow& r : f.tracks) {
      confirmed.insert(r.id);
      if (r.associated && f.target_index >= 0 && r.frame_index == f.target_index) {
        if (takes[r.id]++ == 0) first_take_order.push_back(r.id);
      }
    }
  }
  for (const auto id : first_take_order) {
    if (takes[id] >= 3) o.drone_tracks.push_back(id);
  }
  for (const auto id : confirmed) o.false_tracks += takes.count(id) == 0 ? 1u : 0u;
  if (!o.drone_tracks.empty()) {
    const std::uint32_t last = o.drone_tracks.back();
    std::size_t carried = 0;
    std::size_t taken = 0;
    for (std::size_t k = out.frames.size(); k-- > 0 && carried < 20;) {
      const PclFrameOutcome& f = out.frames[k];
      if (!f.stepped || !f.target_in_scan) continue;
      ++carried;
      for (const PclTrackRow& r : f.tracks) taken += r.id == last && r.associated && r.frame_index == f.target_index;
    }
    o.end_rate = carried > 0 ? static_cast<double>(taken) / static_cast<double>(carried) : 0.0;
  }
  return o;
}

}  // namespace

SCENARIO("injected PCL stream faults give their status counts, hold the drone and add no ghost",
         "[host_sim][faults][pcl]") {
  const PclScenarioParams config = pcl002_config();
  const PclScenarioRun run = generate_pcl(config, 1);
  const kestrel::PclTrackerParams params = pcl_params_for(config);
  std::vector<Fault> faults = make_faults(run);
  // The scenario itself sends frames over the scan's 32 candidates (Poisson
  // clutter plus ridge): each reports kTooManyCandidates in every run. They
  // lie outside every fault's window (frames 60-83 and the reset's refused
  // frames 80-81), so each fault expects them on top of its own.
  std::size_t scenario_over_capacity = 0;
  for (std::size_t k = 0; k < run.frames.size(); ++k) {
    if (run.frames[k].wire.count <= config.scan_capacity) continue;
    INFO("frame " << k << " carries " << run.frames[k].wire.count << " candidates");
    REQUIRE((k < kFaultAt || k >= kFaultAt + 24));
    ++scenario_over_capacity;
  }
  for (Fault& fault : faults) {
    if (scenario_over_capacity > 0) fault.not_ok[Status::kTooManyCandidates] += scenario_over_capacity;
  }
  const auto run_stream = [&](const Bytes& b) {
    return observe(run_pcl_stream(b, run.frames, config, params, TrackerPolicies{}, 1'000'000'000));
  };
  const Observed clean = run_stream(faults.front().stream);
  REQUIRE(clean.drone_tracks.size() == 1);
  for (const Fault& fault : faults) {
    INFO("fault: " << fault.name);
    const Observed o = run_stream(fault.stream);
    const std::string seen = describe(o.not_ok);
    INFO("statuses other than kOk: " << seen << "drone tracks " << o.drone_tracks.size() << ", false tracks "
                                     << o.false_tracks << " (clean run " << clean.false_tracks
                                     << "), last drone track took " << o.end_rate
                                     << " of the last 20 detections (clean run " << clean.end_rate << ")");
    CHECK(o.frames == fault.frames);
    CHECK(o.not_ok == fault.not_ok);
    CHECK(o.drone_tracks.size() == 1 + fault.new_tracks);
    CHECK(o.end_rate >= 0.8);
    CHECK(o.false_tracks <= clean.false_tracks);
  }
}
