// SPDX-License-Identifier: Apache-2.0
// Radar plot CSV reader (docs/host_sim.md): frames from equal times,
// optional columns, unknown columns ignored, and a malformed row reported
// with its line number (never skipped).
#include <catch2/catch.hpp>
#include <sstream>
#include <string>

#include "csv/csv_reader.hpp"
#include "csv/radar_plot_csv.hpp"

using kestrel::sim::CsvError;
using kestrel::sim::read_radar_plot_csv;

namespace {
std::size_t error_line(const std::string& text) {
  std::istringstream in(text);
  try {
    (void)read_radar_plot_csv(in, "test.csv");
  } catch (const CsvError& e) {
    INFO(e.what());
    CHECK(std::string(e.what()).find("test.csv:" + std::to_string(e.line()) + ":") == 0);
    return e.line();
  }
  return 0;  // no error
}
}  // namespace

SCENARIO("A good plot CSV parses into frames", "[host_sim][csv]") {
  GIVEN("rows at 0.0, 0.0, 0.5 s with every optional column, in a free order") {
    std::istringstream in(
        "sensor_id,time_s,bearing_rad,range_m,range_rate_mps\n"
        "0,0.0,0.5,1000.0,-12.5\n"
        "1,0.0,-0.25,2000.5,\n"
        "\n"
        "0,0.5,0.51,1001.0,-12.0\n");
    const auto frames = read_radar_plot_csv(in, "good.csv");
    THEN("rows with the same time form one frame, in file order") {
      REQUIRE(frames.size() == 2);
      REQUIRE(frames[0].radar.size() == 2);
      REQUIRE(frames[1].radar.size() == 1);
      CHECK(frames[0].t_s == 0.0);
      CHECK(frames[1].t_s == 0.5);
    }
    THEN("every column lands in its field; an empty range rate means not measured") {
      CHECK(frames[0].radar[0].range_m == 1000.0);
      CHECK(frames[0].radar[0].bearing_rad == 0.5);
      REQUIRE(frames[0].radar[0].range_rate_mps.has_value());
      CHECK(*frames[0].radar[0].range_rate_mps == -12.5);
      CHECK(frames[0].radar[1].sensor_id == 1);
      CHECK_FALSE(frames[0].radar[1].range_rate_mps.has_value());
    }
  }
  GIVEN("only the three required columns plus unknown ones") {
    std::istringstream in(
        "time_s,range_m,bearing_rad,snr_db,comment\n"
        "1.0,500,0.1,13.2,first look\n"
        "2.0,510,0.1,n/a,second\n");
    const auto frames = read_radar_plot_csv(in, "extra.csv");
    THEN("the unknown columns are ignored, whatever they hold") {
      REQUIRE(frames.size() == 2);
      CHECK(frames[1].radar[0].range_m == 510.0);
      CHECK_FALSE(frames[1].radar[0].range_rate_mps.has_value());
    }
  }
}

SCENARIO("A malformed plot CSV is an error naming its line", "[host_sim][csv]") {
  const std::string header = "time_s,range_m,bearing_rad\n";
  const std::string good = "0.0,1000,0.1\n";
  WHEN("a value is not a number (line 3)") {
    THEN("the error names line 3") { CHECK(error_line(header + good + "0.5,abc,0.1\n") == 3); }
  }
  WHEN("a number has trailing junk (line 2)") {
    THEN("the error names line 2") { CHECK(error_line(header + "0.0,1000m,0.1\n") == 2); }
  }
  WHEN("a row has too few fields (line 4, after a blank line)") {
    THEN("the error names line 4") { CHECK(error_line(header + good + "\n0.5,1000\n") == 4); }
  }
  WHEN("a required value is empty") {
    THEN("the error names its line") { CHECK(error_line(header + ",1000,0.1\n") == 2); }
  }
  WHEN("a value is NaN or infinite (the wire format cannot carry it)") {
    THEN("the error names its line") {
      CHECK(error_line(header + good + "0.5,nan,0.1\n") == 3);
      CHECK(error_line(header + "0.5,1000,inf\n") == 2);
    }
  }
  WHEN("a range is negative") {
    THEN("the error names its line") { CHECK(error_line(header + good + good + "1.0,-1,0.1\n") == 4); }
  }
  WHEN("sensor_id is outside 0..255") {
    THEN("the error names its line") { CHECK(error_line("time_s,range_m,bearing_rad,sensor_id\n0,1,0,256\n") == 2); }
  }
  WHEN("a required column is missing") {
    THEN("the error names the header, line 1") { CHECK(error_line("time_s,range_m\n0,1\n") == 1); }
  }
  WHEN("a frame holds more plots than a wire frame (33 rows at one time)") {
    std::string text = header;
    for (int i = 0; i < 33; ++i) text += "0.0,1000,0.1\n";
    THEN("the error names the 33rd row, line 34") { CHECK(error_line(text) == 34); }
  }
  WHEN("the file is well formed") {
    THEN("there is no error") { CHECK(error_line(header + good) == 0); }
  }
}
