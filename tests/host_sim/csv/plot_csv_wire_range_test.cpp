// SPDX-License-Identifier: Apache-2.0
// Plot CSV values the wire format cannot carry (issue: replay accepted a
// time_s of 1e13 with exit 0 and merged such rows into one frame; ranges,
// range rates and bearings were clamped or wrapped silently). Each must be
// an error naming file, line and column and what the wire field can carry.
// Test names carry "csv" so `ctest -R csv` picks them up.
#include <catch2/catch.hpp>
#include <numbers>
#include <sstream>
#include <string>

#include "csv/csv_reader.hpp"
#include "csv/radar_plot_csv.hpp"
#include "csv/truth_csv.hpp"
#include "stream/quantise.hpp"

using kestrel::sim::CsvError;
using kestrel::sim::read_radar_plot_csv;

namespace {

const std::string kHeader = "time_s,range_m,bearing_rad,range_rate_mps\n";
const std::string kGood = "0.0,1000,0.1,-5\n";

// The message of the CsvError the text raises, or "" when it parses.
std::string plot_error(const std::string& text) {
  std::istringstream in(text);
  try {
    (void)read_radar_plot_csv(in, "p.csv");
  } catch (const CsvError& e) {
    return e.what();
  }
  return "";
}

const std::string kTimeSpan = "[-9223372036854.774, 9223372036854.774] s (i64 microseconds)";
const std::string kRangeSpan = "[0, 4294967.295] m (u32 millimetres)";
const std::string kRateSpan = "[-2147483.648, 2147483.647] m/s (i32 mm/s)";
const std::string kBearingSpan =
    "[-6.283185307179586, 6.283185307179586] rad (one turn either way: the i32 binary angle holds [-pi, pi), "
    "a bearing beyond it is the same direction a turn away)";

}  // namespace

SCENARIO("Plot csv time_s the wire cannot carry is an error naming line and column", "[host_sim][csv]") {
  WHEN("time_s is 1e13 s, past int64 microseconds (line 3)") {
    THEN("the error names p.csv:3, the column, the text and the span") {
      CHECK(plot_error(kHeader + kGood + "1e13,1000,0.1,-5\n") ==
            "p.csv:3: column 'time_s': '1e13' is outside what the wire can carry, " + kTimeSpan);
    }
  }
  WHEN("time_s is 1e300 or -1e13 (line 2)") {
    THEN("each is the same error at line 2") {
      CHECK(plot_error(kHeader + "1e300,1000,0.1,-5\n") ==
            "p.csv:2: column 'time_s': '1e300' is outside what the wire can carry, " + kTimeSpan);
      CHECK(plot_error(kHeader + "-1e13,1000,0.1,-5\n") ==
            "p.csv:2: column 'time_s': '-1e13' is outside what the wire can carry, " + kTimeSpan);
    }
  }
  WHEN("time_s is too large even for a double") {
    THEN("the error says so") {
      CHECK(plot_error(kHeader + "1e400,1000,0.1,-5\n") ==
            "p.csv:2: column 'time_s': '1e400' is outside the range of a double");
    }
  }
  WHEN("time_s is just inside the span, 9223372036854.774 s and its negative") {
    THEN("it parses and the wire time is the nearest microsecond the double holds") {
      REQUIRE(plot_error(kHeader + "9223372036854.774,1000,0.1,-5\n").empty());
      REQUIRE(plot_error(kHeader + "-9223372036854.774,1000,0.1,-5\n").empty());
      CHECK(kestrel::sim::to_wire_time_us(9223372036854.774) == 9223372036854773760LL);
    }
  }
  WHEN("time_s is 9.3e12 s, just past the span") {
    THEN("it is refused") {
      CHECK(plot_error(kHeader + "9.3e12,1000,0.1,-5\n") ==
            "p.csv:2: column 'time_s': '9.3e12' is outside what the wire can carry, " + kTimeSpan);
    }
  }
}

