// SPDX-License-Identifier: Apache-2.0
#include "bench/bench_inputs.hpp"

#include <cmath>
#include <numbers>

#include "scenarios/s1_zigzag.hpp"

namespace kestrel::bench {

std::vector<FrameSi> s1_frames(std::uint64_t seed) {
  const sim::ScenarioRun run = sim::make_s1()->generate(seed);
  std::vector<FrameSi> out;
  out.reserve(run.frames.size());
  for (const sim::MeasurementFrame& f : run.frames) {
    FrameSi frame;
    frame.t_us = std::llround(f.t_s * 1e6);
    for (const sim::RadarPlotSi& p : f.radar) frame.plots.push_back(PlotSi{p.range_m, p.bearing_rad});
    out.push_back(std::move(frame));
  }
  return out;
}

std::vector<FrameSi> crowded_frames(std::size_t targets, std::size_t clutter, std::size_t frames) {
  constexpr double kPeriodS = 0.5;
  constexpr double kSpeedMps = 200.0;
  const double n = static_cast<double>(targets);
  std::vector<FrameSi> out;
  out.reserve(frames);
  for (std::size_t k = 0; k < frames; ++k) {
    const double t = static_cast<double>(k) * kPeriodS;
    FrameSi frame;
    frame.t_us = std::llround(t * 1e6);
    for (std::size_t i = 0; i < targets; ++i) {
      // Start 20-35 km out on bearing (i + 0.5) 2 pi / n, fly across the
      // line of sight: neighbours stay kilometres apart, so no pairing or
      // gate confuses two targets.
      const double b0 = (static_cast<double>(i) + 0.5) * 2.0 * std::numbers::pi / n - std::numbers::pi;
      const double r0 = 20000.0 + 1000.0 * static_cast<double>(i);
      const double x = r0 * std::cos(b0) - kSpeedMps * t * std::sin(b0);
      const double y = r0 * std::sin(b0) + kSpeedMps * t * std::cos(b0);
      frame.plots.push_back(PlotSi{std::hypot(x, y), std::atan2(y, x)});
    }
    for (std::size_t i = 0; i < clutter; ++i) {
      const double b = (static_cast<double>(i) + 0.25) * 2.0 * std::numbers::pi / static_cast<double>(clutter) -
                       std::numbers::pi;
      frame.plots.push_back(PlotSi{300000.0, b});
    }
    out.push_back(std::move(frame));
  }
  return out;
}

}  // namespace kestrel::bench
