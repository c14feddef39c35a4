// SPDX-License-Identifier: Apache-2.0
// Inputs shared by the timing benchmarks (bench.cpp, kestrel-bench) and the
// instruction-count harness (instr_count.cpp, kestrel-instr-count): the S1
// frames (docs/scenarios.md, fixed noise seed) and a full-capacity frame
// sequence, as plain SI records. Both programs measure exactly the same
// steps, so a ns figure and an instruction count of one path describe the
// same work.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace kestrel::bench {

/// One radar plot, SI units (radar at the origin).
struct PlotSi {
  double range_m = 0.0;      ///< Slant range, m.
  double bearing_rad = 0.0;  ///< Counter-clockwise from +x, rad, (-pi, pi].
};

/// One frame: a time and its plots.
struct FrameSi {
  std::int64_t t_us = 0;      ///< Frame time, us.
  std::vector<PlotSi> plots;  ///< Plots in scan order.
};

/// Noise seed of every benchmark run (fixed: counts must be repeatable).
inline constexpr std::uint64_t kBenchSeed = 1;

/// S1 (zig-zag with axial burst, T = 0.5 s, 300 frames, one plot per frame,
/// sr 3 m, sb 0.30 deg) as kestrel-sim generates it with `seed`.
std::vector<FrameSi> s1_frames(std::uint64_t seed = kBenchSeed);

/// A full-capacity sequence: `targets` targets on straight lines (200 m/s,
/// 20-35 km from the radar, spread over all bearings, noise-free plots)
/// plus `clutter` plots at 300 km, far outside every gate, in each of
/// `frames` frames, T = 0.5 s. Target plots come first in each frame.
std::vector<FrameSi> crowded_frames(std::size_t targets, std::size_t clutter, std::size_t frames);

}  // namespace kestrel::bench
