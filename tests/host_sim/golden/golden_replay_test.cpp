// SPDX-License-Identifier: Apache-2.0
// Golden replays, one per sensor kind and scalar: a generated run (seed 1)
// encoded to wire bytes and driven through the board loop (StreamFileFeed ->
// adapter -> tracker -> sink, inside hal::Runner), its reports compared row
// by row with the file recorded in tests/host_sim/data/golden/. Any change of
// behaviour, wanted or not, shows here: a deliberate one is re-recorded with
//   KESTREL_UPDATE_GOLDEN=1 build/host-release/tests/host_sim/kestrel_sim_tests "[golden]"
// and the diff of the files goes into the commit.
//
// Tolerance, per real value: |a - b| <= rtol (1 + max(|a|, |b|)), with rtol
// 1e-9 for double, 1e-4 for float and 1e-12 for fixed point (whose
// arithmetic is integer, so equal on every host; the files print 17
// significant digits). Counts, ids, masks and statuses must be equal. The
// tolerance is for another libm (a last-bit difference in sin/cos/atan2
// that the filter carries on), not for a change in the tracker.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "filters/filter_registry.hpp"
#include "montecarlo/pcl_run.hpp"
#include "montecarlo/single_run.hpp"
#include "montecarlo/sonar_run.hpp"
#include "scenarios/registry.hpp"

namespace {

using namespace kestrel::sim;  // NOLINT(google-build-using-namespace)

/// One table: rows of numbers, the first `exact_columns` compared exactly.
struct Table {
  std::string header;
  std::vector<std::vector<double>> rows;
};

std::string golden_path(const std::string& name) {
  // Appended one piece at a time: GCC 12 warns (-Warray-bounds, a known
  // false positive) on the chained operator+ of a literal-built string.
  std::string path(KESTREL_GOLDEN_DIR);
  path += '/';
  path += name;
  path += ".csv";
  return path;
}

void write_table(const std::string& name, const Table& t) {
  std::ofstream f(golden_path(name));
  REQUIRE(f.good());
  f << t.header << '\n';
  char buf[64];
  for (const auto& row : t.rows) {
    for (std::size_t i = 0; i < row.size(); ++i) {
      std::snprintf(buf, sizeof buf, "%.17g", row[i]);
      f << (i ? "," : "") << buf;
    }
    f << '\n';
  }
}

Table read_table(const std::string& name) {
  std::ifstream f(golden_path(name));
  INFO("golden file " << golden_path(name));
  REQUIRE(f.good());
  Table t;
  std::getline(f, t.header);
  std::string line;
  while (std::getline(f, line)) {
    std::vector<double> row;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) row.push_back(std::strtod(cell.c_str(), nullptr));
    t.rows.push_back(row);
  }
  return t;
}

/// Compare `now` with the recorded table (or record it).
void check_golden(const std::string& name, const Table& now, std::size_t exact_columns, double rtol) {
  if (const char* update = std::getenv("KESTREL_UPDATE_GOLDEN"); update != nullptr && *update != '\0') {
    write_table(name, now);
    WARN("recorded " << golden_path(name));
  }
  const Table want = read_table(name);
  INFO(name << ": " << now.rows.size() << " rows now, " << want.rows.size() << " recorded");
  REQUIRE(now.header == want.header);
  REQUIRE(now.rows.size() == want.rows.size());
  REQUIRE(!now.rows.empty());
  std::size_t worst_row = 0;
  std::size_t worst_col = 0;
  double worst = 0.0;  // largest |a - b| / (1 + max(|a|, |b|)) over the real columns
  bool exact_ok = true;
  for (std::size_t r = 0; r < now.rows.size(); ++r) {
    REQUIRE(now.rows[r].size() == want.rows[r].size());
    for (std::size_t c = 0; c < now.rows[r].size(); ++c) {
      const double a = now.rows[r][c];
      const double b = want.rows[r][c];
      if (std::isnan(a) || std::isnan(b)) {
        exact_ok = exact_ok && std::isnan(a) && std::isnan(b);
        continue;
      }
      if (c < exact_columns) {
        if (a != b) {
          exact_ok = false;
          UNSCOPED_INFO("row " << r << " column " << c << ": " << a << " recorded " << b);
        }
        continue;
      }
      const double e = std::abs(a - b) / (1.0 + std::max(std::abs(a), std::abs(b)));
      if (e > worst) {
        worst = e;
        worst_row = r;
        worst_col = c;
      }
    }
  }
  INFO("largest relative difference " << worst << " at row " << worst_row << ", column " << worst_col
                                      << " (tolerance " << rtol << ")");
  CHECK(exact_ok);
  CHECK(worst <= rtol);
}

