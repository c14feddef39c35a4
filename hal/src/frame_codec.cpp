// SPDX-License-Identifier: Apache-2.0
// Frame encode/decode for wire format version 1 (frame_format.hpp,
// docs/wire_format.md). Every field is read and written one at a time
// through the little-endian helpers; every loop is bounded by the input span
// or by kMaxPayloadBytes.
//
// Decode order, and why:
//  1. magic, on as many of its 4 bytes as are present (kBadMagic, consumed 1)
//     so a resynchronising reader rejects garbage without waiting for more;
//  2. header complete (kTruncated, consumed 0);
//  3. payload_len <= kMaxPayloadBytes, else kMalformedFrame with consumed 1:
//     such a header cannot be skipped as a frame, so the reader resyncs;
//  4. whole frame present (kTruncated, consumed 0);
//  5. CRC (kBadCrc). From here on consumed is the whole frame;
//  6. version, kind, flags, payload shape, record enums. Checking these only
//     on a CRC-intact frame means they report what the sender really sent
//     (a newer version, a sender bug), never line noise, and because the
//     envelope is the same for every version a frame of another version is
//     skipped whole.
// `out` is written only after the whole frame has been validated.
#include "kestrel/hal/frame_codec.hpp"

#include "kestrel/hal/crc32.hpp"
#include "kestrel/hal/frame_format.hpp"

