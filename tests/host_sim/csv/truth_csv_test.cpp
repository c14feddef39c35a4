// SPDX-License-Identifier: Apache-2.0
// Truth CSV reader (docs/host_sim.md): required and optional columns, z_m
// and unknown columns ignored, malformed rows by line number.
#include <catch2/catch.hpp>
#include <cmath>
#include <sstream>

#include "csv/csv_reader.hpp"
#include "csv/truth_csv.hpp"

using kestrel::sim::CsvError;
using kestrel::sim::read_truth_csv;

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
