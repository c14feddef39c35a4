// SPDX-License-Identifier: Apache-2.0
#include "csv/truth_csv.hpp"

#include <cstdio>
#include <fstream>
#include <limits>
#include <memory>
#include <stdexcept>
#include <utility>

#include "csv/csv_reader.hpp"
#include "stream/quantise.hpp"

namespace kestrel::sim {

namespace {

/// The rows of a truth CSV, each with its target id (0 without a `target`
/// column); every target's times increase from row to row.
std::vector<std::vector<TruthSample>> read_rows(std::istream& in, const std::string& source, bool targets) {
  CsvReader csv(in, source);
  const std::size_t c_time = csv.require_column("time_s");
  const std::size_t c_x = csv.require_column("x_m");
  const std::size_t c_y = csv.require_column("y_m");
  const auto c_vx = csv.find_column("vx_mps");
  const auto c_vy = csv.find_column("vy_mps");
  const auto c_target = csv.find_column("target");
  if (!targets && c_target.has_value()) {
    csv.fail("has a target column: the truth of several targets, which a single-target run cannot score");
  }
  if (targets && !c_target.has_value()) csv.fail("has no target column");
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

  std::vector<std::vector<TruthSample>> truth;
  while (csv.next()) {
    const std::size_t id =
        c_target.has_value() ? static_cast<std::size_t>(csv.integer(*c_target, 0, kMaxTruthTargets - 1)) : 0;
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
    if (id >= truth.size()) truth.resize(id + 1);
    if (!truth[id].empty() && s.t_s <= truth[id].back().t_s) {
      csv.fail(c_target.has_value() ? "time_s must increase from row to row of each target"
                                    : "time_s must increase from row to row");
    }
    truth[id].push_back(s);
  }
  for (std::size_t i = 0; i < truth.size(); ++i) {
    if (truth[i].empty()) {
      csv.fail("target " + std::to_string(i) + " has no row (the ids must be 0.." + std::to_string(truth.size() - 1) +
               ", each with rows)");
    }
  }
  return truth;
}

}  // namespace

std::vector<TruthSample> read_truth_csv(std::istream& in, const std::string& source) {
  std::vector<std::vector<TruthSample>> rows = read_rows(in, source, false);
  return rows.empty() ? std::vector<TruthSample>{} : std::move(rows.front());
}

bool truth_csv_has_targets(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open truth CSV '" + path.string() + "'");
  const CsvReader csv(in, path.string());
  return csv.find_column("target").has_value();
}

std::vector<std::vector<TruthSample>> read_targets_truth_csv(std::istream& in, const std::string& source) {
  return read_rows(in, source, true);
}

std::vector<std::vector<TruthSample>> read_targets_truth_csv(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open truth CSV '" + path.string() + "'");
  return read_rows(in, path.string(), true);
}

void write_targets_truth_csv(const std::filesystem::path& path, const std::vector<std::vector<TruthSample>>& targets) {
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "w"), &std::fclose);
  if (!f) throw std::runtime_error("cannot create truth CSV '" + path.string() + "'");
  std::fprintf(f.get(), "time_s,target,x_m,y_m,vx_mps,vy_mps\n");
  const std::size_t times = targets.empty() ? 0 : targets.front().size();
  for (std::size_t k = 0; k < times; ++k) {
    for (std::size_t i = 0; i < targets.size(); ++i) {
      const TruthSample& s = targets[i].at(k);
      std::fprintf(f.get(), "%.6f,%zu,%.17g,%.17g,%.17g,%.17g\n", s.t_s, i, s.x_m, s.y_m, s.vx_mps, s.vy_mps);
    }
  }
  if (std::ferror(f.get()) != 0) throw std::runtime_error("cannot write truth CSV '" + path.string() + "'");
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
