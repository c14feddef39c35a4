// SPDX-License-Identifier: Apache-2.0
// The worst-case radar scene of the frame budgets (docs/footprint.md,
// "Worst-case frame per board") as wire frames: host_sim/bench's
// crowded_frames() (the host `worst_case` path's scene: targets on straight
// lines 20-35 km out, noise-free, then clutter plots at 300 km, outside every
// gate) quantised to the wire's millimetres and binary angles. Built from
// integers on every platform, the tracker sees the same frames on the host
// and on a board; frames_hash() lets each side prove it. Test and timing
// code only: it uses double libm, which no image links.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>

#include "kestrel/hal/frame.hpp"

namespace kestrel::board {

inline constexpr std::int64_t kWorstCasePeriodUs = 500'000;  ///< Frame interval, us (docs/scenarios.md's radar T).
inline constexpr std::size_t kWorstCaseWarmFrames = 10;     ///< Frames stepped before the counted ones.
inline constexpr std::size_t kWorstCaseCountedFrames = 3;   ///< Frames counted (and timed) after them.

/// Frame k of the scene with `targets` targets and `plots` plots in all
/// (targets first, then plots - targets clutter plots). plots <= hal::kMaxRadarPlots.
inline void worst_case_frame(std::size_t targets, std::size_t plots, std::size_t k, hal::Frame& f) {
  constexpr double kPi = std::numbers::pi;
  constexpr double kSpeedMps = 200.0;
  const double t = static_cast<double>(k) * 0.5;
  const double n = static_cast<double>(targets);
  const std::size_t clutter = plots - targets;
  f.kind = hal::FrameKind::kRadar;
  f.count = static_cast<std::uint16_t>(plots);
  f.t_us = static_cast<std::int64_t>(k) * kWorstCasePeriodUs;
  auto put = [&f](std::size_t i, double range_m, double bearing_rad) {
    hal::RadarPlot& p = f.radar[i];
    p = hal::RadarPlot{};
    p.range_mm = static_cast<std::uint32_t>(std::nearbyint(range_m * 1000.0));
    // host_sim/stream/quantise.cpp's rule: nearest binary angle, modulo 2^32.
    const auto bam = static_cast<std::int64_t>(std::round(bearing_rad / (2.0 * kPi) * 4294967296.0));
    p.bearing_bam = static_cast<std::int32_t>(static_cast<std::uint32_t>(bam));
  };
  for (std::size_t i = 0; i < targets && i < plots; ++i) {
    // As crowded_frames(): across the line of sight, neighbours kilometres apart.
    const double b0 = (static_cast<double>(i) + 0.5) * 2.0 * kPi / n - kPi;
    const double r0 = 20000.0 + 1000.0 * static_cast<double>(i);
    const double x = r0 * std::cos(b0) - kSpeedMps * t * std::sin(b0);
    const double y = r0 * std::sin(b0) + kSpeedMps * t * std::cos(b0);
    put(i, std::hypot(x, y), std::atan2(y, x));
  }
  for (std::size_t i = 0; i < clutter; ++i) {
    const double b = (static_cast<double>(i) + 0.25) * 2.0 * kPi / static_cast<double>(clutter) - kPi;
    put(targets + i, 300000.0, b);
  }
}

/// FNV-1a over the time, ranges and bearings of frames [0, frames).
inline std::uint64_t frames_hash(std::size_t targets, std::size_t plots, std::size_t frames) {
  std::uint64_t h = 14695981039346656037ull;
  auto mix = [&h](std::uint64_t v) {
    for (int b = 0; b < 8; ++b) {
      h ^= (v >> (8 * b)) & 0xFFu;
      h *= 1099511628211ull;
    }
  };
  hal::Frame f{};
  for (std::size_t k = 0; k < frames; ++k) {
    worst_case_frame(targets, plots, k, f);
    mix(static_cast<std::uint64_t>(f.t_us));
    for (std::size_t i = 0; i < f.count; ++i) {
      mix(f.radar[i].range_mm);
      mix(static_cast<std::uint32_t>(f.radar[i].bearing_bam));
    }
  }
  return h;
}

}  // namespace kestrel::board
