// SPDX-License-Identifier: Apache-2.0
// Test helpers: seeded random frames with every field over its full wire
// range (valid enum values only), field-by-field equality, and encoding into
// a std::vector. Seeded std::mt19937 so a failing case can be replayed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <span>
#include <vector>

#include "kestrel/hal/frame.hpp"
#include "kestrel/hal/frame_codec.hpp"
#include "kestrel/hal/frame_format.hpp"

namespace kestrel::test {

template <class T>
T random_int(std::mt19937& rng) {
  // Full range of T, drawn through a wider type so int8/uint8 work too.
  std::uniform_int_distribution<std::int64_t> d(std::numeric_limits<T>::min(), std::numeric_limits<T>::max());
  return static_cast<T>(d(rng));
}

inline hal::RadarPlot random_radar_plot(std::mt19937& rng) {
  return hal::RadarPlot{random_int<std::uint32_t>(rng), random_int<std::int32_t>(rng),
                        random_int<std::int32_t>(rng),  random_int<std::int16_t>(rng),
                        static_cast<std::uint8_t>(rng() & 1u), random_int<std::uint8_t>(rng)};
}
inline hal::SonarArrival random_sonar_arrival(std::mt19937& rng) {
  return hal::SonarArrival{random_int<std::uint32_t>(rng), random_int<std::uint8_t>(rng),
                           (rng() & 1u) != 0 ? hal::ToaPath::kReflected : hal::ToaPath::kDirect};
}
inline hal::PclCandidate random_pcl_candidate(std::mt19937& rng) {
  return hal::PclCandidate{random_int<std::uint32_t>(rng), random_int<std::int32_t>(rng),
                           random_int<std::int16_t>(rng)};
}

/// A frame of `kind` with `count` (<= capacity) random items and a random time.
inline hal::Frame random_frame(std::mt19937& rng, hal::FrameKind kind, std::size_t count) {
  hal::Frame f{};
  f.kind = kind;
  f.count = static_cast<std::uint16_t>(count);
  f.t_us = random_int<std::int64_t>(rng);
  for (std::size_t i = 0; i < count; ++i) {
    switch (kind) {
      case hal::FrameKind::kRadar: f.radar[i] = random_radar_plot(rng); break;
      case hal::FrameKind::kSonar: f.sonar[i] = random_sonar_arrival(rng); break;
      case hal::FrameKind::kPcl: f.pcl[i] = random_pcl_candidate(rng); break;
    }
  }
  return f;
}

inline hal::FrameKind random_kind(std::mt19937& rng) {
  return static_cast<hal::FrameKind>(1 + rng() % 3);
}

/// Field-by-field equality of kind, count, time and the first `count` items.
inline bool frames_equal(const hal::Frame& a, const hal::Frame& b) {
  if (a.kind != b.kind || a.count != b.count || a.t_us != b.t_us) return false;
  for (std::size_t i = 0; i < a.count; ++i) {
    switch (a.kind) {
      case hal::FrameKind::kRadar: {
        const hal::RadarPlot& p = a.radar[i];
        const hal::RadarPlot& q = b.radar[i];
        if (p.range_mm != q.range_mm || p.bearing_bam != q.bearing_bam ||
            p.range_rate_mmps != q.range_rate_mmps || p.snr_cdb != q.snr_cdb ||
            p.has_range_rate != q.has_range_rate || p.sensor_id != q.sensor_id) {
          return false;
        }
        break;
      }
      case hal::FrameKind::kSonar: {
        const hal::SonarArrival& p = a.sonar[i];
        const hal::SonarArrival& q = b.sonar[i];
        if (p.time_of_flight_ns != q.time_of_flight_ns || p.beacon_id != q.beacon_id || p.path != q.path) {
          return false;
        }
        break;
      }
      case hal::FrameKind::kPcl: {
        const hal::PclCandidate& p = a.pcl[i];
        const hal::PclCandidate& q = b.pcl[i];
        if (p.bistatic_range_mm != q.bistatic_range_mm || p.doppler_mhz != q.doppler_mhz ||
            p.snr_cdb != q.snr_cdb) {
          return false;
        }
        break;
      }
    }
  }
  return true;
}

/// encode() into a vector; empty on failure.
inline std::vector<std::uint8_t> encode_to_vector(const hal::Frame& f) {
  std::vector<std::uint8_t> out(hal::wire::kMaxEncodedFrameBytes);
  std::size_t written = 0;
  if (hal::encode(f, out, written) != Status::kOk) return {};
  out.resize(written);
  return out;
}

}  // namespace kestrel::test
