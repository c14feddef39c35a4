// SPDX-License-Identifier: Apache-2.0
// The radar tracker driven by arbitrary bytes, for libFuzzer
// (radar_tracker_fuzz.cpp) and for the regression test that replays the
// corpus and a seeded batch of inputs under the normal build
// (tests/core/tracking/tracker_fuzz_regression_test.cpp).
//
// The bytes are read as a sequence of wire radar frames (hal::Frame), each
// converted by the board adapter (hal::to_scan) and stepped, in double,
// float and Q31.32, by the board's tracker and by one whose initiator keeps
// second hypotheses (TwoPointHypothesesInitiator, two extra seed frames,
// pairing plots seeding: the seeds it copies and releases mid-frame). Per frame, one op byte: bits 0-1 choose the time step
// (fuzz_bytes.hpp: the next 0.5 s scan; a signed step of up to +-32 s; any
// int64 time; a gap of up to 49 days), bits 2-6 the plot count (0-31, over
// the scan capacity of 16 on purpose). Per plot, one byte: bit 0 set reads a raw
// range (u32 mm) and bearing (i32 binary angle), clear puts the plot near
// one of four straight-line targets, so tracks form and live long enough to
// meet the faults. The IMM (CV/CA/CT, double and float) runs the same
// bytes as docs/robustness.md runs it: global nearest neighbour, the robust
// gate at 25 and the adaptive measurement noise at gain 0.2, so its mixing
// and its scaled and clipped updates meet the same faults. After every step:
//   - a refused frame (any status but kOk and kTooManyCandidates) leaves
//     every track as it was and reports nothing;
//   - every reported and every initialised track has a finite state and a
//     positive definite covariance;
//   - an IMM track's mode probabilities are finite, in [0, 1] and sum to 1.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <type_traits>

#include "fuzz_bytes.hpp"
#include "kestrel/association/global_nearest_neighbour.hpp"
#include "kestrel/filters/imm_radar.hpp"
#include "kestrel/hal/frame.hpp"
#include "kestrel/hal/radar_adapter.hpp"
#include "kestrel/math/finite.hpp"
#include "kestrel/math/positive_definite.hpp"
#include "kestrel/scalar/fixed_point.hpp"
#include "kestrel/scalar/fixed_point_eigen.hpp"
#include "kestrel/tracking/measurement_noise.hpp"
#include "kestrel/tracking/radar_tracker.hpp"
#include "same_tracks.hpp"

