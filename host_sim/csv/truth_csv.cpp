// SPDX-License-Identifier: Apache-2.0
#include "csv/truth_csv.hpp"

#include <cstdio>
#include <fstream>
#include <limits>
#include <memory>
#include <stdexcept>

#include "csv/csv_reader.hpp"
#include "stream/quantise.hpp"

namespace kestrel::sim {

std::vector<TruthSample> read_truth_csv(std::istream& in, const std::string& source) {
  CsvReader csv(in, source);
  const std::size_t c_time = csv.require_column("time_s");
  const std::size_t c_x = csv.require_column("x_m");
  const std::size_t c_y = csv.require_column("y_m");
  const auto c_vx = csv.find_column("vx_mps");
  const auto c_vy = csv.find_column("vy_mps");
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

  std::vector<TruthSample> truth;
  while (csv.next()) {
    TruthSample s;
    s.t_s = csv.number(c_time);
    // Truth is matched to frames in wire microseconds (metrics/scoring.cpp),
    // so its time must convert as a frame time does.
    if (!try_wire_time_us(s.t_s).has_value()) {
      csv.fail_cell(c_time, "is outside what the wire can carry, " + std::string(kWireTimeSpan));
    }
    s.x_m = csv.number(c_x);
    s.y_m = csv.number(c_y);
    s.vx_mps = c_vx.has_value() ? csv.optional_number(*c_vx).value_or(kNaN) : kNaN;
    s.vy_mps = c_vy.has_value() ? csv.optional_number(*c_vy).value_or(kNaN) : kNaN;
    if (!truth.empty() && s.t_s <= truth.back().t_s) csv.fail("time_s must increase from row to row");
    truth.push_back(s);
  }
  return truth;
}

std::vector<TruthSample> read_truth_csv(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open truth CSV '" + path.string() + "'");
  return read_truth_csv(in, path.string());
}

void write_truth_csv(const std::filesystem::path& path, const std::vector<TruthSample>& truth) {
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "w"), &std::fclose);
  if (!f) throw std::runtime_error("cannot create truth CSV '" + path.string() + "'");
  std::fprintf(f.get(), "time_s,x_m,y_m,vx_mps,vy_mps\n");
  for (const TruthSample& s : truth) {
    std::fprintf(f.get(), "%.6f,%.17g,%.17g,%.17g,%.17g\n", s.t_s, s.x_m, s.y_m, s.vx_mps, s.vy_mps);
  }
  if (std::ferror(f.get()) != 0) throw std::runtime_error("cannot write truth CSV '" + path.string() + "'");
}

}  // namespace kestrel::sim
