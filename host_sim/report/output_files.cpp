// SPDX-License-Identifier: Apache-2.0
#include "report/output_files.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace kestrel::sim {

std::ofstream open_out(const std::filesystem::path& path) {
  std::ofstream out(path, std::ios::trunc);
  if (!out) throw std::runtime_error("cannot create '" + path.string() + "'");
  out.precision(10);
  return out;
}

std::string csv_cell(double v) {
  if (!std::isfinite(v)) return "";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json interval_json(const MeanCi& m) {
  return {{"mean", number_or_null(m.mean)},
          {"ci95_low", number_or_null(m.ci95_low)},
          {"ci95_high", number_or_null(m.ci95_high)},
          {"n", m.n}};
}

nlohmann::json step_ns_json(const StepTiming& t) {
  return {{"min", t.min_ns},   {"median", t.median_ns}, {"p99", t.p99_ns},          {"max", t.max_ns},
          {"mean", t.mean_ns}, {"steps", t.steps},      {"budget_ns", t.budget_ns}, {"overruns", t.overruns}};
}

void write_json_file(const std::filesystem::path& path, const nlohmann::json& j) {
  std::ofstream out = open_out(path);
  out << j.dump(2) << '\n';
  if (!out) throw std::runtime_error("cannot write '" + path.string() + "'");
}

std::string format_number(const char* format, double v) {
  if (!std::isfinite(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string interval_text(const MeanCi& m, const char* format) {
  if (!std::isfinite(m.mean)) return "-";
  return format_number(format, m.mean) + " [" + format_number(format, m.ci95_low) + ", " +
         format_number(format, m.ci95_high) + "]";
}

}  // namespace kestrel::sim
