// SPDX-License-Identifier: Apache-2.0
// Invariants of the CAT048 reader over arbitrary bytes, shared by the
// libFuzzer target (asterix_cat048_fuzz.cpp) and the seeded mutation test
// in every CTest (asterix_fuzz_invariants_test.cpp). Returns nullptr when
// every invariant holds, else the first one broken. No Catch2 here.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "kestrel/hal/asterix_cat048.hpp"

namespace kestrel::test {

/// decode_cat048_record on `in`: kOk consumes 1..in.size() bytes and
/// decoding exactly those bytes gives the same record; any other status is
/// kMalformedFrame with nothing consumed.
inline const char* check_cat048_record_invariants(std::span<const std::uint8_t> in) {
  using namespace hal::asterix;  // NOLINT(google-build-using-namespace)
  Cat048Record rec;
  std::size_t used = 12345;
  const Status s = decode_cat048_record(in, rec, used);
  if (s != Status::kOk) {
    if (s != Status::kMalformedFrame) return "record: status other than kOk or kMalformedFrame";
    if (used != 0) return "record: consumed bytes on failure";
    return nullptr;
  }
  if (used == 0 || used > in.size()) return "record: consumed outside 1..size";
  Cat048Record again;
  std::size_t used_again = 0;
  if (decode_cat048_record(in.first(used), again, used_again) != Status::kOk || used_again != used) {
    return "record: its own bytes do not decode alone";
  }
  // Field by field: the struct's padding is not part of the record.
  const bool same = rec.has_source == again.has_source && rec.sac == again.sac && rec.sic == again.sic &&
                    rec.has_time == again.has_time && rec.tod_128 == again.tod_128 &&
                    rec.has_polar == again.has_polar && rec.rho_256nm == again.rho_256nm &&
                    rec.theta == again.theta && rec.has_track_number == again.has_track_number &&
                    rec.track_number == again.track_number && rec.has_doppler == again.has_doppler &&
                    rec.doppler_mps == again.doppler_mps;
  if (!same) return "record: its own bytes decode differently";
  return nullptr;
}

/// The reader over `in` as a stream of data blocks: each block's status is
/// documented, frames are radar frames of 1..kMaxRadarPlots plots at a time
/// of day, a kMalformedFrame ends the block, and the frames' plots add up
/// to the plots counter.
inline const char* check_cat048_reader_invariants(std::span<const std::uint8_t> in) {
  using namespace hal::asterix;  // NOLINT(google-build-using-namespace)
  Cat048Reader reader;
  std::size_t at = 0;
  std::uint32_t plots = 0;
  for (std::size_t block = 0; block < in.size() + 1 && at < in.size(); ++block) {
    const std::span<const std::uint8_t> rest = in.subspan(at);
    std::size_t len = 99999;
    const Status open = reader.open(rest, len);
    if (open == Status::kTruncated) {
      if (len != 0 && len <= rest.size()) return "open: kTruncated with the whole block present";
      break;
    }
    if (open == Status::kMalformedFrame) {
      if (len != 0) return "open: kMalformedFrame with a block length";
      break;
    }
    if (len < kBlockHeaderSize || len > rest.size()) return "open: block length outside 3..size";
    if (open == Status::kUnknownKind) {
      if (rest[0] == kCat048) return "open: kUnknownKind for CAT 48";
      hal::Frame f{};
      if (reader.next(f) != Status::kNoData) return "next: a frame from an unknown category";
    } else if (open != Status::kOk) {
      return "open: undocumented status";
    }
    bool ended = false;
    for (std::size_t call = 0; call < len + 2; ++call) {
      hal::Frame f{};
      const Status s = reader.next(f);
      if (s == Status::kNoData) {
        if (f.count != 0) return "next: kNoData with plots";
        ended = true;
        break;
      }
      if (s == Status::kMalformedFrame) {
        if (f.count != 0) return "next: kMalformedFrame with plots";
        if (reader.next(f) != Status::kNoData) return "next: frames after kMalformedFrame";
        ended = true;
        break;
      }
      if (s != Status::kOk && s != Status::kTooManyCandidates) return "next: undocumented status";
      if (f.kind != hal::FrameKind::kRadar) return "next: not a radar frame";
      if (f.count == 0 || f.count > hal::kMaxRadarPlots) return "next: plot count outside 1..capacity";
      if (s == Status::kTooManyCandidates && f.count != hal::kMaxRadarPlots) {
        return "next: kTooManyCandidates below capacity";
      }
      if (f.t_us < 0 || f.t_us > t_us_from_time_of_day(0xFFFFFFu)) return "next: time outside 24 bits of 1/128 s";
      for (std::size_t i = 0; i < f.count; ++i) {
        if (f.radar[i].has_range_rate > 1) return "next: has_range_rate not 0 or 1";
        if (f.radar[i].range_mm > range_mm_from_rho(0xFFFF)) return "next: range past 256 NM";
      }
      plots += f.count;
    }
    if (!ended) return "next: block never finished";
    at += len;
  }
  if (reader.counters().plots != plots) return "counters: plots differ from the frames";
  return nullptr;
}

}  // namespace kestrel::test