SCENARIO("Plot csv NaN or Inf time_s is an error naming line and column", "[host_sim][csv]") {
  THEN("nan, inf and -inf are refused at their line") {
    CHECK(plot_error(kHeader + kGood + "nan,1000,0.1,-5\n") == "p.csv:3: column 'time_s': 'nan' is not finite");
    CHECK(plot_error(kHeader + "inf,1000,0.1,-5\n") == "p.csv:2: column 'time_s': 'inf' is not finite");
    CHECK(plot_error(kHeader + "-inf,1000,0.1,-5\n") == "p.csv:2: column 'time_s': '-inf' is not finite");
  }
}

SCENARIO("Plot csv range the wire cannot carry is an error and never clamped", "[host_sim][csv]") {
  WHEN("range_m is one millimetre past u32 millimetres (line 3)") {
    THEN("the error names the line, the column and the span") {
      CHECK(plot_error(kHeader + kGood + "0.5,4294967.296,0.1,-5\n") ==
            "p.csv:3: column 'range_m': '4294967.296' is outside what the wire can carry, " + kRangeSpan);
      CHECK(plot_error(kHeader + "0.5,1e9,0.1,-5\n") ==
            "p.csv:2: column 'range_m': '1e9' is outside what the wire can carry, " + kRangeSpan);
    }
  }
  WHEN("range_m is the largest the wire holds, 4294967.295 m") {
    std::istringstream in(kHeader + "0.5,4294967.295,0.1,-5\n");
    const auto frames = read_radar_plot_csv(in, "p.csv");
    THEN("it is kept, and reaches the wire as 2^32 - 1 mm") {
      REQUIRE(frames.size() == 1);
      CHECK(kestrel::sim::to_wire_frame(frames[0]).radar[0].range_mm == 4294967295u);
    }
  }
}

SCENARIO("Plot csv range rate the wire cannot carry is an error and never clamped", "[host_sim][csv]") {
  WHEN("range_rate_mps is 1e12 or -1e12 (line 3)") {
    THEN("the error names the line, the column and the span") {
      CHECK(plot_error(kHeader + kGood + "0.5,1000,0.1,1e12\n") ==
            "p.csv:3: column 'range_rate_mps': '1e12' is outside what the wire can carry, " + kRateSpan);
      CHECK(plot_error(kHeader + kGood + "0.5,1000,0.1,-1e12\n") ==
            "p.csv:3: column 'range_rate_mps': '-1e12' is outside what the wire can carry, " + kRateSpan);
    }
  }
  WHEN("range_rate_mps is one mm/s past int32 (2147483.648 m/s)") {
    THEN("it is refused, while the ends of int32 mm/s are kept") {
      CHECK(plot_error(kHeader + "0.5,1000,0.1,2147483.648\n") ==
            "p.csv:2: column 'range_rate_mps': '2147483.648' is outside what the wire can carry, " + kRateSpan);
      CHECK(plot_error(kHeader + "0.5,1000,0.1,2147483.647\n").empty());
      CHECK(plot_error(kHeader + "0.5,1000,0.1,-2147483.648\n").empty());
    }
  }
  WHEN("range_rate_mps is empty (not measured)") {
    THEN("there is nothing to check and no error") { CHECK(plot_error(kHeader + "0.5,1000,0.1,\n").empty()); }
  }
}

