#include "stream/quantise.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace kestrel::sim {

namespace {
void require_finite(double v, const char* what) {
  if (!std::isfinite(v)) throw std::invalid_argument(std::string("non-finite ") + what);
}
}  // namespace

std::int64_t to_wire_time_us(double t_s) { return std::llround(t_s * 1e6); }

std::uint32_t to_wire_range_mm(double range_m) {
  const double mm = std::nearbyint(range_m * 1000.0);
  if (mm <= 0.0) return 0;
  if (mm >= 4294967295.0) return std::numeric_limits<std::uint32_t>::max();
  return static_cast<std::uint32_t>(mm);
}

std::int32_t to_wire_bearing_bam(double bearing_rad) {
  // Reduce to [-2^31, 2^31) turns first, so any finite angle maps, then let
  // the unsigned-to-signed conversion (modular in C++20) wrap +pi to -pi.
  const double turns = std::remainder(bearing_rad, 2.0 * std::numbers::pi) / (2.0 * std::numbers::pi);
  const auto bam = static_cast<std::int64_t>(std::llround(turns * 4294967296.0));
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(bam & 0xFFFFFFFFLL));
}

std::int32_t to_wire_range_rate_mmps(double range_rate_mps) {
  const double mmps = std::nearbyint(range_rate_mps * 1000.0);
  if (mmps <= -2147483648.0) return std::numeric_limits<std::int32_t>::min();
  if (mmps >= 2147483647.0) return std::numeric_limits<std::int32_t>::max();
  return static_cast<std::int32_t>(mmps);
}

hal::Frame to_wire_frame(const MeasurementFrame& frame) {
  if (frame.kind != hal::FrameKind::kRadar) throw std::invalid_argument("only radar frames are quantised so far");
  if (frame.radar.size() > hal::kMaxRadarPlots) {
    throw std::invalid_argument("frame at t = " + std::to_string(frame.t_s) + " s has " +
                                std::to_string(frame.radar.size()) + " plots; a wire frame holds " +
                                std::to_string(hal::kMaxRadarPlots));
  }
  require_finite(frame.t_s, "time");
  hal::Frame out{};
  out.kind = hal::FrameKind::kRadar;
  out.t_us = to_wire_time_us(frame.t_s);
  out.count = static_cast<std::uint16_t>(frame.radar.size());
  for (std::size_t i = 0; i < frame.radar.size(); ++i) {
    const RadarPlotSi& p = frame.radar[i];
    require_finite(p.range_m, "range");
    require_finite(p.bearing_rad, "bearing");
    hal::RadarPlot w{};
    w.range_mm = to_wire_range_mm(p.range_m);
    w.bearing_bam = to_wire_bearing_bam(p.bearing_rad);
    if (p.range_rate_mps.has_value()) {
      require_finite(*p.range_rate_mps, "range rate");
      w.range_rate_mmps = to_wire_range_rate_mmps(*p.range_rate_mps);
      w.has_range_rate = 1;
    }
    w.sensor_id = p.sensor_id;
    out.radar[i] = w;
  }
  return out;
}

MeasurementFrame from_wire_frame(const hal::Frame& frame) {
  MeasurementFrame out;
  out.t_s = static_cast<double>(frame.t_us) * 1e-6;
  out.kind = frame.kind;
  if (frame.kind != hal::FrameKind::kRadar) return out;
  const std::size_t n = frame.count < hal::kMaxRadarPlots ? frame.count : hal::kMaxRadarPlots;
  for (std::size_t i = 0; i < n; ++i) {
    const hal::RadarPlot& w = frame.radar[i];
    RadarPlotSi p;
    p.range_m = static_cast<double>(w.range_mm) * 1e-3;
    p.bearing_rad = static_cast<double>(w.bearing_bam) * hal::kRadPerBam;
    if (w.has_range_rate != 0) p.range_rate_mps = static_cast<double>(w.range_rate_mmps) * 1e-3;
    p.sensor_id = w.sensor_id;
    out.radar.push_back(p);
  }
  return out;
}

}  // namespace kestrel::sim
