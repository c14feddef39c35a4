// SPDX-License-Identifier: Apache-2.0
// The passive-radar (PCL) tracker driven by arbitrary bytes, for libFuzzer
// (pcl_tracker_fuzz.cpp) and for the regression test that replays the
// corpus and a seeded batch of inputs under the normal build
// (tests/core/tracking/tracker_fuzz_regression_test.cpp).
//
// The bytes are read as a sequence of wire PCL frames (hal::Frame), each
// converted by the board adapter (hal::PclAdapter, which ranks an
// over-capacity frame's candidates against the live tracks) and stepped by
// the PCL-002 tracker in double and float (the scalars pcl_tracker.hpp is
// built for). Per frame, one op byte: bits 0-1 choose the time step
// (fuzz_bytes.hpp: the next 0.5 s frame; a signed step of up to +-32 s; any
// int64 time; a gap of up to 49 days), bits 2-5 the candidate count (0-15,
// over the scan capacity of 8 on purpose), bits 6-7 unused. Per candidate,
// one byte b:
//   - bit 0 clear: near one of four targets (bits 1-2), noise from bits
//     3-7; one target slows through zero Doppler, where no track may start
//     but a confirmed one must survive;
//   - bits 0-1 = 01: clutter inside the valid box, u16 range (3 m units)
//     and i16 Doppler (1/8 Hz units), SNR from bits 2-7;
//   - bits 0-1 = 11: raw u32 range (mm), i32 Doppler (mHz), i16 SNR.
// After every step:
//   - the adapter kept min(count, 8) candidates;
//   - a refused frame (any status but kOk) leaves every track as it was and
//     reports nothing;
//   - every reported and every initialised track has a finite state and a
//     positive definite covariance.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>

#include "fuzz_bytes.hpp"
#include "kestrel/hal/frame.hpp"
#include "kestrel/hal/pcl_adapter.hpp"
#include "kestrel/math/finite.hpp"
#include "kestrel/math/positive_definite.hpp"
#include "kestrel/tracking/pcl_tracker.hpp"
#include "same_tracks.hpp"

