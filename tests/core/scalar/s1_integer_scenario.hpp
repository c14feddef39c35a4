// SPDX-License-Identifier: Apache-2.0
// docs/scenarios.md's S1 (zig-zag with an axial burst) and S1n generated with
// integer arithmetic only: the truth comes from Q31.32 math (CORDIC sin,
// exact hypot, atan2), the noise from a splitmix64 generator and an
// Irwin-Hall normal (sum of 12 uniforms minus 6, sd 1), and each plot is
// quantised to the wire units (range mm, bearing binary angle) of
// hal::RadarPlot. So the same seed gives the same frames on every host and
// build type (x86-64 -O0/-O2, i386 with x87): the fixed-point golden hash
// depends on nothing else. Each scalar sees the frames through
// hal::to_scan, the HAL boundary a board uses.
//
// Used by tests/core/tracking/radar_tracker_fixed_point_test.cpp and by the
// standalone golden-hash program (golden_hash/golden_hash_main.cpp), which
// is built at several optimisation levels and for -m32.
#pragma once

#include <cstddef>
#include <cstdint>

#include "kestrel/hal/frame.hpp"
#include "kestrel/hal/radar_adapter.hpp"
#include "kestrel/scalar/fixed_point_eigen.hpp"
#include "kestrel/tracking/radar_tracker.hpp"

namespace kestrel::test {

/// splitmix64 (Steele, Lea, Flood 2014): tiny, fully specified, portable.
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }

 private:
  std::uint64_t state_;
};

/// Approximately N(0, 1) in units of 2^-32 (Irwin-Hall, |value| <= 6).
inline std::int64_t gaussian_2p32(SplitMix64& g) {
  std::int64_t sum = 0;
  for (int i = 0; i < 12; ++i) sum += static_cast<std::int64_t>(g.next() >> 32);
  return sum - 6 * (std::int64_t{1} << 32);
}

/// round(g * sigma / 2^32), half up, integer only.
inline std::int64_t scaled_noise(std::int64_t g_2p32, std::int64_t sigma) {
  return (g_2p32 * sigma + (std::int64_t{1} << 31)) >> 32;
}

/// round(v), half up, of a non-negative or negative Q31.32 value.
inline std::int64_t round_to_int(Q31_32 v) { return (v.raw() + (std::int64_t{1} << 31)) >> 32; }

struct S1Options {
  std::uint64_t seed = 1;
  bool time_varying_noise = false;  ///< S1n: range sigma x3 for 60 <= t < 75 s, bearing x3 for 110 <= t < 120 s.
  int steps = 300;                  ///< T = 0.5 s.
  bool tuned = false;               ///< qj = 160 m^2/s^5 (docs/r2aekf.md's tuned EKF-CA) instead of 1.6.
};

/// One step: the truth and the radar plot of time t = k T.
struct S1Sample {
  std::int64_t t_us;    ///< Frame time, us.
  Q31_32 x_m;           ///< True x, m.
  Q31_32 y_m;           ///< True y, m.
  hal::RadarPlot plot;  ///< Noisy plot in wire units.
};

inline constexpr std::int64_t kS1StepUs = 500000;
inline constexpr std::int64_t kS1RangeSigmaMm = 3000;  ///< sr = 3.0 m.
/// sb = 0.30 deg in binary angle units: 0.3 / 180 * 2^31 = 3579139.4.
inline constexpr std::int64_t kS1BearingSigmaBam = 3579139;

/// S1 truth at step k (docs/scenarios.md): x = -15000 + s(t), y = 8000 + 300 sin(2 pi t / 15),
/// s(t) at 200 m/s plus +5 m/s^2 for 80 <= t < 85 s.
inline void s1_truth(int k, Q31_32& x, Q31_32& y) {
  using Q = Q31_32;
  const Q t = Q(k) / Q(2);
  Q s;
  if (t < Q(80)) {
    s = Q(200) * t;
  } else if (t < Q(85)) {
    const Q a = t - Q(80);
    s = Q(200) * t + a * a * Q(5) / Q(2);
  } else {
    s = Q(200) * Q(85) + Q(25) * Q(5) / Q(2) + Q(225) * (t - Q(85));
  }
  x = Q(-15000) + s;
  // 2 pi t / 15 with t = k / 2: pi k / 15.
  y = Q(8000) + Q(300) * fixed::sin(ScalarTraits<Q>::pi() * Q(k) / Q(15));
}

