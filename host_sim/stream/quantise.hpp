// SI measurements <-> wire units (hal/frame.hpp): range in millimetres,
// bearing as a binary angle (2^32 per turn), range-rate in mm/s, time in
// microseconds. Quantisation is what a real sensor front end does before
// transmitting; its error (0.5 mm, 1.5e-9 rad) is far below any sensor
// noise, and the round trip wire -> SI -> wire is exact, so a plot CSV
// written from a stream replays to the same bytes.
#pragma once

#include <cstdint>

#include "kestrel/hal/frame.hpp"
#include "scenarios/scenario.hpp"

namespace kestrel::sim {

/// Time in seconds to whole microseconds (nearest).
std::int64_t to_wire_time_us(double t_s);
/// Range in metres to millimetres (nearest), clamped to [0, 2^32 - 1].
std::uint32_t to_wire_range_mm(double range_m);
/// Bearing in radians to a binary angle (nearest; +pi wraps to -pi, the same direction).
std::int32_t to_wire_bearing_bam(double bearing_rad);
/// Range-rate in m/s to mm/s (nearest), clamped to int32.
std::int32_t to_wire_range_rate_mmps(double range_rate_mps);

/// A radar frame in wire units. Throws std::invalid_argument when it holds
/// more plots than a wire frame can (hal::kMaxRadarPlots) or a non-finite value.
hal::Frame to_wire_frame(const MeasurementFrame& frame);

/// The SI view of a wire radar frame (what the CSV writer prints).
MeasurementFrame from_wire_frame(const hal::Frame& frame);

}  // namespace kestrel::sim