namespace kestrel::test {

/// Next frame from the bytes; false when they are used up.
inline bool next_radar_frame(ByteReader& r, std::int64_t& t_us, int frame_index, hal::Frame& f) {
  if (r.empty()) return false;
  const std::uint8_t op = r.u8();
  step_time(r, op, 500000, t_us);
  f = hal::Frame{};
  f.kind = hal::FrameKind::kRadar;
  f.t_us = t_us;
  f.count = static_cast<std::uint16_t>((op >> 2) & 31u);
  for (std::uint16_t i = 0; i < f.count; ++i) {
    const std::uint8_t b = r.u8();
    hal::RadarPlot& p = f.radar[i];
    p = hal::RadarPlot{};
    if (b & 1u) {
      p.range_mm = r.read<std::uint32_t>();
      p.bearing_bam = r.read<std::int32_t>();
    } else {
      const int target = (b >> 1) & 3;
      const double t = 0.5 * frame_index;
      const double noise = static_cast<double>((b >> 3) & 31u) - 15.5;
      const double x = -15000.0 + 4000.0 * target + (150.0 + 30.0 * target) * t + noise;
      const double y = 8000.0 - 3000.0 * target + (40.0 - 60.0 * target) * t - noise;
      p.range_mm = static_cast<std::uint32_t>(std::hypot(x, y) * 1000.0);
      // atan2 = +pi maps to 2^31, one past the binary angle's range: clamp.
      const double bam = std::atan2(y, x) / 3.14159265358979323846 * 2147483648.0;
      p.bearing_bam = bam >= 2147483647.0 ? INT32_MAX : static_cast<std::int32_t>(bam);
    }
  }
  return true;
}

/// The radar tracker of make_radar_tracker() with the hypotheses initiator.
template <class Scalar>
using HypothesesRadarTracker =
    Tracker<EkfCa<Scalar>, TwoPointHypothesesInitiator<CaMotion<Scalar>, CaPolarRadar<Scalar>>, 8, 16>;

template <class Scalar>
HypothesesRadarTracker<Scalar> make_hypotheses_radar_tracker(const RadarTrackerParams& p) {
  const auto board = make_radar_tracker<Scalar, 8, 16>(p);
  TwoPointHypothesesInitiator<CaMotion<Scalar>, CaPolarRadar<Scalar>> init{board.initiator(), 2, true};
  return HypothesesRadarTracker<Scalar>(board.prototype_filter(), init, board.config());
}

/// The IMM of docs/robustness.md in the tracker (see the header note).
template <class Scalar>
using RobustImmRadarTracker =
    Tracker<RadarImm<Scalar>, TwoPointHypothesesInitiator<CaMotion<Scalar>, CaPolarRadar<Scalar>>, 8, 16,
            GlobalNearestNeighbour, MOfN, AdaptiveMeasurementNoise>;

/// make_radar_tracker(p)'s initiation and management around the IMM with
/// p's sensor sigmas, robust gate 25 and adaptive noise gain 0.2; nullptr
/// if the tracker refuses that noise rule.
template <class Scalar>
std::unique_ptr<RobustImmRadarTracker<Scalar>> make_robust_imm_radar_tracker(RadarTrackerParams p) {
  p.robust_gate_factor = 25.0;
  p.robust_noise_gain = 0.2;
  const auto board = make_radar_tracker<Scalar, 8, 16>(p);
  RadarImmParams ip;
  ip.sigma_range_m = p.sigma_range_m;
  ip.sigma_bearing_rad = p.sigma_bearing_rad;
  TwoPointHypothesesInitiator<CaMotion<Scalar>, CaPolarRadar<Scalar>> init{board.initiator(), 2, true};
  auto tracker = std::make_unique<RobustImmRadarTracker<Scalar>>(make_radar_imm<Scalar>(ip), init, board.config());
  if (tracker->configure_measurement_noise(radar_measurement_noise<Scalar>(p)) != Status::kOk) return nullptr;
  return tracker;
}

/// For a filter with mode probabilities: nullptr, or what is wrong with
/// those of an initialised track.
template <class Tracker>
const char* mode_probabilities_broken(const Tracker& tracker) {
  if constexpr (requires(const typename Tracker::TrackT& t) { t.filter.mode_probabilities(); }) {
    for (const std::size_t i : tracker.tracks().active_slots()) {
      const auto& tr = tracker.tracks()[i];
      if (!tr.initialised) continue;
      const auto& mu = tr.filter.mode_probabilities();
      double sum = 0.0;
      for (int j = 0; j < static_cast<int>(mu.size()); ++j) {
        const double m = static_cast<double>(mu(j));
        if (!(m >= 0.0 && m <= 1.0)) return "a mode probability is not finite or outside [0, 1]";
        sum += m;
      }
      // float's rounding over three modes, with room to spare.
      if (!(std::fabs(sum - 1.0) <= 1e-4)) return "the mode probabilities do not sum to 1";
    }
  }
  return nullptr;
}

/// Runs the bytes through one tracker; nullptr or what broke.
template <class Tracker>
const char* check_radar_tracker_invariants_of(std::span<const std::uint8_t> in, const Tracker& start,
                                              FuzzTally* tally = nullptr) {
  // Heap, not stack: the tracker and its snapshot are a few tens of KiB.
  auto tracker = std::make_unique<Tracker>(start);
  auto before = std::make_unique<Tracker>(*tracker);
  auto frame = std::make_unique<hal::Frame>();
  typename Tracker::Scan scan;
  ByteReader r(in);
  std::int64_t t_us = 0;
  for (int k = 0; k < 400 && next_radar_frame(r, t_us, k, *frame); ++k) {
    const Status converted = hal::to_scan(*frame, scan);
    if (converted != Status::kOk && converted != Status::kTooManyCandidates) return "to_scan refused a radar frame";
    *before = *tracker;
    const Status s = tracker->step(scan);
    if (const char* why = step_invariant_broken(*tracker, *before, s)) return why;
    if (const char* why = mode_probabilities_broken(*tracker)) return why;
    if (tally != nullptr) {
      ++tally->frames;
      tally->refused += s != Status::kOk ? 1 : 0;
      tally->truncated += converted == Status::kTooManyCandidates ? 1 : 0;
      tally->reports += static_cast<int>(tracker->reports().size());
    }
  }
  return nullptr;
}

/// Runs the bytes through one scalar's trackers; nullptr or what broke.
/// `imm_tally` (optional) sums what the IMM's run met.
template <class Scalar>
const char* check_radar_tracker_invariants_for(std::span<const std::uint8_t> in, FuzzTally* imm_tally) {
  RadarTrackerParams p;
  p.qj = 16.0;
  {
    auto board = std::make_unique<RadarTracker<EkfCa<Scalar>, 8, 16>>(make_radar_tracker<Scalar, 8, 16>(p));
    if (const char* why = check_radar_tracker_invariants_of(in, *board)) return why;
  }
  {
    auto hypotheses = std::make_unique<HypothesesRadarTracker<Scalar>>(make_hypotheses_radar_tracker<Scalar>(p));
    if (const char* why = check_radar_tracker_invariants_of(in, *hypotheses)) return why;
  }
  if constexpr (std::is_floating_point_v<Scalar>) {  // the IMM is double and float
    const auto imm = make_robust_imm_radar_tracker<Scalar>(p);
    if (imm == nullptr) return "the IMM tracker refused its adaptive noise rule";
    return check_radar_tracker_invariants_of(in, *imm, imm_tally);
  }
  return nullptr;
}

/// All scalars; nullptr or what broke. `imm_tally` (optional) sums what
/// the IMM's runs (double and float) met.
inline const char* check_radar_tracker_invariants(std::span<const std::uint8_t> in, FuzzTally* imm_tally = nullptr) {
  if (const char* why = check_radar_tracker_invariants_for<double>(in, imm_tally)) return why;
  if (const char* why = check_radar_tracker_invariants_for<float>(in, imm_tally)) return why;
  return check_radar_tracker_invariants_for<Q31_32>(in, imm_tally);
}

}  // namespace kestrel::test
