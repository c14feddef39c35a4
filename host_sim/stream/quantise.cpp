// SPDX-License-Identifier: Apache-2.0
#include "stream/quantise.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>

namespace kestrel::sim {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Every check is written as "inside", so NaN (which compares false) fails it.

template <class T>
T or_throw(std::optional<T> wire, const char* quantity, double value, std::string_view span) {
  if (!wire.has_value()) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    throw std::out_of_range(std::string(quantity) + " " + text + " is outside what the wire can carry, " +
                            std::string(span));
  }
  return *wire;
}

}  // namespace

std::optional<std::int64_t> try_wire_time_us(double t_s) {
  // std::round, not llround: llround of a value outside long long is
  // unspecified, so the range is checked on the double. 2^63 is exact in a
  // double; the largest double below it is the largest time accepted.
  const double us = std::round(t_s * 1e6);
  if (!(us >= -9223372036854775808.0 && us < 9223372036854775808.0)) return std::nullopt;
  return static_cast<std::int64_t>(us);
}

std::optional<std::uint32_t> try_wire_range_mm(double range_m) {
  const double mm = std::nearbyint(range_m * 1000.0);
  if (!(mm >= 0.0 && mm <= 4294967295.0)) return std::nullopt;
  return static_cast<std::uint32_t>(mm);
}

std::optional<std::int32_t> try_wire_bearing_bam(double bearing_rad) {
  // Beyond one turn the value is no bearing a sensor reports (degrees by
  // mistake, or garbage), and far beyond it the double has lost the wire's
  // resolution (at 1e10 rad its spacing is 2e-6 rad, over 1000 binary-angle
  // units), so a "wrapped" value would be an invention: refuse it.
  if (!(std::abs(bearing_rad) <= kTwoPi)) return std::nullopt;
  // The nearest binary angle, an integer in [-2^32, 2^32]. Reducing it
  // modulo 2^32 (the conversions to uint32 and on to int32 are modular in
  // C++20) is exact, so +pi wraps to -pi and 4 rad to 4 - 2 pi with no
  // rounding beyond the quantisation every bearing gets.
  const auto bam = static_cast<std::int64_t>(std::round(bearing_rad / kTwoPi * 4294967296.0));
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(bam));
}

std::optional<std::int32_t> try_wire_range_rate_mmps(double range_rate_mps) {
  const double mmps = std::nearbyint(range_rate_mps * 1000.0);
  if (!(mmps >= -2147483648.0 && mmps <= 2147483647.0)) return std::nullopt;
  return static_cast<std::int32_t>(mmps);
}

std::int64_t to_wire_time_us(double t_s) { return or_throw(try_wire_time_us(t_s), "time", t_s, kWireTimeSpan); }

std::uint32_t to_wire_range_mm(double range_m) {
  return or_throw(try_wire_range_mm(range_m), "range", range_m, kWireRangeSpan);
}

std::int32_t to_wire_bearing_bam(double bearing_rad) {
  return or_throw(try_wire_bearing_bam(bearing_rad), "bearing", bearing_rad, kWireBearingSpan);
}

std::int32_t to_wire_range_rate_mmps(double range_rate_mps) {
  return or_throw(try_wire_range_rate_mmps(range_rate_mps), "range rate", range_rate_mps, kWireRangeRateSpan);
}

hal::Frame to_wire_frame(const MeasurementFrame& frame) {
  if (frame.kind != hal::FrameKind::kRadar) throw std::invalid_argument("only radar frames are quantised so far");
  if (frame.radar.size() > hal::kMaxRadarPlots) {
    throw std::invalid_argument("frame at t = " + std::to_string(frame.t_s) + " s has " +
                                std::to_string(frame.radar.size()) + " plots; a wire frame holds " +
                                std::to_string(hal::kMaxRadarPlots));
  }
  hal::Frame out{};
  out.kind = hal::FrameKind::kRadar;
  out.t_us = to_wire_time_us(frame.t_s);
  out.count = static_cast<std::uint16_t>(frame.radar.size());
  for (std::size_t i = 0; i < frame.radar.size(); ++i) {
    const RadarPlotSi& p = frame.radar[i];
    hal::RadarPlot w{};
    w.range_mm = to_wire_range_mm(p.range_m);
    w.bearing_bam = to_wire_bearing_bam(p.bearing_rad);
    if (p.range_rate_mps.has_value()) {
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
