#include "csv/radar_plot_csv.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <stdexcept>

#include "csv/csv_reader.hpp"
#include "kestrel/hal/frame.hpp"

namespace kestrel::sim {

std::vector<MeasurementFrame> read_radar_plot_csv(std::istream& in, const std::string& source) {
  CsvReader csv(in, source);
  const std::size_t c_time = csv.require_column("time_s");
  const std::size_t c_range = csv.require_column("range_m");
  const std::size_t c_bearing = csv.require_column("bearing_rad");
  const auto c_rate = csv.find_column("range_rate_mps");
  const auto c_sensor = csv.find_column("sensor_id");

  std::vector<MeasurementFrame> frames;
  while (csv.next()) {
    const double t_s = csv.number(c_time);
    RadarPlotSi plot;
    plot.range_m = csv.number(c_range);
    if (plot.range_m < 0.0) csv.fail("column 'range_m': a range cannot be negative");
    plot.bearing_rad = csv.number(c_bearing);
    if (c_rate.has_value()) plot.range_rate_mps = csv.optional_number(*c_rate);
    if (c_sensor.has_value()) plot.sensor_id = static_cast<std::uint8_t>(csv.integer(*c_sensor, 0, 255));

    // Same time as the previous row (compared in wire microseconds, the
    // resolution a frame has): same frame.
    const bool same_frame = !frames.empty() && std::llround(frames.back().t_s * 1e6) == std::llround(t_s * 1e6);
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
