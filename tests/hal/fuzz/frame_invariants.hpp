// SPDX-License-Identifier: Apache-2.0
// Invariants of decode() and FrameAssembler over arbitrary bytes, shared by
// the libFuzzer target (frame_decode_fuzz.cpp) and the seeded mutation test
// that runs in every CTest (frame_fuzz_invariants_test.cpp). Each checker
// returns nullptr when every invariant holds, else a short description of
// the first one broken. No Catch2 here, so libFuzzer can use it.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <span>
#include <vector>

#include "kestrel/hal/frame.hpp"
#include "kestrel/hal/frame_assembler.hpp"
#include "kestrel/hal/frame_codec.hpp"
#include "kestrel/hal/frame_format.hpp"

namespace kestrel::test {

/// decode() on `in`:
///  - consumed is 0 for kTruncated, 1 for kBadMagic, 1 or a whole frame for
///    kMalformedFrame, a whole frame (header + payload_len + CRC, within
///    `in`) for every other status;
///  - kOk and kTooManyCandidates give a known kind and count <= capacity
///    (== capacity for kTooManyCandidates); any other status leaves `out`
///    untouched;
///  - a kOk frame re-encodes to exactly the bytes it was decoded from, and a
///    kTooManyCandidates frame re-encodes to the same header time and the
///    same first records;
///  - decoding only the consumed bytes gives the same result.
inline const char* check_decode_invariants(std::span<const std::uint8_t> in) {
  namespace wire = hal::wire;
  hal::Frame out;
  std::memset(&out, 0x5A, sizeof out);
  hal::Frame untouched;
  std::memset(&untouched, 0x5A, sizeof untouched);
  std::size_t consumed = 0xDEAD;
  const Status s = hal::decode(in, out, consumed);

  const auto whole_frame = [&]() -> std::size_t {
    if (in.size() < wire::kHeaderSize) return 0;
    return wire::kHeaderSize + wire::load_u32(in, wire::kPayloadLenOffset) + wire::kCrcSize;
  };
  switch (s) {
    case Status::kTruncated:
      if (consumed != 0) return "kTruncated with consumed != 0";
      break;
    case Status::kBadMagic:
      if (consumed != 1) return "kBadMagic with consumed != 1";
      break;
    case Status::kMalformedFrame:
      if (consumed != 1 && consumed != whole_frame()) return "kMalformedFrame with consumed neither 1 nor the frame";
      break;
    case Status::kOk:
    case Status::kTooManyCandidates:
    case Status::kBadCrc:
    case Status::kUnsupportedVersion:
    case Status::kUnknownKind:
      if (consumed != whole_frame()) return "consumed is not the whole frame";
      break;
    default: return "decode returned a status outside its contract";
  }
  if (consumed > in.size()) return "consumed more than the input";

  if (s != Status::kOk && s != Status::kTooManyCandidates) {
    if (std::memcmp(&out, &untouched, sizeof out) != 0) return "decode wrote to out on failure";
    return nullptr;
  }

  const std::size_t capacity = hal::capacity_of(out.kind);
  if (capacity == 0) return "decoded frame has an unknown kind";
  if (out.count > capacity) return "decoded count exceeds capacity";
  if (s == Status::kTooManyCandidates && out.count != capacity) return "kTooManyCandidates without count == capacity";

  std::array<std::uint8_t, wire::kMaxEncodedFrameBytes> re{};
  std::size_t written = 0;
  if (hal::encode(out, re, written) != Status::kOk) return "decoded frame does not re-encode";
  if (s == Status::kOk) {
    if (written != consumed || !std::equal(re.begin(), re.begin() + static_cast<std::ptrdiff_t>(written), in.begin())) {
      return "re-encoded kOk frame differs from its input bytes";
    }
  } else {
    // Same version/kind, time, and first `capacity` records.
    const std::size_t rec = wire::record_size(out.kind);
    const std::size_t records_at = wire::kHeaderSize + wire::kPayloadPrefixSize;
    if (!std::equal(re.begin() + 4, re.begin() + 6, in.begin() + 4) ||
        !std::equal(re.begin() + wire::kTimeOffset, re.begin() + wire::kHeaderSize, in.begin() + wire::kTimeOffset) ||
        !std::equal(re.begin() + static_cast<std::ptrdiff_t>(records_at),
                    re.begin() + static_cast<std::ptrdiff_t>(records_at + capacity * rec),
                    in.begin() + static_cast<std::ptrdiff_t>(records_at))) {
      return "kTooManyCandidates frame does not hold the first records of its input";
    }
  }

  hal::Frame again{};
  std::size_t consumed_again = 0;
  if (hal::decode(in.first(consumed), again, consumed_again) != s || consumed_again != consumed) {
    return "decode depends on bytes after the frame";
  }
  return nullptr;
}

/// FrameAssembler fed `in` in pseudo-random chunks (from `seed`) returns the
/// same frames and non-magic statuses, in the same order, as a plain loop of
/// decode() over the whole input; it never returns kTruncated, never more
/// results than input bytes, and what it holds at the end is less than one
/// maximum frame.
inline const char* check_assembler_invariants(std::span<const std::uint8_t> in, std::uint32_t seed) {
  struct Event {
    Status status;
    std::vector<std::uint8_t> frame_bytes;  // re-encoded frame for kOk / kTooManyCandidates
  };
  const auto make_event = [](Status s, const hal::Frame& f) {
    Event e{s, {}};
    if (s == Status::kOk || s == Status::kTooManyCandidates) {
      e.frame_bytes.resize(hal::wire::kMaxEncodedFrameBytes);
      std::size_t written = 0;
      if (hal::encode(f, e.frame_bytes, written) != Status::kOk) written = 0;
      e.frame_bytes.resize(written);
    }
    return e;
  };

  // Reference: decode() over the whole input, kBadMagic left out because the
  // assembler reports a run of garbage once, not once per byte.
  std::vector<Event> expected;
  for (std::size_t pos = 0; pos < in.size();) {
    hal::Frame f{};
    std::size_t consumed = 0;
    const Status s = hal::decode(in.subspan(pos), f, consumed);
    if (s == Status::kTruncated) break;
    if (consumed == 0) return "decode consumed nothing on a final status";
    if (s != Status::kBadMagic) expected.push_back(make_event(s, f));
    pos += consumed;
  }

  auto assembler = std::make_unique<hal::FrameAssembler<>>();
  std::vector<Event> got;
  std::size_t results = 0;
  std::uint32_t x = seed | 1u;
  const auto drain = [&]() -> const char* {
    for (std::size_t guard = 0; guard <= in.size() + 1; ++guard) {
      hal::Frame f{};
      const Status s = assembler->next(f);
      if (s == Status::kNoData) return nullptr;
      if (s == Status::kTruncated) return "assembler returned kTruncated";
      if (++results > in.size()) return "assembler returned more results than input bytes";
      if (s != Status::kBadMagic) got.push_back(make_event(s, f));
    }
    return "assembler next() did not reach kNoData";
  };
  for (std::size_t pos = 0; pos < in.size();) {
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    const std::size_t chunk = std::min<std::size_t>(1 + x % 300, in.size() - pos);
    const std::size_t taken = assembler->push(in.subspan(pos, chunk));
    pos += taken;
    if (const char* why = drain()) return why;
    if (taken == 0 && assembler->buffered() >= hal::wire::kMaxFrameBytes) return "assembler stalled with a full buffer";
  }
  if (const char* why = drain()) return why;
  if (assembler->buffered() >= hal::wire::kMaxFrameBytes) return "assembler holds a whole frame's worth of bytes";

  if (got.size() != expected.size()) return "assembler and decode loop disagree on the number of results";
  for (std::size_t i = 0; i < got.size(); ++i) {
    if (got[i].status != expected[i].status) return "assembler and decode loop disagree on a status";
    if (got[i].frame_bytes != expected[i].frame_bytes) return "assembler and decode loop disagree on a frame";
  }
  return nullptr;
}

}  // namespace kestrel::test
