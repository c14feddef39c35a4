// SPDX-License-Identifier: Apache-2.0
// The versioned wire layout of a frame (version 1): byte offsets, sizes and
// units of every field, and the little-endian load/store helpers the codec
// uses to read and write them one field at a time. A frame on the wire is
//
//   header (20 bytes) | payload (payload_len bytes) | CRC-32 (4 bytes)
//
// and the payload is `count u16 | reserved u16 | count fixed-size records`.
// Everything is little-endian and written with explicit shifts, never by
// copying a struct, so the layout does not depend on the host's byte order
// or on struct padding. docs/wire_format.md has the same layout as a table,
// the statuses, the resynchronisation rules and the over-capacity rule.
//
// The envelope (magic, the version byte at offset 4, payload_len at offset
// 8, the header size and the trailing CRC) is fixed for every version, so a
// decoder can check and skip a frame of a version it does not understand.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "kestrel/hal/frame.hpp"

namespace kestrel::hal::wire {

// ---------------------------------------------------------------- header --

/// Frame magic: the bytes 'K' 'S' 'T' 'R' on the wire (u32 LE 0x5254534B).
inline constexpr std::uint32_t kMagic = 0x5254534Bu;
/// The only version this decoder understands.
inline constexpr std::uint8_t kVersion = 1;

/// Header fields: offset (bytes from the start of the frame), all LE.
inline constexpr std::size_t kMagicOffset = 0;        ///< u32, kMagic.
inline constexpr std::size_t kVersionOffset = 4;      ///< u8, kVersion.
inline constexpr std::size_t kKindOffset = 5;         ///< u8, FrameKind (1 radar, 2 sonar, 3 PCL).
inline constexpr std::size_t kFlagsOffset = 6;        ///< u16, reserved: must be 0 in v1.
inline constexpr std::size_t kPayloadLenOffset = 8;   ///< u32, payload bytes (after header, before CRC).
inline constexpr std::size_t kTimeOffset = 12;        ///< i64, measurement time t_us, microseconds.
inline constexpr std::size_t kHeaderSize = 20;        ///< Bytes of the header.

// --------------------------------------------------------------- payload --

/// Payload prefix, offsets from the start of the payload.
inline constexpr std::size_t kCountOffset = 0;          ///< u16, number of records.
inline constexpr std::size_t kPayloadReservedOffset = 2;  ///< u16, reserved: must be 0 in v1.
inline constexpr std::size_t kPayloadPrefixSize = 4;    ///< Bytes before the first record.

/// Radar record (RadarPlot), offsets from the start of the record.
inline constexpr std::size_t kRadarRangeOffset = 0;          ///< u32 range_mm, millimetres.
inline constexpr std::size_t kRadarBearingOffset = 4;        ///< i32 bearing_bam, binary angle (2^32/turn).
inline constexpr std::size_t kRadarRangeRateOffset = 8;      ///< i32 range_rate_mmps, mm/s, + opening.
inline constexpr std::size_t kRadarSnrOffset = 12;           ///< i16 snr_cdb, 0.01 dB.
inline constexpr std::size_t kRadarHasRangeRateOffset = 14;  ///< u8 has_range_rate, 0 or 1.
inline constexpr std::size_t kRadarSensorIdOffset = 15;      ///< u8 sensor_id.
inline constexpr std::size_t kRadarRecordSize = 16;

/// Sonar record (SonarArrival), offsets from the start of the record.
inline constexpr std::size_t kSonarTimeOfFlightOffset = 0;  ///< u32 time_of_flight_ns, nanoseconds.
inline constexpr std::size_t kSonarBeaconIdOffset = 4;      ///< u8 beacon_id.
inline constexpr std::size_t kSonarPathOffset = 5;          ///< u8 path, ToaPath: 0 direct, 1 reflected.
inline constexpr std::size_t kSonarReservedOffset = 6;      ///< u16 reserved: must be 0.
inline constexpr std::size_t kSonarRecordSize = 8;

/// PCL record (PclCandidate), offsets from the start of the record.
inline constexpr std::size_t kPclBistaticRangeOffset = 0;  ///< u32 bistatic_range_mm, millimetres.
inline constexpr std::size_t kPclDopplerOffset = 4;        ///< i32 doppler_mhz, millihertz.
inline constexpr std::size_t kPclSnrOffset = 8;            ///< i16 snr_cdb, 0.01 dB.
inline constexpr std::size_t kPclReservedOffset = 10;      ///< u16 reserved: must be 0.
inline constexpr std::size_t kPclRecordSize = 12;

// ------------------------------------------------------------------ CRC --

/// CRC-32 (zlib's) over header and payload, u32 LE right after the payload.
inline constexpr std::size_t kCrcSize = 4;

// ------------------------------------------------------------- limits --

/// Largest record of any kind.
inline constexpr std::size_t kMaxRecordSize = kRadarRecordSize;
/// Largest payload_len a decoder accepts; a header announcing more is
/// kMalformedFrame. It leaves room for frames over their kind's capacity
/// (up to 255 radar plots, 340 PCL candidates, 510 sonar arrivals), which
/// decode as kTooManyCandidates with the first capacity items kept.
inline constexpr std::size_t kMaxPayloadBytes = kPayloadPrefixSize + 255 * kMaxRecordSize;
/// Largest frame a decoder accepts: size receive buffers with this.
inline constexpr std::size_t kMaxFrameBytes = kHeaderSize + kMaxPayloadBytes + kCrcSize;

/// Bytes of one record of `kind` on the wire (0 for an unknown kind).
constexpr std::size_t record_size(FrameKind kind) {
  switch (kind) {
    case FrameKind::kRadar: return kRadarRecordSize;
    case FrameKind::kSonar: return kSonarRecordSize;
    case FrameKind::kPcl: return kPclRecordSize;
  }
  return 0;
}

/// Bytes of a whole frame of `kind` carrying `count` records.
constexpr std::size_t frame_size(FrameKind kind, std::size_t count) {
  return kHeaderSize + kPayloadPrefixSize + count * record_size(kind) + kCrcSize;
}

/// Largest frame encode() can produce (every kind at its capacity): size
/// transmit buffers with this.
inline constexpr std::size_t kMaxEncodedFrameBytes = [] {
  std::size_t m = frame_size(FrameKind::kRadar, kMaxRadarPlots);
  if (frame_size(FrameKind::kSonar, kMaxSonarArrivals) > m) m = frame_size(FrameKind::kSonar, kMaxSonarArrivals);
  if (frame_size(FrameKind::kPcl, kMaxPclCandidates) > m) m = frame_size(FrameKind::kPcl, kMaxPclCandidates);
  return m;
}();

static_assert(kPayloadPrefixSize + kMaxRadarPlots * kRadarRecordSize <= kMaxPayloadBytes);
static_assert(kPayloadPrefixSize + kMaxSonarArrivals * kSonarRecordSize <= kMaxPayloadBytes);
static_assert(kPayloadPrefixSize + kMaxPclCandidates * kPclRecordSize <= kMaxPayloadBytes);
static_assert(kMaxEncodedFrameBytes <= kMaxFrameBytes);
// The largest record count any accepted payload can hold fits the u16 count.
static_assert((kMaxPayloadBytes - kPayloadPrefixSize) / kSonarRecordSize <= 0xFFFFu);
// Frame::count is a u16 too.
static_assert(kMaxPclCandidates <= 0xFFFFu && kMaxRadarPlots <= 0xFFFFu && kMaxSonarArrivals <= 0xFFFFu);

// --------------------------------------------- little-endian field access --
// The callers index inside spans whose size they have checked; these helpers
// only compose bytes.

constexpr std::uint16_t load_u16(std::span<const std::uint8_t> b, std::size_t at) {
  return static_cast<std::uint16_t>(b[at] | (b[at + 1] << 8));
}
constexpr std::uint32_t load_u32(std::span<const std::uint8_t> b, std::size_t at) {
  return static_cast<std::uint32_t>(b[at]) | (static_cast<std::uint32_t>(b[at + 1]) << 8) |
         (static_cast<std::uint32_t>(b[at + 2]) << 16) | (static_cast<std::uint32_t>(b[at + 3]) << 24);
}
constexpr std::uint64_t load_u64(std::span<const std::uint8_t> b, std::size_t at) {
  return static_cast<std::uint64_t>(load_u32(b, at)) | (static_cast<std::uint64_t>(load_u32(b, at + 4)) << 32);
}
// Two's complement reinterpretation of the unsigned field (well defined in C++20).
constexpr std::int16_t load_i16(std::span<const std::uint8_t> b, std::size_t at) {
  return static_cast<std::int16_t>(load_u16(b, at));
}
constexpr std::int32_t load_i32(std::span<const std::uint8_t> b, std::size_t at) {
  return static_cast<std::int32_t>(load_u32(b, at));
}
constexpr std::int64_t load_i64(std::span<const std::uint8_t> b, std::size_t at) {
  return static_cast<std::int64_t>(load_u64(b, at));
}

constexpr void store_u8(std::span<std::uint8_t> b, std::size_t at, std::uint8_t v) { b[at] = v; }
constexpr void store_u16(std::span<std::uint8_t> b, std::size_t at, std::uint16_t v) {
  b[at] = static_cast<std::uint8_t>(v & 0xFFu);
  b[at + 1] = static_cast<std::uint8_t>(v >> 8);
}
constexpr void store_u32(std::span<std::uint8_t> b, std::size_t at, std::uint32_t v) {
  b[at] = static_cast<std::uint8_t>(v & 0xFFu);
  b[at + 1] = static_cast<std::uint8_t>((v >> 8) & 0xFFu);
  b[at + 2] = static_cast<std::uint8_t>((v >> 16) & 0xFFu);
  b[at + 3] = static_cast<std::uint8_t>(v >> 24);
}
constexpr void store_u64(std::span<std::uint8_t> b, std::size_t at, std::uint64_t v) {
  store_u32(b, at, static_cast<std::uint32_t>(v & 0xFFFFFFFFu));
  store_u32(b, at + 4, static_cast<std::uint32_t>(v >> 32));
}
constexpr void store_i16(std::span<std::uint8_t> b, std::size_t at, std::int16_t v) {
  store_u16(b, at, static_cast<std::uint16_t>(v));
}
constexpr void store_i32(std::span<std::uint8_t> b, std::size_t at, std::int32_t v) {
  store_u32(b, at, static_cast<std::uint32_t>(v));
}
constexpr void store_i64(std::span<std::uint8_t> b, std::size_t at, std::int64_t v) {
  store_u64(b, at, static_cast<std::uint64_t>(v));
}

}  // namespace kestrel::hal::wire