/// Radar: S2, seed 1, qj 50, confirmed gate d2 16, every confirmed report.
Table radar_table(const char* filter) {
  const auto scenario = make_scenario("s2");
  FilterOptions options;
  options.qj = 50.0;
  options.confirmed_gate_d2 = 16.0;
  const RunDetail d = run_scenario_once(*scenario, 1, find_filter(filter), options, 1000000000, ScoringParams{});
  Table t{"frame,status,track_id,confirmed,associated,measurement_index,age,hits,misses,x_m,y_m,vx_mps,vy_mps,"
          "p_xx,p_xy,p_yy,nis",
          {}};
  for (std::size_t k = 0; k < d.stream.frames.size(); ++k) {
    const auto& f = d.stream.frames[k];
    if (f.tracks.empty()) {
      t.rows.push_back({static_cast<double>(k), static_cast<double>(f.status), 0, 0, 0, -1, 0, 0, 0, 0, 0, 0, 0,
                        0, 0, 0, 0});
    }
    for (const auto& r : f.tracks) {
      t.rows.push_back({static_cast<double>(k), static_cast<double>(f.status), static_cast<double>(r.track_id),
                        r.confirmed ? 1.0 : 0.0, r.associated ? 1.0 : 0.0, static_cast<double>(r.measurement_index),
                        static_cast<double>(r.age), static_cast<double>(r.hits), static_cast<double>(r.misses),
                        r.x_m, r.y_m, r.vx_mps, r.vy_mps, r.p_xx, r.p_xy, r.p_yy, r.nis});
    }
  }
  return t;
}

}  // namespace

TEST_CASE("Golden replay: radar S2 through the board loop, EKF-CA in double, float and Q31.32",
          "[host_sim][golden]") {
  check_golden("radar_s2_ekf-ca", radar_table("ekf-ca"), 9, 1e-9);
  check_golden("radar_s2_ekf-ca-f32", radar_table("ekf-ca-f32"), 9, 1e-4);
  check_golden("radar_s2_ekf-ca-q31_32", radar_table("ekf-ca-q31_32"), 9, 1e-12);
  check_golden("radar_s2_r2aekf", radar_table("r2aekf"), 9, 1e-9);
}

TEST_CASE("Golden replay: PCL pcl002 through the board loop, default policies", "[host_sim][golden]") {
  const PclScenarioParams c = pcl002_config();
  const PclScenarioRun run = generate_pcl(c, 1);
  const PclRunOutput out = run_pcl(run, c, pcl_params_for(c), TrackerPolicies{}, 1000000000);
  Table t{"frame,status,scan_count,tracks_in_table,track_id,associated,frame_index,age,hits,misses,rb_m,drb_mps,"
          "p_rr,p_rd,p_dd,nis",
          {}};
  for (std::size_t k = 0; k < out.frames.size(); ++k) {
    const auto& f = out.frames[k];
    const double head[] = {static_cast<double>(k), static_cast<double>(f.status), static_cast<double>(f.scan_count),
                           static_cast<double>(f.tracks_in_table)};
    if (f.tracks.empty()) t.rows.push_back({head[0], head[1], head[2], head[3], 0, 0, -1, 0, 0, 0, 0, 0, 0, 0, 0, 0});
    for (const auto& r : f.tracks) {
      t.rows.push_back({head[0], head[1], head[2], head[3], static_cast<double>(r.id), r.associated ? 1.0 : 0.0,
                        static_cast<double>(r.frame_index), static_cast<double>(r.age), static_cast<double>(r.hits),
                        static_cast<double>(r.misses), r.rb_m, r.drb_mps, r.p_rr, r.p_rd, r.p_dd, r.nis});
    }
  }
  check_golden("pcl_pcl002", t, 10, 1e-9);
}

TEST_CASE("Golden replay: sonar uw003 through the board loop, the default sonar tracker",
          "[host_sim][golden]") {
  const SonarScenarioParams c = uw003_config();
  const SonarScenarioRun run = generate_sonar(c, 1);
  const SonarRunOutput out = run_sonar(run, sonar_params_for(c), 1000000000);
  Table t{"frame,status,reported,initialised,predict_only,present,fused,gated,x_m,y_m,z_m,vx_mps,vy_mps,vz_mps,c_mps,"
          "sd_x,sd_y,sd_z,sd_vx,sd_vy,sd_vz,sd_c,nis",
          {}};
  for (std::size_t k = 0; k < out.frames.size(); ++k) {
    const auto& f = out.frames[k];
    std::vector<double> row{static_cast<double>(k),         static_cast<double>(f.status),
                            f.reported ? 1.0 : 0.0,         f.initialised ? 1.0 : 0.0,
                            f.predict_only ? 1.0 : 0.0,     static_cast<double>(f.present),
                            static_cast<double>(f.fused),   static_cast<double>(f.gated)};
    for (double v : f.x) row.push_back(v);
    for (double v : f.sd) row.push_back(v);
    row.push_back(f.nis);
    t.rows.push_back(row);
  }
  check_golden("sonar_uw003", t, 8, 1e-9);
}
