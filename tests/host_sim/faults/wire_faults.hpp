// SPDX-License-Identifier: Apache-2.0
// Building blocks of the fault-injection tests: a stream of wire frames
// with each frame sent, dropped, repeated, re-timed or damaged on purpose,
// and what a fault expects of the Runner. Shared by the sonar and PCL
// tests (sonar_faults_test.cpp, pcl_faults_test.cpp); the radar test
// uses the damage helpers.
#pragma once

#include <array>
#include <catch2/catch.hpp>
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "kestrel/hal/frame.hpp"
#include "kestrel/hal/frame_codec.hpp"
#include "kestrel/hal/frame_format.hpp"
#include "kestrel/status.hpp"

namespace kestrel::test::faults {

using Bytes = std::vector<std::uint8_t>;

/// One frame's wire bytes (header, payload, CRC).
inline Bytes encode_frame(const hal::Frame& f) {
  std::array<std::uint8_t, hal::wire::kMaxEncodedFrameBytes> buffer{};
  std::size_t written = 0;
  REQUIRE(hal::encode(f, buffer, written) == Status::kOk);
  return Bytes(buffer.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(written));
}

inline void append(Bytes& out, const Bytes& b) { out.insert(out.end(), b.begin(), b.end()); }

/// Flip one payload bit of an encoded frame: its CRC then fails (kBadCrc).
inline void flip_payload_bit(Bytes& frame) { frame[hal::wire::kHeaderSize + 5] ^= 0x40u; }

/// Seven bytes of line noise that start like a magic: the assembler reports
/// them once (kBadMagic, one Runner frame) and resynchronises.
inline Bytes line_noise() { return Bytes{0x4B, 0x53, 0x00, 0xFF, 0x4B, 0x53, 0x54}; }

/// The stream of a scenario's frames (records with a `wire` frame), each
/// passed as a copy to per_frame(k, frame, out), which appends what the
/// faulty sensor sends for it.
template <class Records, class PerFrame>
Bytes each_frame(const Records& records, PerFrame&& per_frame) {
  Bytes out;
  for (std::size_t k = 0; k < records.size(); ++k) {
    hal::Frame f = records[k].wire;
    per_frame(k, f, out);
  }
  return out;
}

/// Every frame, as the sensor sends it.
template <class Records>
Bytes send_all(const Records& records) {
  return each_frame(records, [](std::size_t, const hal::Frame& f, Bytes& out) { append(out, encode_frame(f)); });
}

/// The frames [from, from + count) are not sent.
template <class Records>
Bytes drop_frames(const Records& records, std::size_t from, std::size_t count) {
  return each_frame(records, [&](std::size_t k, const hal::Frame& f, Bytes& out) {
    if (k < from || k >= from + count) append(out, encode_frame(f));
  });
}

/// The frames [from, from + count) are each sent twice.
template <class Records>
Bytes repeat_frames(const Records& records, std::size_t from, std::size_t count) {
  return each_frame(records, [&](std::size_t k, const hal::Frame& f, Bytes& out) {
    append(out, encode_frame(f));
    if (k >= from && k < from + count) append(out, encode_frame(f));
  });
}

/// The frames [from, from + count) carry their time moved by shift_us (a
/// clock that jumps, a stall, a reset); count 0: to the end.
template <class Records>
Bytes shift_times(const Records& records, std::size_t from, std::size_t count, std::int64_t shift_us) {
  return each_frame(records, [&](std::size_t k, hal::Frame f, Bytes& out) {
    if (k >= from && (count == 0 || k < from + count)) f.t_us += shift_us;
    append(out, encode_frame(f));
  });
}

/// Frames `flipped` have a payload bit flipped (kBadCrc each), and line
/// noise goes before frame `noise_before` (kBadMagic, one Runner frame more).
template <class Records>
Bytes corrupt_frames(const Records& records, const std::vector<std::size_t>& flipped, std::size_t noise_before) {
  return each_frame(records, [&](std::size_t k, const hal::Frame& f, Bytes& out) {
    Bytes b = encode_frame(f);
    for (const std::size_t i : flipped) {
      if (i == k) flip_payload_bit(b);
    }
    if (k == noise_before) append(out, line_noise());
    append(out, b);
  });
}

/// One fault and what the Runner should report for it.
struct WireFault {
  std::string name;
  Bytes stream;
  std::map<Status, std::size_t> not_ok;  ///< Expected count of each status other than kOk.
  std::size_t frames = 0;                ///< Frames the Runner should see.
  std::size_t new_tracks = 0;            ///< Tracks started after the first by a documented rule.
};

/// "status count; ..." for a test message.
inline std::string describe(const std::map<Status, std::size_t>& counts) {
  std::string seen;
  for (const auto& [status, count] : counts) seen += std::string(to_string(status)) + " " + std::to_string(count) + "; ";
  return seen;
}

}  // namespace kestrel::test::faults
