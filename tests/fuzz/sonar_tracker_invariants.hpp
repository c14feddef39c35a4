// SPDX-License-Identifier: Apache-2.0
// The sonar (TOA) tracker driven by arbitrary bytes, for
// libFuzzer (sonar_tracker_fuzz.cpp) and for the regression test that
// replays the corpus and a seeded batch of inputs under the normal build
// (tests/core/tracking/tracker_fuzz_regression_test.cpp).
//
// The bytes are read as a sequence of wire sonar frames (hal::Frame), each
// converted by the board adapter (hal::SonarAdapter) and stepped by the
// UW-003 tracker (four beacons, geometry from hal::SonarAdapterParams's defaults)
// in double and float (the scalars sonar_tracker.hpp is built for).
// Per frame, one op byte: bits 0-1 choose the time step (fuzz_bytes.hpp:
// the next 1 s ping; a signed step of up to +-32 s; any int64 time; a gap of
// up to 49 days), bits 2-5 the arrival count (0-15, over the scan capacity
// of 8 on purpose), bits 6-7 the beacon the target's arrivals start at.
// Per arrival i, one byte b:
//   - bit 0 clear: the target's arrival on beacon (start + i) % 4, direct
//     for i < 4 and reflected after, so a frame of 4-8 such arrivals gives a
//     fix; noise of 0.2 ms per step from bits 1-5 (+-3.1 ms, sigma 3 ms),
//     and bits 6-7 = 11 make it 40 ms late (an outlier the gate must drop);
//   - bit 0 set: raw u32 time of flight (ns); beacon from bits 4-6 (4-7 are
//     not in the table), or a raw u8 when bit 7 is set; path code from bits
//     1-3: 0-5 direct or reflected by parity, 6-7 not a path (the adapter
//     refuses the frame).
// After every frame:
//   - the adapter refused (kMalformedFrame) exactly the frames whose kept
//     arrivals carry a path code that is not a path, else kept min(count, 8);
//   - a stepped frame that the tracker refuses reports nothing and moves
//     only the refused status's counter; refused for its content or time
//     (kMalformedFrame, kOutOfRange, kTimeWentBackwards,
//     kTimeJumpedForward), it leaves the state and filter diagnostics as
//     they were; refused because no track could start or hold (a fix's or
//     a filter's status), it leaves no track held; an accepted one reports
//     once, at the frame time;
//   - every report and the held state are finite with a positive definite
//     covariance.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <span>

#include "fuzz_bytes.hpp"
#include "kestrel/hal/frame.hpp"
#include "kestrel/hal/sonar_adapter.hpp"
#include "kestrel/math/finite.hpp"
#include "kestrel/math/positive_definite.hpp"
#include "kestrel/tracking/sonar_tracker.hpp"

