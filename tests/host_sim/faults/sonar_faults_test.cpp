// SPDX-License-Identifier: Apache-2.0
// Faults injected into a sonar stream on the path a board receives it:
// uw003 (seed 1, 50 frames at 1 s) -> wire bytes -> StreamFileFeed (frame
// assembler) -> SonarAdapter -> SonarTracker::step, inside hal::Runner
// (sim::run_sonar_stream). The radar counterpart is fault_injection_test.cpp;
// the table of both is in docs/robustness.md. Each fault has its expected
// count of every status the Runner returns and of the tracks that replace
// the first one (only where a documented rule restarts it: a gap over
// max_predict_us, a clock the resync rule takes), and every run is checked
// for:
//   - every frame the tracker accepts publishes one report, whose track id
//     is the first track's or that of a documented restart;
//   - recovery: the last estimate is the clean run's to within three times
//     the clean run's position sigma (sqrt of the trace of its position
//     covariance), and every estimate's covariance is positive definite.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "host_sim/faults/wire_faults.hpp"
#include "montecarlo/sonar_run.hpp"

using namespace kestrel::sim;  // NOLINT(google-build-using-namespace)
using kestrel::Status;

namespace {

constexpr std::size_t kFaultAt = 20;  // frame index where each fault starts (t = 20 s)
constexpr std::int64_t kSecondUs = 1'000'000;

using namespace kestrel::test::faults;  // NOLINT(google-build-using-namespace): the stream builders
using Fault = WireFault;

std::vector<Fault> make_faults(const SonarScenarioRun& run) {
  const std::size_t n = run.frames.size();
  std::vector<Fault> faults;
  const auto each = [&](auto&& per_frame) { return each_frame(run.frames, per_frame); };

  faults.push_back({"none", send_all(run.frames), {}, n, 0});

  // Dropout burst: 5 frames missing (a 6 s gap, under max_predict_us = 60 s).
  faults.push_back({"dropout burst, 5 s", drop_frames(run.frames, kFaultAt, 5), {}, n - 5, 0});

  // Outlier burst: in 4 frames two arrivals each 25 ms late (37 m at
  // 1500 m/s, over 5 sigma of the 3 ms TOA noise): the per-channel gate drops
  // them and the track fuses the rest.
  faults.push_back({"outlier burst, 4 frames x 2 arrivals 25 ms late",
                    each([&](std::size_t k, kestrel::hal::Frame f, Bytes& out) {
                      if (k >= kFaultAt && k < kFaultAt + 4) {
                        for (std::size_t i = 0; i < 2 && i < f.count; ++i) {
                          f.sonar[(k + 3 * i) % f.count].time_of_flight_ns += 25'000'000u;
                        }
                      }
                      append(out, encode_frame(f));
                    }),
                    {}, n, 0});

  // Sensor stall: the sonar is silent for 70 s from frame 20 (its clock
  // runs on): over max_predict_us, the track restarts from a fresh fix.
  faults.push_back({"stall, 70 s", shift_times(run.frames, kFaultAt, 0, 70 * kSecondUs), {}, n, 1});

  // Duplicated frames: 5 frames each sent twice (same time, same arrivals).
  faults.push_back({"duplicated frames x 5", repeat_frames(run.frames, kFaultAt, 5), {}, n + 5, 0});

  // Sensor reset: from frame 30 the clock is 30 s behind. The first
  // resync_frames - 1 = 2 frames of the new clock are refused, the third
  // is taken (resync) and the track restarts from its fix.
  faults.push_back({"sensor reset, clock back 30 s", shift_times(run.frames, 30, 0, -30 * kSecondUs),
                    {{Status::kTimeWentBackwards, 2}}, n, 1});

  // One corrupted timestamp a day ahead (CRC valid): refused, nothing else.
  faults.push_back({"one frame 1 day ahead", shift_times(run.frames, kFaultAt, 1, 86400 * kSecondUs),
                    {{Status::kTimeJumpedForward, 1}}, n, 0});

  // Over capacity: 3 frames carry a ninth arrival (a copy of the first)
  // where the tracker's scan holds 8 (4 beacons x 2 paths): the first 8
  // are tracked, the frame reports kTooManyCandidates.
  faults.push_back({"3 frames over capacity (9 arrivals)", each([&](std::size_t k, kestrel::hal::Frame f, Bytes& out) {
                      if (k >= kFaultAt && k < kFaultAt + 3 && f.count == 8) {
                        f.sonar[8] = f.sonar[0];
                        f.count = 9;
                      }
                      append(out, encode_frame(f));
                    }),
                    {{Status::kTooManyCandidates, 3}}, n, 0});

  // An arrival labelled with a beacon the installation does not have:
  // the frame is refused (kOutOfRange), nothing else changes.
  faults.push_back({"arrival from an unknown beacon", each([&](std::size_t k, kestrel::hal::Frame f, Bytes& out) {
                      if (k == kFaultAt) f.sonar[0].beacon_id = 6;
                      append(out, encode_frame(f));
                    }),
                    {{Status::kOutOfRange, 1}}, n, 0});

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
  std::size_t accepted_without_report = 0;
  std::vector<std::uint32_t> track_ids;  ///< In order of first appearance.
  bool all_covariances_pd = true;
  std::array<double, 3> final_position{};
  double final_position_sigma = 0.0;
};

Observed observe(const SonarRunOutput& out) {
  Observed o;
  o.frames = out.frames.size();
  for (const SonarFrameOutcome& f : out.frames) {
    if (f.status != Status::kOk) ++o.not_ok[f.status];
    const bool accepted = f.stepped && (f.status == Status::kOk || f.status == Status::kTooManyCandidates);
    if (accepted && !f.reported) ++o.accepted_without_report;
    if (!f.reported) continue;
    if (o.track_ids.empty() || o.track_ids.back() != f.track_id) o.track_ids.push_back(f.track_id);
    // The position block: its three leading minors positive.
    const auto& p = f.p_pos;
    const double m2 = p[0] * p[4] - p[1] * p[3];
    const double m3 = p[0] * (p[4] * p[8] - p[5] * p[7]) - p[1] * (p[3] * p[8] - p[5] * p[6]) +
                      p[2] * (p[3] * p[7] - p[4] * p[6]);
    o.all_covariances_pd = o.all_covariances_pd && p[0] > 0.0 && m2 > 0.0 && m3 > 0.0;
    o.final_position = {f.x[0], f.x[1], f.x[2]};
    o.final_position_sigma = std::sqrt(p[0] + p[4] + p[8]);
  }
  return o;
}

}  // namespace