namespace kestrel::test {

inline constexpr std::int64_t kPclFuzzPeriodUs = 500000;
inline constexpr std::size_t kPclFuzzTracks = 16;
inline constexpr std::size_t kPclFuzzCandidates = 8;
// Long enough for tracks to confirm (5 of 6), coast out (6 misses) and
// start again, short enough that an execution of ordinary frames stays
// near 50 ms under ASan at -O1.
inline constexpr int kPclFuzzMaxFrames = 48;

/// Next frame from the bytes; false when they are used up.
/// @param lambda_m carrier wavelength, m (the targets' Doppler).
inline bool next_pcl_frame(ByteReader& r, std::int64_t& t_us, int frame_index, double lambda_m, hal::Frame& f) {
  if (r.empty()) return false;
  const std::uint8_t op = r.u8();
  step_time(r, op, kPclFuzzPeriodUs, t_us);
  f = hal::Frame{};
  f.kind = hal::FrameKind::kPcl;
  f.t_us = t_us;
  f.count = static_cast<std::uint16_t>((op >> 2) & 15u);
  for (std::uint16_t i = 0; i < f.count; ++i) {
    const std::uint8_t b = r.u8();
    hal::PclCandidate& c = f.pcl[i];
    c = hal::PclCandidate{};
    if ((b & 1u) == 0) {
      const int target = (b >> 1) & 3;
      const double t = 0.5 * frame_index;
      const double noise = static_cast<double>((b >> 3) & 31u) - 15.5;
      // Range rates -12, +25 and -60 m/s; target 3 starts at +8 m/s and
      // decelerates through 0 at t = 8 s (frame 16). Every range stays in
      // (0, 200 km) well past the frame cap.
      const double v0[4] = {-12.0, 25.0, -60.0, 8.0};
      const double a = target == 3 ? -1.0 : 0.0;
      const double rb_m = 4000.0 + 9000.0 * target + v0[target] * t + 0.5 * a * t * t + noise;
      const double rate_mps = v0[target] + a * t;
      // dRb = -lambda fD; Doppler noise of about 0.05 Hz per noise step.
      const double doppler_hz = -rate_mps / lambda_m + 0.05 * noise;
      c.bistatic_range_mm = static_cast<std::uint32_t>(rb_m * 1000.0);
      c.doppler_mhz = static_cast<std::int32_t>(std::lround(doppler_hz * 1000.0));
      c.snr_cdb = static_cast<std::int16_t>(1500 + 10 * ((b >> 3) & 31));
    } else if ((b & 2u) == 0) {
      c.bistatic_range_mm = static_cast<std::uint32_t>(r.read<std::uint16_t>()) * 3000u;
      c.doppler_mhz = static_cast<std::int32_t>(r.read<std::int16_t>()) * 125;
      c.snr_cdb = static_cast<std::int16_t>(20 * (b >> 2));
    } else {
      c.bistatic_range_mm = r.read<std::uint32_t>();
      c.doppler_mhz = r.read<std::int32_t>();
      c.snr_cdb = r.read<std::int16_t>();
    }
  }
  return true;
}

/// Runs the bytes through one scalar's tracker; nullptr or what broke.
template <class Scalar>
const char* check_pcl_tracker_invariants_for(std::span<const std::uint8_t> in, FuzzTally& tally) {
  // 16 slots against up to 8 candidates a frame: clutter fills the table
  // and the "no free slot" path runs too. Small, because gating costs
  // slots x candidates innovations a frame, the bulk of an execution.
  using Tracker = PclTracker<PclKf<Scalar>, kPclFuzzTracks, kPclFuzzCandidates>;
  const PclTrackerParams p;
  // Heap, not stack: the tracker and its snapshot are several KiB each.
  auto tracker = std::make_unique<Tracker>(make_pcl_tracker<Scalar, kPclFuzzTracks, kPclFuzzCandidates>(p));
  auto before = std::make_unique<Tracker>(*tracker);
  auto frame = std::make_unique<hal::Frame>();
  hal::PclAdapterParams adapter_config;
  adapter_config.carrier_hz = p.carrier_hz;
  const hal::PclAdapter<Tracker> adapter(tracker.get(), adapter_config);
  const double lambda_m = kSpeedOfLightMps / p.carrier_hz;
  typename Tracker::Scan scan;
  ByteReader r(in);
  std::int64_t t_us = 0;
  for (int k = 0; k < kPclFuzzMaxFrames && next_pcl_frame(r, t_us, k, lambda_m, *frame); ++k) {
    const Status converted = adapter(*frame, scan);
    if (converted != Status::kOk && converted != Status::kTooManyCandidates) return "the adapter refused a PCL frame";
    const std::size_t kept = frame->count < kPclFuzzCandidates ? frame->count : kPclFuzzCandidates;
    if (scan.count != kept) return "the adapter kept the wrong number of candidates";
    *before = *tracker;
    const Status s = tracker->step(scan);
    ++tally.frames;
    tally.refused += s != Status::kOk ? 1 : 0;
    tally.truncated += converted == Status::kTooManyCandidates ? 1 : 0;
    tally.reports += static_cast<int>(tracker->reports().size());
    if (const char* why = step_invariant_broken(*tracker, *before, s)) return why;
  }
  return nullptr;
}

/// All scalars; nullptr or what broke. `tally` (optional) sums what the run met.
inline const char* check_pcl_tracker_invariants(std::span<const std::uint8_t> in, FuzzTally* tally = nullptr) {
  FuzzTally local;
  FuzzTally& t = tally != nullptr ? *tally : local;
  if (const char* why = check_pcl_tracker_invariants_for<double>(in, t)) return why;
  return check_pcl_tracker_invariants_for<float>(in, t);
}

}  // namespace kestrel::test