namespace kestrel::test {

inline constexpr std::int64_t kSonarFuzzPeriodUs = 1000000;
inline constexpr int kSonarFuzzBeacons = 4;
inline constexpr std::size_t kSonarFuzzArrivals = 2 * kSonarFuzzBeacons;
// A fix, a few tracked pings, a reacquisition (3 empty frames) and a
// restart after a gap fit; more frames only repeat them. One ordinary ping
// costs about 1.2 ms per scalar under ASan at -O1, a failing multilateration
// several times that.
inline constexpr int kSonarFuzzMaxFrames = 24;

/// The target's travel time to a beacon at frame k, s: a slow straight
/// line at 40-60 m depth inside the UW-003 square, c = 1500 m/s.
inline double sonar_target_toa_s(const SonarTrackerParams& p, int beacon, bool reflected, int frame_index) {
  const double t = static_cast<double>(frame_index) * 1.0e-6 * static_cast<double>(kSonarFuzzPeriodUs);
  const double x = 700.0 + 1.2 * t;
  const double y = 900.0 + 0.8 * t;
  const double z = 40.0 + 0.05 * t;
  // The reflected path runs from the image source mirrored across the seabed.
  const double zs = reflected ? 2.0 * p.seabed_depth_m - z : z;
  const double* b = p.beacons_m[beacon];
  return std::sqrt((x - b[0]) * (x - b[0]) + (y - b[1]) * (y - b[1]) + (zs - b[2]) * (zs - b[2])) / 1500.0;
}

/// Next frame from the bytes; false when they are used up.
inline bool next_sonar_frame(ByteReader& r, std::int64_t& t_us, int frame_index, const SonarTrackerParams& p,
                             hal::Frame& f) {
  if (r.empty()) return false;
  const std::uint8_t op = r.u8();
  step_time(r, op, kSonarFuzzPeriodUs, t_us);
  f = hal::Frame{};
  f.kind = hal::FrameKind::kSonar;
  f.t_us = t_us;
  f.count = static_cast<std::uint16_t>((op >> 2) & 15u);
  const int start = op >> 6;
  for (std::uint16_t i = 0; i < f.count; ++i) {
    const std::uint8_t b = r.u8();
    hal::SonarArrival& a = f.sonar[i];
    a = hal::SonarArrival{};
    if ((b & 1u) == 0) {
      const int beacon = (start + i) % kSonarFuzzBeacons;
      const bool reflected = ((i / kSonarFuzzBeacons) & 1) != 0;
      const double noise_s = 2.0e-4 * (static_cast<double>((b >> 1) & 31u) - 15.5);
      const double late_s = (b >> 6) == 3 ? 0.040 : 0.0;
      const double toa_s = sonar_target_toa_s(p, beacon, reflected, frame_index) + noise_s + late_s;
      a.time_of_flight_ns = static_cast<std::uint32_t>(std::llround(toa_s * 1.0e9));
      a.beacon_id = static_cast<std::uint8_t>(beacon);
      a.path = reflected ? hal::ToaPath::kReflected : hal::ToaPath::kDirect;
    } else {
      a.time_of_flight_ns = r.read<std::uint32_t>();
      a.beacon_id = (b & 0x80u) != 0 ? r.u8() : static_cast<std::uint8_t>((b >> 4) & 7u);
      const std::uint8_t code = (b >> 1) & 7u;
      // ToaPath has a uint8 underlying type, so codes 6 and 7 are
      // representable values that are not a path.
      a.path = static_cast<hal::ToaPath>(code < 6 ? code & 1u : code);
    }
  }
  return true;
}

/// The state, the last update's diagnostics and the counters, but for the
/// per-status refusal counts, are the same bit for bit (NaN included).
template <class Tracker>
bool same_sonar_state(const Tracker& a, const Tracker& b) {
  const auto same_bits = [](const auto& u, const auto& v) {
    return std::memcmp(u.data(), v.data(), sizeof(*u.data()) * static_cast<std::size_t>(u.size())) == 0;
  };
  const auto& fa = a.filter();
  const auto& fb = b.filter();
  if (a.initialised() != b.initialised() || !same_bits(fa.x(), fb.x()) || !same_bits(fa.P(), fb.P())) return false;
  const auto& da = fa.diagnostics();
  const auto& db = fb.diagnostics();
  if (!same_bits(da.innovation, db.innovation) || !same_bits(da.innovation_variance, db.innovation_variance) ||
      !same_bits(da.test_ratio, db.test_ratio) || std::memcmp(&da.nis, &db.nis, sizeof(da.nis)) != 0 ||
      da.present != db.present || da.rejected != db.rejected || da.fused_channels != db.fused_channels ||
      da.fused != db.fused || da.status != db.status) {
    return false;
  }
  const SonarCounters& ca = a.counters();
  const SonarCounters& cb = b.counters();
  return ca.frames_ok == cb.frames_ok && ca.initialisations == cb.initialisations && ca.arrivals == cb.arrivals &&
         ca.fused == cb.fused && ca.gated_out == cb.gated_out && ca.predict_only == cb.predict_only;
}

/// Runs the bytes through one scalar's tracker; nullptr or what broke.
template <class Scalar>
const char* check_sonar_tracker_invariants_for(std::span<const std::uint8_t> in, FuzzTally& tally) {
  using Tracker = SonarTracker<Scalar, kSonarFuzzBeacons>;
  const SonarTrackerParams p = hal::sonar_tracker_params(hal::SonarAdapterParams{});
  // Heap, not stack, as the other harnesses: a tracker is a few KiB.
  auto tracker = std::make_unique<Tracker>(make_sonar_tracker<Scalar, kSonarFuzzBeacons>(p));
  auto before = std::make_unique<Tracker>(*tracker);
  auto frame = std::make_unique<hal::Frame>();
  const hal::SonarAdapter adapter;
  typename Tracker::Scan scan;
  ByteReader r(in);
  std::int64_t t_us = 0;
  for (int k = 0; k < kSonarFuzzMaxFrames && next_sonar_frame(r, t_us, k, p, *frame); ++k) {
    const std::size_t kept = frame->count < kSonarFuzzArrivals ? frame->count : kSonarFuzzArrivals;
    bool bad_path = false;
    for (std::size_t i = 0; i < kept; ++i) {
      bad_path = bad_path || static_cast<std::uint8_t>(frame->sonar[i].path) > 1u;
    }
    const Status converted = adapter(*frame, scan);
    if (bad_path) {
      if (converted != Status::kMalformedFrame) return "the adapter took an arrival whose path is not a path";
      continue;  // as the Runner: a frame the adapter refuses is not stepped
    }
    if (converted != Status::kOk && converted != Status::kTooManyCandidates) return "the adapter refused a sonar frame";
    if (scan.count != kept) return "the adapter kept the wrong number of arrivals";
    *before = *tracker;
    const Status s = tracker->step(scan);
    ++tally.frames;
    tally.refused += s != Status::kOk ? 1 : 0;
    tally.truncated += converted == Status::kTooManyCandidates ? 1 : 0;
    tally.reports += static_cast<int>(tracker->reports().size());
    if (s != Status::kOk) {
      if (!tracker->reports().empty()) return "a refused frame published reports";
      if (!same_sonar_state(*tracker, *before)) {
        // kNonFinite is a frame check (an arrival time) and a filter status.
        if (s == Status::kMalformedFrame || s == Status::kOutOfRange || s == Status::kTimeWentBackwards ||
            s == Status::kTimeJumpedForward) {
          return "a frame refused for its content or time changed the tracker";
        }
        if (tracker->initialised()) return "a frame refused for its fix or filter still holds a track";
      }
      const auto idx = static_cast<std::size_t>(s);
      for (std::size_t j = 0; j < kStatusCount; ++j) {
        const std::uint32_t rise = tracker->counters().rejected[j] - before->counters().rejected[j];
        if (rise != (j == idx ? 1u : 0u)) return "a refused frame moved the wrong refusal counter";
      }
    } else {
      if (tracker->reports().size() != 1) return "an accepted frame did not report once";
      if (tracker->reports()[0].t_us != scan.t_us) return "a report is not at its frame's time";
    }
    for (const auto& rep : tracker->reports()) {
      if (!all_finite(rep.x)) return "a reported state is not finite";
      if (!is_positive_definite(rep.P)) return "a reported covariance is not positive definite";
    }
    if (tracker->initialised()) {
      if (!all_finite(tracker->filter().x())) return "the tracker holds a state that is not finite";
      if (!is_positive_definite(tracker->filter().P())) return "the tracker holds a covariance that is not positive definite";
    }
  }
  return nullptr;
}

/// All scalars; nullptr or what broke. `tally` (optional) sums what the run met.
inline const char* check_sonar_tracker_invariants(std::span<const std::uint8_t> in, FuzzTally* tally = nullptr) {
  FuzzTally local;
  FuzzTally& t = tally != nullptr ? *tally : local;
  if (const char* why = check_sonar_tracker_invariants_for<double>(in, t)) return why;
  return check_sonar_tracker_invariants_for<float>(in, t);
}

}  // namespace kestrel::test