inline S1Sample s1_sample(int k, const S1Options& o, SplitMix64& rng) {
  using Q = Q31_32;
  S1Sample out{};
  out.t_us = kS1StepUs * k;
  s1_truth(k, out.x_m, out.y_m);
  const bool range_x3 = o.time_varying_noise && k >= 120 && k < 150;    // 60 <= t < 75 s
  const bool bearing_x3 = o.time_varying_noise && k >= 220 && k < 240;  // 110 <= t < 120 s
  const std::int64_t g_r = gaussian_2p32(rng);
  const std::int64_t g_b = gaussian_2p32(rng);
  const std::int64_t range_mm = round_to_int(fixed::hypot(out.x_m, out.y_m) * Q(1000)) +
                                scaled_noise(g_r, kS1RangeSigmaMm * (range_x3 ? 3 : 1));
  // bearing / pi in [-1, 1] as Q31.32 raw; binary angle = that * 2^31.
  const Q turns = fixed::atan2(out.y_m, out.x_m) / ScalarTraits<Q>::pi();
  const std::int64_t bam = ((turns.raw() + 1) >> 1) + scaled_noise(g_b, kS1BearingSigmaBam * (bearing_x3 ? 3 : 1));
  out.plot.range_mm = static_cast<std::uint32_t>(range_mm < 0 ? 0 : range_mm);
  out.plot.bearing_bam = static_cast<std::int32_t>(static_cast<std::uint32_t>(bam));  // modulo one turn
  out.plot.has_range_rate = 0;
  return out;
}

/// One radar frame holding the sample's plot.
inline hal::Frame s1_frame(const S1Sample& s) {
  hal::Frame f{};
  f.kind = hal::FrameKind::kRadar;
  f.count = 1;
  f.t_us = s.t_us;
  f.radar[0] = s.plot;
  return f;
}

template <class Scalar>
using S1Tracker = RadarTracker<EkfCa<Scalar>, 4, 4>;

inline constexpr RadarTrackerParams tuned_params() {
  RadarTrackerParams p;
  p.qj = 160.0;
  return p;
}

/// The EKF-CA radar tracker with docs/scenarios.md's sensor and qj = 1.6 (or 160), its
/// real constants converted at compile time (as on a board).
template <class Scalar>
S1Tracker<Scalar> make_s1_tracker(bool tuned) {
  static constexpr RadarTrackerParams kParams{};
  static constexpr RadarTrackerParams kTuned = tuned_params();
  static constexpr RadarTrackerConfig<Scalar> kConfig = radar_tracker_config<Scalar>(kParams);
  static constexpr RadarTrackerConfig<Scalar> kTunedConfig = radar_tracker_config<Scalar>(kTuned);
  return tuned ? make_radar_tracker<Scalar, 4, 4>(kTuned, kTunedConfig)
               : make_radar_tracker<Scalar, 4, 4>(kParams, kConfig);
}

/// Runs S1 (or S1n) through `tracker` (any radar tracker); visit(k, sample,
/// tracker) after every step. @return false if a frame was refused.
template <class Tracker, class Visit>
bool run_s1_on(Tracker& tracker, const S1Options& o, Visit&& visit) {
  SplitMix64 rng(o.seed);
  typename Tracker::Scan scan;
  for (int k = 0; k < o.steps; ++k) {
    const S1Sample sample = s1_sample(k, o, rng);
    if (hal::to_scan(s1_frame(sample), scan) != Status::kOk) return false;
    if (tracker.step(scan) != Status::kOk) return false;
    visit(k, sample, static_cast<const Tracker&>(tracker));
  }
  return true;
}

/// run_s1_on() with the EKF-CA tracker of make_s1_tracker() on Scalar.
template <class Scalar, class Visit>
bool run_s1(const S1Options& o, Visit&& visit) {
  S1Tracker<Scalar> tracker = make_s1_tracker<Scalar>(o.tuned);
  return run_s1_on(tracker, o, visit);
}

/// 64-bit FNV-1a over little-endian integers: the same on every host.
class Fnv1a64 {
 public:
  void add(std::uint64_t v) {
    for (int i = 0; i < 8; ++i) {
      hash_ ^= (v >> (8 * i)) & 0xFFu;
      hash_ *= 0x100000001B3ull;
    }
  }
  void add_signed(std::int64_t v) { add(static_cast<std::uint64_t>(v)); }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 0xCBF29CE484222325ull;
};

/// Hash of every report (time, id, status, raw x and P) after every step of
/// S1 seed 1 on a fixed-point scalar.
template <int F>
std::uint64_t s1_golden_hash() {
  Fnv1a64 h;
  S1Options o;
  o.seed = 1;
  const bool ok = run_s1<FixedPoint<F>>(o, [&h](int, const S1Sample& s, const S1Tracker<FixedPoint<F>>& tr) {
    h.add_signed(s.t_us);
    h.add(tr.reports().size());
    for (const auto& r : tr.reports()) {
      h.add(r.track_id);
      h.add(static_cast<std::uint64_t>(r.status));
      for (int i = 0; i < 6; ++i) h.add_signed(r.x(i).raw());
      for (int c = 0; c < 6; ++c) {
        for (int i = 0; i < 6; ++i) h.add_signed(r.P(i, c).raw());
      }
    }
  });
  if (!ok) h.add(0xDEADull);
  return h.value();
}

/// Checked-in hashes of s1_golden_hash(): they change only by a deliberate
/// commit (a change of the arithmetic, the filter or the scenario).
inline constexpr std::uint64_t kS1GoldenHashQ31_32 = 0x1ffba0c88793211cull;
inline constexpr std::uint64_t kS1GoldenHashQ23_40 = 0x139710a68a6d9ba7ull;

}  // namespace kestrel::test
