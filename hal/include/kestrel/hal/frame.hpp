// SPDX-License-Identifier: Apache-2.0
// The frames a sensor front end hands to the tracker, in the integer units
// they arrive in (the wire format of frame_format.hpp carries exactly these
// fields). Integer units at the HAL boundary keep a fixed-point build free of
// run-time float conversions and make host replays bit-exact with a board
// (docs/models.md). One frame = one sensor look at one time; the three kinds
// share a header and differ in their item records, each with a fixed
// maximum count.
#pragma once

#include <cstddef>
#include <cstdint>

namespace kestrel::hal {

/// Sensor kind of a frame; the numeric values are part of the wire format.
enum class FrameKind : std::uint8_t {
  kRadar = 1,  ///< Monostatic radar plots (range, bearing[, range-rate]).
  kSonar = 2,  ///< Underwater TOA arrivals, labelled by beacon and path.
  kPcl = 3,    ///< Passive-radar range-Doppler candidates.
};

/// Binary angle: 2^32 units per turn, so int32 covers [-pi, pi) exactly.
inline constexpr double kRadPerBam = 3.14159265358979323846 / 2147483648.0;

/// One radar detection (a "plot"). Radar at the frame's sensor origin.
struct RadarPlot {
  std::uint32_t range_mm;        ///< Slant range, millimetres, >= 0.
  std::int32_t bearing_bam;      ///< atan2(y, x), counter-clockwise from +x, binary angle units.
  std::int32_t range_rate_mmps;  ///< Radial velocity, mm/s, positive opening; valid if has_range_rate.
  std::int16_t snr_cdb;          ///< Signal-to-noise ratio, 0.01 dB.
  std::uint8_t has_range_rate;   ///< 1 if range_rate_mmps is measured, else 0.
  std::uint8_t sensor_id;        ///< Which sensor produced the plot (0 for a single radar).
};

/// Arrival path of an underwater TOA; values are part of the wire format.
enum class ToaPath : std::uint8_t {
  kDirect = 0,     ///< Straight line from target to beacon.
  kReflected = 1,  ///< Seabed-reflected (image source below the seabed).
};

/// One time-of-arrival at a beacon.
struct SonarArrival {
  std::uint32_t time_of_flight_ns;  ///< Travel time, nanoseconds.
  std::uint8_t beacon_id;           ///< Index into the beacon table of the sonar config.
  ToaPath path;                     ///< Direct or seabed-reflected.
};

/// One passive-radar range-Doppler candidate.
struct PclCandidate {
  std::uint32_t bistatic_range_mm;  ///< |p-tx| + |p-rx| - |tx-rx|, millimetres, >= 0.
  std::int32_t doppler_mhz;         ///< Bistatic Doppler, millihertz (dRb = -lambda * fD).
  std::int16_t snr_cdb;             ///< Signal-to-noise ratio, 0.01 dB.
};

/// Capacities of the item arrays. They bound the wire payload and every loop
/// over a frame's items; a frame announcing more is refused by the decoder
/// (kTooManyCandidates) after keeping the first kMax items.
inline constexpr std::size_t kMaxRadarPlots = 32;
inline constexpr std::size_t kMaxSonarArrivals = 16;
inline constexpr std::size_t kMaxPclCandidates = 64;

/// A decoded frame: a tagged union over the three sensor kinds.
struct Frame {
  FrameKind kind;
  std::uint16_t count;  ///< Number of valid items in the active array.
  std::int64_t t_us;    ///< Measurement time, microseconds on the sensor clock.
  union {
    RadarPlot radar[kMaxRadarPlots];
    SonarArrival sonar[kMaxSonarArrivals];
    PclCandidate pcl[kMaxPclCandidates];
  };
};

/// Capacity of the item array that belongs to a kind (0 for an unknown kind).
constexpr std::size_t capacity_of(FrameKind kind) {
  switch (kind) {
    case FrameKind::kRadar: return kMaxRadarPlots;
    case FrameKind::kSonar: return kMaxSonarArrivals;
    case FrameKind::kPcl: return kMaxPclCandidates;
  }
  return 0;
}

}  // namespace kestrel::hal
