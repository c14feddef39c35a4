// SPDX-License-Identifier: Apache-2.0
#include "csv/radar_plot_csv.hpp"

#include <cstdio>
#include <fstream>
#include <memory>
#include <stdexcept>

#include "csv/csv_reader.hpp"
#include "kestrel/hal/frame.hpp"
#include "stream/quantise.hpp"

namespace kestrel::sim {

namespace {
// The wire value of a cell, or a CsvError naming the column, the text as
// written and what the wire field can carry. Replay quantises every value
// later; checking here is what puts file:line on a value it cannot send.
template <class T>
T on_wire(const CsvReader& csv, std::size_t col, std::optional<T> wire, std::string_view span) {
  if (!wire.has_value()) csv.fail_cell(col, "is outside what the wire can carry, " + std::string(span));
  return *wire;
}
}  // namespace

std::vector<MeasurementFrame> read_radar_plot_csv(std::istream& in, const std::string& source) {
  CsvReader csv(in, source);
  const std::size_t c_time = csv.require_column("time_s");
  const std::size_t c_range = csv.require_column("range_m");
  const std::size_t c_bearing = csv.require_column("bearing_rad");
  const auto c_rate = csv.find_column("range_rate_mps");
  const auto c_sensor = csv.find_column("sensor_id");

  std::vector<MeasurementFrame> frames;
  std::int64_t last_t_us = 0;
  while (csv.next()) {
    const double t_s = csv.number(c_time);
    const std::int64_t t_us = on_wire(csv, c_time, try_wire_time_us(t_s), kWireTimeSpan);
    RadarPlotSi plot;
    plot.range_m = csv.number(c_range);
    if (plot.range_m < 0.0) csv.fail("column 'range_m': a range cannot be negative");
    on_wire(csv, c_range, try_wire_range_mm(plot.range_m), kWireRangeSpan);
    plot.bearing_rad = csv.number(c_bearing);
    on_wire(csv, c_bearing, try_wire_bearing_bam(plot.bearing_rad), kWireBearingSpan);
    if (c_rate.has_value()) {
      plot.range_rate_mps = csv.optional_number(*c_rate);
      if (plot.range_rate_mps.has_value()) {
        on_wire(csv, *c_rate, try_wire_range_rate_mmps(*plot.range_rate_mps), kWireRangeRateSpan);
      }
    }
    if (c_sensor.has_value()) plot.sensor_id = static_cast<std::uint8_t>(csv.integer(*c_sensor, 0, 255));

    // Same time as the previous row (compared in wire microseconds, the
    // resolution a frame has): same frame.
    const bool same_frame = !frames.empty() && t_us == last_t_us;
    last_t_us = t_us;
    if (!same_frame) {
      frames.emplace_back();
      frames.back().t_s = t_s;
      frames.back().kind = hal::FrameKind::kRadar;
    }
    if (frames.back().radar.size() == hal::kMaxRadarPlots) {
      csv.fail("more than " + std::to_string(hal::kMaxRadarPlots) + " plots at time_s " + std::to_string(t_s) +
               " (the capacity of a radar wire frame)");
    }
    frames.back().radar.push_back(plot);
  }
  return frames;
}

std::vector<MeasurementFrame> read_radar_plot_csv(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open plot CSV '" + path.string() + "'");
  return read_radar_plot_csv(in, path.string());
}

void write_radar_plot_csv(const std::filesystem::path& path, const std::vector<MeasurementFrame>& frames) {
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "w"), &std::fclose);
  if (!f) throw std::runtime_error("cannot create plot CSV '" + path.string() + "'");
  std::fprintf(f.get(), "time_s,range_m,bearing_rad,range_rate_mps,sensor_id\n");
  for (const MeasurementFrame& frame : frames) {
    for (const RadarPlotSi& p : frame.radar) {
      std::fprintf(f.get(), "%.6f,%.17g,%.17g,", frame.t_s, p.range_m, p.bearing_rad);
      if (p.range_rate_mps.has_value()) std::fprintf(f.get(), "%.17g", *p.range_rate_mps);
      std::fprintf(f.get(), ",%u\n", static_cast<unsigned>(p.sensor_id));
    }
  }
  if (std::ferror(f.get()) != 0) throw std::runtime_error("cannot write plot CSV '" + path.string() + "'");
}

}  // namespace kestrel::sim
