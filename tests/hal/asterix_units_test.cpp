// SPDX-License-Identifier: Apache-2.0
// ASTERIX unit conversions (asterix_units.hpp): the azimuth convention at
// the four cardinal directions and over every azimuth, time of day and
// range scalings against hand-computed values.
#include "kestrel/hal/asterix_units.hpp"

#include <catch2/catch.hpp>
#include <cstdint>

#include "kestrel/hal/frame.hpp"

namespace ax = kestrel::hal::asterix;

SCENARIO("ASTERIX azimuth clockwise from north becomes Kestrel bearing counter-clockwise from east", "[hal][asterix]") {
  // North is +90 deg from east, east 0, south -90, west -180 (int32 min).
  STATIC_REQUIRE(ax::bearing_bam_from_azimuth(0x0000) == 0x40000000);
  STATIC_REQUIRE(ax::bearing_bam_from_azimuth(0x4000) == 0);
  STATIC_REQUIRE(ax::bearing_bam_from_azimuth(0x8000) == -0x40000000);
  STATIC_REQUIRE(ax::bearing_bam_from_azimuth(0xC000) == INT32_MIN);
  // Radians, as the radar adapter sees them.
  CHECK(ax::bearing_bam_from_azimuth(0x0000) * kestrel::hal::kRadPerBam == Approx(3.14159265358979 / 2).epsilon(1e-15));
  CHECK(ax::bearing_bam_from_azimuth(0xC000) * kestrel::hal::kRadPerBam == Approx(-3.14159265358979).epsilon(1e-15));
  // The inverse at the same four points.
  STATIC_REQUIRE(ax::azimuth_from_bearing_bam(0x40000000) == 0x0000);
  STATIC_REQUIRE(ax::azimuth_from_bearing_bam(0) == 0x4000);
  STATIC_REQUIRE(ax::azimuth_from_bearing_bam(-0x40000000) == 0x8000);
  STATIC_REQUIRE(ax::azimuth_from_bearing_bam(INT32_MIN) == 0xC000);
}

SCENARIO("every ASTERIX azimuth round-trips through the Kestrel bearing", "[hal][asterix]") {
  int mismatches = 0;
  for (std::uint32_t t = 0; t <= 0xFFFFu; ++t) {
    const auto theta = static_cast<std::uint16_t>(t);
    if (ax::azimuth_from_bearing_bam(ax::bearing_bam_from_azimuth(theta)) != theta) ++mismatches;
  }
  CHECK(mismatches == 0);
  // Half an azimuth LSB either side of north rounds to north, across the wrap.
  CHECK(ax::azimuth_from_bearing_bam(0x40000000 + 0x7FFF) == 0);
  CHECK(ax::azimuth_from_bearing_bam(0x40000000 - 0x7FFF) == 0);
  CHECK(ax::azimuth_from_bearing_bam(0x40000000 - 0x8000) == 1);
}

SCENARIO("time of day in 1/128 s becomes microseconds and back", "[hal][asterix]") {
  STATIC_REQUIRE(ax::t_us_from_time_of_day(0) == 0);
  STATIC_REQUIRE(ax::t_us_from_time_of_day(128) == 1'000'000);
  STATIC_REQUIRE(ax::t_us_from_time_of_day(1) == 7813);  // 7812.5 rounds half up
  STATIC_REQUIRE(ax::t_us_from_time_of_day(ax::kDayTod128 - 1) == 86'399'992'188);
  int mismatches = 0;
  for (std::uint32_t tod = 0; tod < ax::kDayTod128; tod += 997) {
    if (ax::time_of_day_from_t_us(ax::t_us_from_time_of_day(tod)) != tod) ++mismatches;
  }
  CHECK(mismatches == 0);
}

SCENARIO("range in 1/256 NM becomes millimetres", "[hal][asterix]") {
  STATIC_REQUIRE(ax::range_mm_from_rho(256) == 1'852'000);  // 1 NM
  STATIC_REQUIRE(ax::range_mm_from_rho(1) == 7234);          // 7234.375
  STATIC_REQUIRE(ax::range_mm_from_rho(0xFFFF) == 474'104'766);  // 65535 x 7234.375 = 474104765.625
  STATIC_REQUIRE(ax::rho_from_range_mm(1'852'000) == 256);
  STATIC_REQUIRE(ax::rho_from_range_mm(0xFFFFFFFFu) == 0xFFFF);
  int mismatches = 0;
  for (std::uint32_t r = 0; r <= 0xFFFFu; ++r) {
    if (ax::rho_from_range_mm(ax::range_mm_from_rho(static_cast<std::uint16_t>(r))) != r) ++mismatches;
  }
  CHECK(mismatches == 0);
}