namespace kestrel::hal {

// Field names read like the layout table; this file is the only user.
using namespace wire;  // NOLINT(google-build-using-namespace)

namespace {

constexpr std::uint8_t magic_byte(std::size_t i) {
  return static_cast<std::uint8_t>((kMagic >> (8 * i)) & 0xFFu);
}

// Enumerated and reserved record fields of one record; the numeric fields
// take every value.
bool record_is_valid(FrameKind kind, std::span<const std::uint8_t> rec) {
  switch (kind) {
    case FrameKind::kRadar: return rec[kRadarHasRangeRateOffset] <= 1;
    case FrameKind::kSonar:
      return rec[kSonarPathOffset] <= 1 && load_u16(rec, kSonarReservedOffset) == 0;
    case FrameKind::kPcl: return load_u16(rec, kPclReservedOffset) == 0;
  }
  return false;
}

void read_record(FrameKind kind, std::span<const std::uint8_t> rec, Frame& out, std::size_t i) {
  switch (kind) {
    case FrameKind::kRadar:
      out.radar[i] = RadarPlot{load_u32(rec, kRadarRangeOffset),
                               load_i32(rec, kRadarBearingOffset),
                               load_i32(rec, kRadarRangeRateOffset),
                               load_i16(rec, kRadarSnrOffset),
                               rec[kRadarHasRangeRateOffset],
                               rec[kRadarSensorIdOffset]};
      return;
    case FrameKind::kSonar:
      out.sonar[i] = SonarArrival{load_u32(rec, kSonarTimeOfFlightOffset), rec[kSonarBeaconIdOffset],
                                  static_cast<ToaPath>(rec[kSonarPathOffset])};
      return;
    case FrameKind::kPcl:
      out.pcl[i] = PclCandidate{load_u32(rec, kPclBistaticRangeOffset), load_i32(rec, kPclDopplerOffset),
                                load_i16(rec, kPclSnrOffset)};
      return;
  }
}

void write_record(const Frame& frame, std::size_t i, std::span<std::uint8_t> rec) {
  switch (frame.kind) {
    case FrameKind::kRadar: {
      const RadarPlot& p = frame.radar[i];
      store_u32(rec, kRadarRangeOffset, p.range_mm);
      store_i32(rec, kRadarBearingOffset, p.bearing_bam);
      store_i32(rec, kRadarRangeRateOffset, p.range_rate_mmps);
      store_i16(rec, kRadarSnrOffset, p.snr_cdb);
      store_u8(rec, kRadarHasRangeRateOffset, p.has_range_rate);
      store_u8(rec, kRadarSensorIdOffset, p.sensor_id);
      return;
    }
    case FrameKind::kSonar: {
      const SonarArrival& a = frame.sonar[i];
      store_u32(rec, kSonarTimeOfFlightOffset, a.time_of_flight_ns);
      store_u8(rec, kSonarBeaconIdOffset, a.beacon_id);
      store_u8(rec, kSonarPathOffset, static_cast<std::uint8_t>(a.path));
      store_u16(rec, kSonarReservedOffset, 0);
      return;
    }
    case FrameKind::kPcl: {
      const PclCandidate& c = frame.pcl[i];
      store_u32(rec, kPclBistaticRangeOffset, c.bistatic_range_mm);
      store_i32(rec, kPclDopplerOffset, c.doppler_mhz);
      store_i16(rec, kPclSnrOffset, c.snr_cdb);
      store_u16(rec, kPclReservedOffset, 0);
      return;
    }
  }
}

}  // namespace

Status encode(const Frame& frame, std::span<std::uint8_t> out, std::size_t& written) {
  written = 0;
  const std::size_t rec_size = record_size(frame.kind);
  if (rec_size == 0) return Status::kUnknownKind;
  if (frame.count > capacity_of(frame.kind)) return Status::kTooManyCandidates;
  // Refuse what decode would refuse, so a sender never emits a frame the
  // receiver drops (has_range_rate must be 0/1, path a ToaPath value).
  for (std::size_t i = 0; i < capacity_of(frame.kind); ++i) {
    if (i >= frame.count) break;
    if (frame.kind == FrameKind::kRadar && frame.radar[i].has_range_rate > 1) return Status::kMalformedFrame;
    if (frame.kind == FrameKind::kSonar && frame.sonar[i].path != ToaPath::kDirect &&
        frame.sonar[i].path != ToaPath::kReflected) {
      return Status::kMalformedFrame;
    }
  }
  const std::size_t total = frame_size(frame.kind, frame.count);
  if (out.size() < total) return Status::kBufferTooSmall;

  const std::size_t payload_len = kPayloadPrefixSize + frame.count * rec_size;
  store_u32(out, kMagicOffset, kMagic);
  store_u8(out, kVersionOffset, kVersion);
  store_u8(out, kKindOffset, static_cast<std::uint8_t>(frame.kind));
  store_u16(out, kFlagsOffset, 0);
  store_u32(out, kPayloadLenOffset, static_cast<std::uint32_t>(payload_len));
  store_i64(out, kTimeOffset, frame.t_us);

  const std::span<std::uint8_t> payload = out.subspan(kHeaderSize, payload_len);
  store_u16(payload, kCountOffset, frame.count);
  store_u16(payload, kPayloadReservedOffset, 0);
  for (std::size_t i = 0; i < frame.count; ++i) {  // count <= capacity, checked above
    write_record(frame, i, payload.subspan(kPayloadPrefixSize + i * rec_size, rec_size));
  }

  const std::uint32_t crc = crc32(out.first(kHeaderSize + payload_len));
  store_u32(out, kHeaderSize + payload_len, crc);
  written = total;
  return Status::kOk;
}

Status decode(std::span<const std::uint8_t> in, Frame& out, std::size_t& consumed) {
  consumed = 0;
  const std::size_t magic_bytes = in.size() < 4 ? in.size() : 4;
  for (std::size_t i = 0; i < magic_bytes; ++i) {
    if (in[kMagicOffset + i] != magic_byte(i)) {
      consumed = 1;
      return Status::kBadMagic;
    }
  }
  if (in.size() < kHeaderSize) return Status::kTruncated;

  const std::uint32_t payload_len = load_u32(in, kPayloadLenOffset);
  if (payload_len > kMaxPayloadBytes) {
    consumed = 1;
    return Status::kMalformedFrame;
  }
  const std::size_t total = kHeaderSize + payload_len + kCrcSize;
  if (in.size() < total) return Status::kTruncated;

  consumed = total;
  const std::span<const std::uint8_t> frame = in.first(total);
  if (crc32(frame.first(kHeaderSize + payload_len)) != load_u32(frame, kHeaderSize + payload_len)) {
    return Status::kBadCrc;
  }
  if (frame[kVersionOffset] != kVersion) return Status::kUnsupportedVersion;
  const std::uint8_t kind_byte = frame[kKindOffset];
  if (kind_byte < static_cast<std::uint8_t>(FrameKind::kRadar) ||
      kind_byte > static_cast<std::uint8_t>(FrameKind::kPcl)) {
    return Status::kUnknownKind;
  }
  const auto kind = static_cast<FrameKind>(kind_byte);
  if (load_u16(frame, kFlagsOffset) != 0) return Status::kMalformedFrame;
  if (payload_len < kPayloadPrefixSize) return Status::kMalformedFrame;

  const std::span<const std::uint8_t> payload = frame.subspan(kHeaderSize, payload_len);
  const std::size_t count = load_u16(payload, kCountOffset);
  if (load_u16(payload, kPayloadReservedOffset) != 0) return Status::kMalformedFrame;
  const std::size_t rec_size = record_size(kind);
  if (payload_len != kPayloadPrefixSize + count * rec_size) return Status::kMalformedFrame;

  // Validate every record, the ones beyond the capacity too, before touching
  // `out`. count * rec_size <= kMaxPayloadBytes bounds this loop.
  const std::span<const std::uint8_t> records = payload.subspan(kPayloadPrefixSize);
  for (std::size_t i = 0; i < count; ++i) {
    if (!record_is_valid(kind, records.subspan(i * rec_size, rec_size))) return Status::kMalformedFrame;
  }

  // Over capacity: keep the first `capacity` records in wire order.
  const std::size_t capacity = capacity_of(kind);
  const std::size_t kept = count < capacity ? count : capacity;
  out.kind = kind;
  out.count = static_cast<std::uint16_t>(kept);
  out.t_us = load_i64(frame, kTimeOffset);
  for (std::size_t i = 0; i < kept; ++i) {
    read_record(kind, records.subspan(i * rec_size, rec_size), out, i);
  }
  return count > capacity ? Status::kTooManyCandidates : Status::kOk;
}

}  // namespace kestrel::hal