SCENARIO("Plot csv bearing beyond one turn is an error and within a turn wraps exactly", "[host_sim][csv]") {
  WHEN("bearing_rad is 1e10 rad (line 3)") {
    THEN("the error names the line, the column and the span") {
      CHECK(plot_error(kHeader + kGood + "0.5,1000,1e10,-5\n") ==
            "p.csv:3: column 'bearing_rad': '1e10' is outside what the wire can carry, " + kBearingSpan);
    }
  }
  WHEN("bearing_rad is 6.3 or -6.3 rad, just past a turn") {
    THEN("it is refused") {
      CHECK(plot_error(kHeader + "0.5,1000,6.3,-5\n") ==
            "p.csv:2: column 'bearing_rad': '6.3' is outside what the wire can carry, " + kBearingSpan);
      CHECK(plot_error(kHeader + "0.5,1000,-6.3,-5\n") ==
            "p.csv:2: column 'bearing_rad': '-6.3' is outside what the wire can carry, " + kBearingSpan);
    }
  }
  WHEN("bearing_rad is within a turn but outside [-pi, pi)") {
    std::istringstream in(kHeader + "0.5,1000,4.0,-5\n1.0,1000,3.141592653589793,-5\n1.5,1000,6.283185307179586,-5\n");
    const auto frames = read_radar_plot_csv(in, "p.csv");
    REQUIRE(frames.size() == 3);
    THEN("it reaches the wire as the same direction, the nearest binary angle of 4 - 2 pi") {
      // -1560706194 = round((4 - 2 pi) / (2 pi) * 2^32), computed to 50 digits.
      CHECK(kestrel::sim::to_wire_frame(frames[0]).radar[0].bearing_bam == -1560706194);
      CHECK(kestrel::sim::to_wire_bearing_bam(4.0 - 2.0 * std::numbers::pi) == -1560706194);
      CHECK(kestrel::sim::to_wire_frame(frames[1]).radar[0].bearing_bam == INT32_MIN);
      CHECK(kestrel::sim::to_wire_frame(frames[2]).radar[0].bearing_bam == 0);
    }
  }
}

SCENARIO("Plot csv with only a header gives no frames and no error", "[host_sim][csv]") {
  // The reader reports what the file holds; replay turns zero frames into a
  // warning and exit 3 (CTest kestrel_sim.cli.replay_header_only_csv_*).
  GIVEN("a header and nothing else, or a header and blank lines") {
    for (const std::string& text : {kHeader, kHeader + "\n\n"}) {
      std::istringstream in(text);
      CHECK(read_radar_plot_csv(in, "p.csv").empty());
    }
  }
}

SCENARIO("Plot csv rows at times the wire cannot carry no longer merge into one frame", "[host_sim][csv]") {
  WHEN("two rows are at 1e13 and 2e13 s (both rounded to the same garbage before)") {
    THEN("the first of them is an error at its line") {
      CHECK(plot_error(kHeader + kGood + "1e13,1000,0.1,-5\n2e13,1000,0.2,-5\n") ==
            "p.csv:3: column 'time_s': '1e13' is outside what the wire can carry, " + kTimeSpan);
    }
  }
  WHEN("two rows are at 1e300 and 1e13 s") {
    THEN("the first of them is an error at its line") {
      CHECK(plot_error(kHeader + "1e300,1000,0.1,-5\n1e13,1000,0.2,-5\n") ==
            "p.csv:2: column 'time_s': '1e300' is outside what the wire can carry, " + kTimeSpan);
    }
  }
  WHEN("rows one microsecond apart, and rows within one microsecond") {
    std::istringstream in(kHeader + "1.000001,1000,0.1,-5\n1.000002,1000,0.2,-5\n1.0000021,1000,0.3,-5\n");
    const auto frames = read_radar_plot_csv(in, "p.csv");
    THEN("a microsecond apart are two frames, the same microsecond is one") {
      REQUIRE(frames.size() == 2);
      CHECK(frames[0].radar.size() == 1);
      CHECK(frames[1].radar.size() == 2);
    }
  }
}

SCENARIO("Truth csv time_s the wire cannot carry is an error naming line and column", "[host_sim][csv]") {
  // Truth is matched to frames in wire microseconds, so it obeys the same span.
  std::istringstream in("time_s,x_m,y_m\n0.0,1,2\n1e13,1,2\n");
  try {
    (void)kestrel::sim::read_truth_csv(in, "t.csv");
    FAIL("no error");
  } catch (const CsvError& e) {
    CHECK(std::string(e.what()) == "t.csv:3: column 'time_s': '1e13' is outside what the wire can carry, " + kTimeSpan);
  }
}
