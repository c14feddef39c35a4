// SPDX-License-Identifier: Apache-2.0
// Truth CSV reader (docs/host_sim.md): required and optional columns, z_m
// and unknown columns ignored, malformed rows by line number; the truth of
// several targets (`target` column) written and read back.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "csv/csv_reader.hpp"
#include "csv/truth_csv.hpp"

using kestrel::sim::CsvError;
using kestrel::sim::read_targets_truth_csv;
using kestrel::sim::read_truth_csv;
using kestrel::sim::TruthSample;

SCENARIO("Truth CSV files", "[host_sim][csv]") {
  GIVEN("positions with velocity, depth and an unknown column") {
    std::istringstream in("time_s,x_m,y_m,z_m,vx_mps,vy_mps,note\n0,1,2,3,4,5,a\n0.5,3,4,3,4,5,b\n");
    const auto truth = read_truth_csv(in, "t.csv");
    THEN("every row is read") {
      REQUIRE(truth.size() == 2);
      CHECK(truth[1].t_s == 0.5);
      CHECK(truth[1].x_m == 3.0);
      CHECK(truth[1].vy_mps == 5.0);
    }
  }
  GIVEN("positions only") {
    std::istringstream in("time_s,x_m,y_m\n0,1,2\n");
    const auto truth = read_truth_csv(in, "t.csv");
    THEN("velocity is NaN (unknown)") {
      REQUIRE(truth.size() == 1);
      CHECK(std::isnan(truth[0].vx_mps));
    }
  }
  GIVEN("a row whose time does not increase (line 3)") {
    std::istringstream in("time_s,x_m,y_m\n1,1,2\n1,1,2\n");
    THEN("reading fails naming line 3") {
      try {
        (void)read_truth_csv(in, "t.csv");
        FAIL("no error");
      } catch (const CsvError& e) {
        CHECK(e.line() == 3);
      }
    }
  }
  GIVEN("a malformed number on line 2") {
    std::istringstream in("time_s,x_m,y_m\n0,1,2x\n");
    THEN("reading fails naming line 2") {
      try {
        (void)read_truth_csv(in, "t.csv");
        FAIL("no error");
      } catch (const CsvError& e) {
        CHECK(e.line() == 2);
      }
    }
  }
}

namespace {
/// The line of the CsvError that reading `text` as a truth of several targets throws, or 0.
std::size_t targets_error_line(const std::string& text) {
  std::istringstream in(text);
  try {
    (void)read_targets_truth_csv(in, "t.csv");
  } catch (const CsvError& e) {
    return e.line();
  }
  return 0;
}
}  // namespace

SCENARIO("Truth CSV files of several targets", "[host_sim][csv]") {
  GIVEN("two targets written by write_targets_truth_csv") {
    const std::vector<std::vector<TruthSample>> targets{
        {{0.0, -1041.889066001582, 15908.846518073249, 34.72963553338608, -196.9615506024416},
         {1.0, -1007.1594304681424, 15711.884967470967, 34.7, -196.9}},
        {{0.0, 1041.889066001582, 15908.846518073249, -34.729635533386059, -196.9615506024416},
         {1.0, 1007.1594304681424, 15711.884967470967, -34.7, -196.9}}};
    const std::filesystem::path path = std::filesystem::temp_directory_path() / "kestrel_targets_truth.csv";
    kestrel::sim::write_targets_truth_csv(path, targets);
    THEN("they read back bit for bit, and the single-target reader refuses the file") {
      CHECK(kestrel::sim::truth_csv_has_targets(path));
      const auto back = read_targets_truth_csv(path);
      REQUIRE(back.size() == 2);
      for (std::size_t i = 0; i < 2; ++i) {
        REQUIRE(back[i].size() == 2);
        for (std::size_t k = 0; k < 2; ++k) {
          CHECK(back[i][k].t_s == targets[i][k].t_s);
          CHECK(back[i][k].x_m == targets[i][k].x_m);
          CHECK(back[i][k].y_m == targets[i][k].y_m);
          CHECK(back[i][k].vx_mps == targets[i][k].vx_mps);
        }
      }
      try {
        (void)read_truth_csv(path);
        FAIL("a truth of several targets read as one target's");
      } catch (const CsvError& e) {
        CHECK(e.line() == 1);
      }
    }
    std::filesystem::remove(path);
  }
  GIVEN("malformed truths of several targets") {
    THEN("each is refused at its line") {
      // An id that is not a whole number, one out of range, a time that does
      // not increase within a target, a missing id, no target column.
      CHECK(targets_error_line("time_s,target,x_m,y_m\n0,0,1,2\n0,1.5,1,2\n") == 3);
      CHECK(targets_error_line("time_s,target,x_m,y_m\n0,-1,1,2\n") == 2);
      CHECK(targets_error_line("time_s,target,x_m,y_m\n0,0,1,2\n0,1,1,2\n0,1,1,2\n") == 4);
      CHECK(targets_error_line("time_s,target,x_m,y_m\n0,0,1,2\n0,2,1,2\n") > 0);
      CHECK(targets_error_line("time_s,x_m,y_m\n0,1,2\n") == 1);
      CHECK(targets_error_line("time_s,target,x_m,y_m\n0,0,1,2\n0,1,1,2\n1,0,1,2\n1,1,1,2\n") == 0);
    }
  }
}
