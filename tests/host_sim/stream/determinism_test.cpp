// SPDX-License-Identifier: Apache-2.0
// Reproducibility (docs/scenarios.md: a run is a function of its seed, bit
// for bit): the same seed gives the same stream bytes, another seed does not;
// Monte Carlo figures do not depend on the number of threads; and the plot
// CSV written from a stream replays to the same bytes.
#include <catch2/catch.hpp>
#include <filesystem>
#include <stdexcept>

#include "csv/radar_plot_csv.hpp"
#include "filters/filter_registry.hpp"
#include "montecarlo/monte_carlo.hpp"
#include "scenarios/registry.hpp"
#include "stream/quantise.hpp"
#include "stream/stream_writer.hpp"

using namespace kestrel::sim;  // NOLINT(google-build-using-namespace)

SCENARIO("Generated streams are reproducible", "[host_sim][stream]") {
  for (const char* name : {"s1", "s2", "s1n", "s2n"}) {
    GIVEN("scenario " << name) {
      const auto scenario = make_scenario(name);
      WHEN("it is generated twice with seed 42 and once with seed 43") {
        const auto a = encode_stream(scenario->generate(42).frames);
        const auto b = encode_stream(scenario->generate(42).frames);
        const auto c = encode_stream(scenario->generate(43).frames);
        THEN("the same seed gives identical bytes, another seed different bytes") {
          REQUIRE_FALSE(a.empty());
          CHECK(a == b);
          CHECK(a != c);
          CHECK(a.size() == c.size());
        }
      }
    }
  }
}

SCENARIO("Monte Carlo results do not depend on the thread count", "[host_sim][montecarlo]") {
  GIVEN("6 runs of S2 with EKF-CA") {
    const auto scenario = make_scenario("s2");
    const FilterEntry& filter = find_filter("ekf-ca");
    MonteCarloParams config;
    config.runs = 6;
    config.base_seed = 100;
    WHEN("run with 1 and with 3 worker threads") {
      config.jobs = 1;
      const auto one = run_monte_carlo(*scenario, filter, config);
      config.jobs = 3;
      const auto three = run_monte_carlo(*scenario, filter, config);
      THEN("every run's seed and figures are bit-identical") {
        REQUIRE(one.runs.size() == 6);
        REQUIRE(three.runs.size() == 6);
        for (std::size_t i = 0; i < 6; ++i) {
          CHECK(one.runs[i].seed == 100 + i);
          CHECK(three.runs[i].seed == one.runs[i].seed);
          CHECK(three.runs[i].metrics.rmse_m == one.runs[i].metrics.rmse_m);
          CHECK(three.runs[i].metrics.peak_m == one.runs[i].metrics.peak_m);
          CHECK(three.runs[i].metrics.nees_pos == one.runs[i].metrics.nees_pos);
        }
      }
    }
  }
}

SCENARIO("A plot CSV written from a stream replays to the same bytes", "[host_sim][stream][csv]") {
  GIVEN("S1 seed 3 as a stream and as the plot CSV `generate` writes") {
    const auto frames = make_scenario("s1")->generate(3).frames;
    const auto bytes = encode_stream(frames);
    std::vector<MeasurementFrame> wire_frames;
    for (const auto& f : frames) wire_frames.push_back(from_wire_frame(to_wire_frame(f)));
    const auto path = std::filesystem::temp_directory_path() / "kestrel_sim_roundtrip.plots.csv";
    write_radar_plot_csv(path, wire_frames);
    WHEN("the CSV is read back and encoded") {
      const auto replayed = encode_stream(read_radar_plot_csv(path));
      THEN("the bytes are those of the stream") { CHECK(replayed == bytes); }
    }
    std::filesystem::remove(path);
  }
}

SCENARIO("Quantisation to wire units", "[host_sim][stream]") {
  THEN("range rounds to the millimetre; a value the field cannot hold is refused, not clamped") {
    CHECK(to_wire_range_mm(1.2344) == 1234);
    CHECK(to_wire_range_mm(1.2346) == 1235);
    CHECK_THROWS_AS(to_wire_range_mm(-0.2), std::out_of_range);
    CHECK_THROWS_AS(to_wire_range_mm(4294967.296), std::out_of_range);
  }
  THEN("bearing maps to binary angle; +pi and -pi are the same direction") {
    CHECK(to_wire_bearing_bam(0.0) == 0);
    CHECK(to_wire_bearing_bam(3.14159265358979323846 / 2) == 1073741824);
    CHECK(to_wire_bearing_bam(-3.14159265358979323846 / 2) == -1073741824);
    CHECK(to_wire_bearing_bam(3.14159265358979323846) == INT32_MIN);
    CHECK(to_wire_bearing_bam(-3.14159265358979323846) == INT32_MIN);
  }
  THEN("time rounds to the microsecond") { CHECK(to_wire_time_us(149.5) == 149500000); }
}
