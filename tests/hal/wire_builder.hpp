// SPDX-License-Identifier: Apache-2.0
// Test helper: builds wire frames byte by byte with every header and record
// field settable, including values the encoder refuses to produce (bad
// magic, other versions, unknown kinds, reserved bits, inconsistent lengths,
// over-capacity counts, bad CRCs). It writes little-endian bytes itself and
// uses only the layout numbers of docs/wire_format.md, not the codec or the
// frame_format.hpp helpers, so comparing it with encode() checks the layout
// independently.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "kestrel/hal/crc32.hpp"
#include "kestrel/hal/frame.hpp"

namespace kestrel::test {

class WireBuilder {
 public:
  std::uint32_t magic = 0x5254534Bu;
  std::uint8_t version = 1;
  std::uint8_t kind = 1;
  std::uint16_t flags = 0;
  std::optional<std::uint32_t> payload_len;  ///< Default: 4 + record bytes.
  std::int64_t t_us = 0;
  std::optional<std::uint16_t> count;  ///< Default: number of records appended.
  std::uint16_t reserved = 0;
  std::optional<std::uint32_t> crc;  ///< Default: the correct CRC.

  explicit WireBuilder(hal::FrameKind k, std::int64_t t = 0) : kind(static_cast<std::uint8_t>(k)), t_us(t) {}

  WireBuilder& radar(std::uint32_t range_mm, std::int32_t bearing_bam, std::int32_t range_rate_mmps,
                     std::int16_t snr_cdb, std::uint8_t has_range_rate, std::uint8_t sensor_id) {
    put(records_, range_mm, 4);
    put(records_, static_cast<std::uint32_t>(bearing_bam), 4);
    put(records_, static_cast<std::uint32_t>(range_rate_mmps), 4);
    put(records_, static_cast<std::uint16_t>(snr_cdb), 2);
    put(records_, has_range_rate, 1);
    put(records_, sensor_id, 1);
    ++records_count_;
    return *this;
  }
  WireBuilder& radar(const hal::RadarPlot& p) {
    return radar(p.range_mm, p.bearing_bam, p.range_rate_mmps, p.snr_cdb, p.has_range_rate, p.sensor_id);
  }

  WireBuilder& sonar(std::uint32_t time_of_flight_ns, std::uint8_t beacon_id, std::uint8_t path,
                     std::uint16_t record_reserved = 0) {
    put(records_, time_of_flight_ns, 4);
    put(records_, beacon_id, 1);
    put(records_, path, 1);
    put(records_, record_reserved, 2);
    ++records_count_;
    return *this;
  }
  WireBuilder& sonar(const hal::SonarArrival& a) {
    return sonar(a.time_of_flight_ns, a.beacon_id, static_cast<std::uint8_t>(a.path));
  }

  WireBuilder& pcl(std::uint32_t bistatic_range_mm, std::int32_t doppler_mhz, std::int16_t snr_cdb,
                   std::uint16_t record_reserved = 0) {
    put(records_, bistatic_range_mm, 4);
    put(records_, static_cast<std::uint32_t>(doppler_mhz), 4);
    put(records_, static_cast<std::uint16_t>(snr_cdb), 2);
    put(records_, record_reserved, 2);
    ++records_count_;
    return *this;
  }
  WireBuilder& pcl(const hal::PclCandidate& c) { return pcl(c.bistatic_range_mm, c.doppler_mhz, c.snr_cdb); }

  /// Append the items of `frame` (its kind must match this builder's).
  WireBuilder& items(const hal::Frame& frame) {
    for (std::size_t i = 0; i < frame.count; ++i) {
      switch (frame.kind) {
        case hal::FrameKind::kRadar: radar(frame.radar[i]); break;
        case hal::FrameKind::kSonar: sonar(frame.sonar[i]); break;
        case hal::FrameKind::kPcl: pcl(frame.pcl[i]); break;
      }
    }
    return *this;
  }

  /// Append raw record bytes (for odd lengths); does not change the count.
  WireBuilder& raw_record_bytes(std::span<const std::uint8_t> bytes) {
    records_.insert(records_.end(), bytes.begin(), bytes.end());
    return *this;
  }

  [[nodiscard]] std::vector<std::uint8_t> build() const {
    std::vector<std::uint8_t> out;
    put(out, magic, 4);
    put(out, version, 1);
    put(out, kind, 1);
    put(out, flags, 2);
    put(out, payload_len.value_or(static_cast<std::uint32_t>(4 + records_.size())), 4);
    put(out, static_cast<std::uint64_t>(t_us), 8);
    put(out, count.value_or(records_count_), 2);
    put(out, reserved, 2);
    out.insert(out.end(), records_.begin(), records_.end());
    put(out, crc.value_or(hal::crc32(out)), 4);
    return out;
  }

  /// Recompute the CRC at the end of a single frame held in `bytes` after a
  /// test has edited it.
  static void fix_crc(std::vector<std::uint8_t>& bytes) {
    const std::size_t body = bytes.size() - 4;
    const std::uint32_t c = hal::crc32(std::span<const std::uint8_t>(bytes).first(body));
    for (std::size_t i = 0; i < 4; ++i) bytes[body + i] = static_cast<std::uint8_t>(c >> (8 * i));
  }

 private:
  static void put(std::vector<std::uint8_t>& v, std::uint64_t value, std::size_t bytes) {
    for (std::size_t i = 0; i < bytes; ++i) v.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
  }

  std::vector<std::uint8_t> records_;
  std::uint16_t records_count_ = 0;
};

}  // namespace kestrel::test