SCENARIO("injected sonar stream faults give their status counts, keep or restart the track by rule, and recover",
         "[host_sim][faults][sonar]") {
  const SonarScenarioParams config = uw003_config();
  const SonarScenarioRun run = generate_sonar(config, 1);
  const kestrel::SonarTrackerParams params = sonar_params_for(config);
  const std::vector<Fault> faults = make_faults(run);
  const Observed clean = observe(run_sonar_stream(faults.front().stream, params, 1'000'000'000));
  REQUIRE(clean.track_ids.size() == 1);
  for (const Fault& fault : faults) {
    INFO("fault: " << fault.name);
    const Observed o = observe(run_sonar_stream(fault.stream, params, 1'000'000'000));
    const std::string seen = describe(o.not_ok);
    const double moved = std::hypot(o.final_position[0] - clean.final_position[0],
                                    o.final_position[1] - clean.final_position[1],
                                    o.final_position[2] - clean.final_position[2]);
    INFO("statuses other than kOk: " << seen << "tracks " << o.track_ids.size() << ", final estimate " << moved
                                     << " m from the clean run's (its position sigma " << clean.final_position_sigma
                                     << " m)");
    CHECK(o.frames == fault.frames);
    CHECK(o.not_ok == fault.not_ok);
    CHECK(o.accepted_without_report == 0);
    CHECK(o.track_ids.size() == 1 + fault.new_tracks);
    CHECK(std::set<std::uint32_t>(o.track_ids.begin(), o.track_ids.end()).size() == o.track_ids.size());
    CHECK(o.all_covariances_pd);
    CHECK(moved <= 3.0 * clean.final_position_sigma);
  }
}
