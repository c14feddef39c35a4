// SPDX-License-Identifier: Apache-2.0
// ASTERIX units to Kestrel wire units and back (EUROCONTROL ASTERIX Part 1
// and Part 4, CAT048 items I048/140 and I048/040). ASTERIX measures
// azimuth clockwise from north; Kestrel's bearing is counter-clockwise from
// +x (east), with y north. This header is the one place that conversion and
// the time-of-day and range scalings happen; readers and writers call it.
// Integer only: exact on a board without an FPU.
#pragma once

#include <cstddef>
#include <cstdint>

namespace kestrel::hal::asterix {

/// Every data block opens with CAT (1 byte) and LEN (2 bytes, big-endian,
/// counting the whole block).
inline constexpr std::size_t kBlockHeaderSize = 3;

/// Kestrel bearing from an ASTERIX azimuth.
/// @param theta azimuth, clockwise from north, 2^16 units per turn (I048/040 THETA).
/// @return bearing, counter-clockwise from +x (east), binary angle (2^32 per
///         turn, RadarPlot::bearing_bam). Exact: bearing = 90 deg - theta.
constexpr std::int32_t bearing_bam_from_azimuth(std::uint16_t theta) {
  // Modulo 2^32 arithmetic is the turn's wrap; the conversion to int32 is
  // modular (C++20), so 270 deg becomes -180 deg, not an overflow.
  return static_cast<std::int32_t>(0x40000000u - (static_cast<std::uint32_t>(theta) << 16));
}

/// ASTERIX azimuth from a Kestrel bearing: the inverse of
/// bearing_bam_from_azimuth, rounded to the nearest 2^-16 turn.
/// @param bearing_bam counter-clockwise from +x (east), binary angle.
/// @return azimuth clockwise from north, 2^16 units per turn.
constexpr std::uint16_t azimuth_from_bearing_bam(std::int32_t bearing_bam) {
  const std::uint32_t cw_from_north = 0x40000000u - static_cast<std::uint32_t>(bearing_bam);
  return static_cast<std::uint16_t>(((cw_from_north + 0x8000u) >> 16) & 0xFFFFu);
}

/// Time of day (1/128 s since midnight, 24 bits: I048/140, I062/070) to
/// microseconds, rounded half up (one LSB is 7812.5 us).
constexpr std::int64_t t_us_from_time_of_day(std::uint32_t tod_128) {
  return (static_cast<std::int64_t>(tod_128) * 15625 + 1) / 2;
}

/// A day, the range of an ASTERIX time of day, in us and in 1/128 s.
inline constexpr std::int64_t kDayUs = 86'400'000'000;
inline constexpr std::uint32_t kDayTod128 = 86'400u * 128u;

/// Microseconds since midnight to time of day in 1/128 s, rounded to
/// nearest. Caller checks 0 <= t_us < kDayUs (the writer refuses others).
constexpr std::uint32_t time_of_day_from_t_us(std::int64_t t_us) {
  return static_cast<std::uint32_t>((t_us * 16 + 62'500) / 125'000);
}

/// Slant range in 1/256 NM (I048/040 RHO, 1 NM = 1852 m exactly) to
/// millimetres, rounded half up (one LSB is 7234.375 mm).
constexpr std::uint32_t range_mm_from_rho(std::uint16_t rho_256nm) {
  return static_cast<std::uint32_t>((static_cast<std::uint64_t>(rho_256nm) * 1'852'000u + 128u) / 256u);
}

/// Millimetres to 1/256 NM, rounded to nearest; saturates at the item's
/// 0xFFFF (256 NM). For writers and tests; the reader never needs it.
constexpr std::uint16_t rho_from_range_mm(std::uint32_t range_mm) {
  const std::uint64_t rho = (static_cast<std::uint64_t>(range_mm) * 256u + 926'000u) / 1'852'000u;
  return rho > 0xFFFFu ? std::uint16_t{0xFFFF} : static_cast<std::uint16_t>(rho);
}

}  // namespace kestrel::hal::asterix
