// SPDX-License-Identifier: Apache-2.0
// SI measurements <-> wire units (hal/frame.hpp): range in millimetres,
// bearing as a binary angle (2^32 per turn), range-rate in mm/s, time in
// microseconds. Quantisation is what a real sensor front end does before
// transmitting; its error (0.5 mm, 1.5e-9 rad) is far below any sensor
// noise, and the round trip wire -> SI -> wire is exact, so a plot CSV
// written from a stream replays to the same bytes.
//
// A value the wire field cannot hold is refused, never clamped or wrapped
// into some other value: replay must not silently change a user's value.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "kestrel/hal/frame.hpp"
#include "scenarios/scenario.hpp"

namespace kestrel::sim {

/// What each wire field can carry, in SI units, for error messages. Values
/// are rounded to the field's unit first; the try_ functions below decide.
/// Time: i64 microseconds reach +-9223372036854.775807 s, but a double time
/// is only resolved to 2 ms out there, so the span quoted is the one every
/// value inside is accepted from (a few just outside it are too).
inline constexpr std::string_view kWireTimeSpan = "[-9223372036854.774, 9223372036854.774] s (i64 microseconds)";
inline constexpr std::string_view kWireRangeSpan = "[0, 4294967.295] m (u32 millimetres)";
inline constexpr std::string_view kWireBearingSpan =
    "[-6.283185307179586, 6.283185307179586] rad (one turn either way: the i32 binary angle holds [-pi, pi), "
    "a bearing beyond it is the same direction a turn away)";
inline constexpr std::string_view kWireRangeRateSpan = "[-2147483.648, 2147483.647] m/s (i32 mm/s)";

/// Time in seconds to whole microseconds (nearest, ties away from zero);
/// nullopt for NaN, Inf or a time outside int64 microseconds.
std::optional<std::int64_t> try_wire_time_us(double t_s);
/// Range in metres to millimetres (nearest); nullopt outside kWireRangeSpan or non-finite.
std::optional<std::uint32_t> try_wire_range_mm(double range_m);
/// Bearing in radians to the nearest binary angle; nullopt beyond one turn
/// (|bearing| > 2 pi) or non-finite. Within a turn the angle is reduced
/// modulo 2^32 as an integer, which is exact: +pi and -pi both give -2^31,
/// 4.0 rad gives the same angle as 4.0 - 2 pi.
std::optional<std::int32_t> try_wire_bearing_bam(double bearing_rad);
/// Range-rate in m/s to mm/s (nearest); nullopt outside int32 mm/s or non-finite.
std::optional<std::int32_t> try_wire_range_rate_mmps(double range_rate_mps);

/// The same conversions, throwing std::out_of_range (naming the quantity,
/// the value and what the field can carry) where try_ gives nullopt.
std::int64_t to_wire_time_us(double t_s);
std::uint32_t to_wire_range_mm(double range_m);
std::int32_t to_wire_bearing_bam(double bearing_rad);
std::int32_t to_wire_range_rate_mmps(double range_rate_mps);

/// A radar frame in wire units. Throws std::invalid_argument when it holds
/// more plots than a wire frame can (hal::kMaxRadarPlots), std::out_of_range
/// for a value the wire cannot carry (see above; includes NaN and Inf).
hal::Frame to_wire_frame(const MeasurementFrame& frame);

/// The SI view of a wire radar frame (what the CSV writer prints).
MeasurementFrame from_wire_frame(const hal::Frame& frame);

}  // namespace kestrel::sim
