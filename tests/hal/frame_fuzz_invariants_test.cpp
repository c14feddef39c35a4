// SPDX-License-Identifier: Apache-2.0
// The fuzz target's invariant checker run in every CTest over a few thousand
// seeded mutations of valid frame streams, so CI exercises it without
// libFuzzer. Mutations that re-fix the CRC reach the checks behind it.
#include <array>
#include <catch2/catch.hpp>
#include <cstdint>
#include <random>
#include <span>
#include <vector>

#include "frame_gen.hpp"
#include "fuzz/frame_invariants.hpp"
#include "kestrel/hal/frame_format.hpp"
#include "wire_builder.hpp"

namespace wire = kestrel::hal::wire;
using kestrel::hal::FrameKind;

namespace {

// One frame, sometimes over capacity (built by hand, since encode refuses).
std::vector<std::uint8_t> random_frame_bytes(std::mt19937& rng) {
  const FrameKind kind = kestrel::test::random_kind(rng);
  const std::size_t capacity = kestrel::hal::capacity_of(kind);
  if (rng() % 8 == 0) {
    const kestrel::hal::Frame a = kestrel::test::random_frame(rng, kind, capacity);
    const kestrel::hal::Frame b = kestrel::test::random_frame(rng, kind, 1 + rng() % 4);
    return kestrel::test::WireBuilder(kind, a.t_us).items(a).items(b).build();
  }
  const std::size_t count = rng() % 3 == 0 ? capacity : rng() % (capacity + 1);
  return kestrel::test::encode_to_vector(kestrel::test::random_frame(rng, kind, count));
}

void set_u16(std::vector<std::uint8_t>& f, std::size_t at, std::uint32_t v) {
  f[at] = static_cast<std::uint8_t>(v);
  f[at + 1] = static_cast<std::uint8_t>(v >> 8);
}

// Damage one frame; `fix` re-computes its CRC afterwards for the mutations
// that aim at the checks behind the CRC.
void mutate_frame(std::mt19937& rng, std::vector<std::uint8_t>& f) {
  bool fix = true;
  switch (rng() % 10) {
    case 0: f[4] = static_cast<std::uint8_t>(rng()); break;                  // version
    case 1: f[5] = static_cast<std::uint8_t>(rng() % 6); break;              // kind
    case 2: set_u16(f, wire::kFlagsOffset, static_cast<std::uint32_t>(rng() % 3)); break;                // flags
    case 3: set_u16(f, wire::kHeaderSize, static_cast<std::uint32_t>(rng() % 80)); break;                // count
    case 4: set_u16(f, wire::kHeaderSize + 2, static_cast<std::uint32_t>(rng() % 2)); break;             // payload reserved
    case 5: {                                                                // payload_len
      const std::uint32_t len = static_cast<std::uint32_t>(rng() % (wire::kMaxPayloadBytes + 10));
      for (std::size_t i = 0; i < 4; ++i) f[wire::kPayloadLenOffset + i] = static_cast<std::uint8_t>(len >> (8 * i));
      break;
    }
    case 6:  // a record byte (enum, reserved or value)
      if (f.size() > wire::kHeaderSize + wire::kPayloadPrefixSize + wire::kCrcSize) {
        const std::size_t span = f.size() - wire::kHeaderSize - wire::kPayloadPrefixSize - wire::kCrcSize;
        f[wire::kHeaderSize + wire::kPayloadPrefixSize + rng() % span] = static_cast<std::uint8_t>(rng() % 4);
      }
      break;
    case 7:  // flip bits, CRC left wrong
      for (int i = 0; i < 1 + static_cast<int>(rng() % 3); ++i) {
        const std::size_t bit = rng() % (f.size() * 8);
        f[bit / 8] = static_cast<std::uint8_t>(f[bit / 8] ^ (1u << (bit % 8)));
      }
      fix = false;
      break;
    case 8:  // truncate
      f.resize(rng() % f.size());
      fix = false;
      break;
    default: fix = false; break;  // leave intact
  }
  if (fix && f.size() >= wire::kHeaderSize + wire::kCrcSize) kestrel::test::WireBuilder::fix_crc(f);
}

std::vector<std::uint8_t> random_stream(std::mt19937& rng) {
  std::vector<std::uint8_t> stream;
  const int frames = 1 + static_cast<int>(rng() % 4);
  for (int i = 0; i < frames; ++i) {
    if (rng() % 4 == 0) {  // garbage, sometimes with a false magic
      const std::size_t n = rng() % 40;
      for (std::size_t k = 0; k < n; ++k) stream.push_back(static_cast<std::uint8_t>(rng()));
      if (rng() % 2 == 0) stream.insert(stream.end(), {0x4B, 0x53, 0x54, 0x52});
    }
    auto f = random_frame_bytes(rng);
    if (rng() % 3 != 0) mutate_frame(rng, f);
    stream.insert(stream.end(), f.begin(), f.end());
  }
  return stream;
}

}  // namespace

SCENARIO("decode and the assembler keep their invariants on mutated streams", "[hal][fuzz]") {
  GIVEN("4000 seeded random streams of valid, damaged and over-capacity frames with garbage") {
    std::mt19937 rng(0xC0FFEE);
    std::size_t checked = 0;
    std::array<std::size_t, kestrel::kStatusCount> seen{};
    for (int i = 0; i < 4000; ++i) {
      const auto stream = random_stream(rng);
      const std::span<const std::uint8_t> s(stream);
      {
        kestrel::hal::Frame f;
        std::size_t consumed = 0;
        ++seen[static_cast<std::size_t>(kestrel::hal::decode(s, f, consumed))];
      }
      // decode at the start and at a random offset, as a resyncing reader would.
      const std::size_t offset = stream.empty() ? 0 : rng() % stream.size();
      for (const auto& in : {s, s.subspan(offset)}) {
        const char* why = kestrel::test::check_decode_invariants(in);
        if (why != nullptr) {
          INFO("stream " << i << ": " << why);
          REQUIRE(why == nullptr);
        }
      }
      const char* why = kestrel::test::check_assembler_invariants(s, static_cast<std::uint32_t>(i));
      if (why != nullptr) {
        INFO("stream " << i << ": " << why);
        REQUIRE(why == nullptr);
      }
      ++checked;
    }
    THEN("every stream was checked and every decode outcome was reached") {
      REQUIRE(checked == 4000);
      using kestrel::Status;
      for (const Status st : {Status::kOk, Status::kTooManyCandidates, Status::kTruncated, Status::kBadMagic,
                              Status::kUnsupportedVersion, Status::kUnknownKind, Status::kMalformedFrame,
                              Status::kBadCrc}) {
        INFO(kestrel::to_string(st));
        CHECK(seen[static_cast<std::size_t>(st)] > 0);
      }
    }
  }
}
