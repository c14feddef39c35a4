// SPDX-License-Identifier: Apache-2.0
// encode/decode of the v1 wire format: golden bytes, round trips, and one
// scenario per malformed class with the status and `consumed` the header
// documents. Frames that encode() refuses to produce are hand-built with
// WireBuilder.
#include "kestrel/hal/frame_codec.hpp"

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>
#include <random>
#include <span>
#include <vector>

#include "frame_gen.hpp"
#include "kestrel/hal/frame_format.hpp"
#include "support/alloc_guard.hpp"
#include "wire_builder.hpp"

using kestrel::Status;
using kestrel::hal::decode;
using kestrel::hal::encode;
using kestrel::hal::Frame;
using kestrel::hal::FrameKind;
using kestrel::test::WireBuilder;
namespace wire = kestrel::hal::wire;

namespace {

constexpr std::array<FrameKind, 3> kKinds{FrameKind::kRadar, FrameKind::kSonar, FrameKind::kPcl};

struct Decoded {
  Status status;
  std::size_t consumed;
  Frame frame;
};

Decoded decode_bytes(std::span<const std::uint8_t> in) {
  Decoded d{Status::kOk, 12345, Frame{}};
  d.status = decode(in, d.frame, d.consumed);
  return d;
}

// A frame object filled with a byte pattern, to detect any write by decode.
Frame sentinel_frame() {
  Frame f;
  std::memset(&f, 0xA5, sizeof f);
  return f;
}
bool is_sentinel(const Frame& f) {
  const Frame s = sentinel_frame();
  return std::memcmp(&f, &s, sizeof f) == 0;
}

// A valid frame of each kind with a few items, as bytes.
std::vector<std::uint8_t> sample_frame(FrameKind kind, std::uint32_t seed, std::size_t count = 3) {
  std::mt19937 rng(seed);
  return kestrel::test::encode_to_vector(kestrel::test::random_frame(rng, kind, count));
}

}  // namespace

SCENARIO("the layout constants are the documented ones", "[hal][codec]") {
  // docs/wire_format.md, "Sizes".
  STATIC_REQUIRE(wire::kHeaderSize == 20);
  STATIC_REQUIRE(wire::kCrcSize == 4);
  STATIC_REQUIRE(wire::kMaxPayloadBytes == 4084);
  STATIC_REQUIRE(wire::kMaxFrameBytes == 4108);
  STATIC_REQUIRE(wire::kMaxEncodedFrameBytes == 796);
  STATIC_REQUIRE(wire::frame_size(FrameKind::kRadar, kestrel::hal::kMaxRadarPlots) == 540);
  STATIC_REQUIRE(wire::frame_size(FrameKind::kSonar, kestrel::hal::kMaxSonarArrivals) == 156);
  STATIC_REQUIRE(wire::record_size(FrameKind::kRadar) == 16);
  STATIC_REQUIRE(wire::record_size(FrameKind::kSonar) == 8);
  STATIC_REQUIRE(wire::record_size(FrameKind::kPcl) == 12);
}

SCENARIO("encode produces the documented bytes", "[hal][codec]") {
  // Golden frames written with Python's struct and zlib, independent of this
  // code (see docs/wire_format.md, "Worked examples"):
  //   rec = struct.pack('<IiihBB', 1500, 0x40000000, -250, 1234, 1, 2)
  //   payload = struct.pack('<HH', 1, 0) + rec
  //   body = struct.pack('<IBBHIq', 0x5254534B, 1, 1, 0, len(payload), 1000000) + payload
  //   frame = body + struct.pack('<I', zlib.crc32(body))
  GIVEN("a radar frame with one plot") {
    Frame f{};
    f.kind = FrameKind::kRadar;
    f.count = 1;
    f.t_us = 1000000;
    f.radar[0] = {1500, 0x40000000, -250, 1234, 1, 2};
    const std::vector<std::uint8_t> golden{
        0x4B, 0x53, 0x54, 0x52, 0x01, 0x01, 0x00, 0x00, 0x14, 0x00, 0x00, 0x00, 0x40, 0x42, 0x0F,
        0x00, 0x00, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0xDC, 0x05, 0x00, 0x00, 0x00, 0x00,
        0x00, 0x40, 0x06, 0xFF, 0xFF, 0xFF, 0xD2, 0x04, 0x01, 0x02, 0x3A, 0x24, 0x82, 0x58};
    THEN("encode writes exactly the golden bytes and decode reads them back") {
      REQUIRE(kestrel::test::encode_to_vector(f) == golden);
      const Decoded d = decode_bytes(golden);
      REQUIRE(d.status == Status::kOk);
      REQUIRE(d.consumed == golden.size());
      REQUIRE(kestrel::test::frames_equal(d.frame, f));
    }
  }
  GIVEN("a sonar frame with one reflected arrival and a negative time") {
    // struct.pack('<IBBH', 123456789, 3, 1, 0); t_us = -5
    Frame f{};
    f.kind = FrameKind::kSonar;
    f.count = 1;
    f.t_us = -5;
    f.sonar[0] = {123456789, 3, kestrel::hal::ToaPath::kReflected};
    const std::vector<std::uint8_t> golden{0x4B, 0x53, 0x54, 0x52, 0x01, 0x02, 0x00, 0x00, 0x0C, 0x00, 0x00, 0x00,
                                           0xFB, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x01, 0x00, 0x00, 0x00,
                                           0x15, 0xCD, 0x5B, 0x07, 0x03, 0x01, 0x00, 0x00, 0xDB, 0x27, 0xFD, 0x14};
    THEN("encode writes exactly the golden bytes") { REQUIRE(kestrel::test::encode_to_vector(f) == golden); }
  }
  GIVEN("a PCL frame with one candidate at t = 2^40 us") {
    // struct.pack('<IihH', 2500000, -125000, -300, 0)
    Frame f{};
    f.kind = FrameKind::kPcl;
    f.count = 1;
    f.t_us = std::int64_t{1} << 40;
    f.pcl[0] = {2500000, -125000, -300};
    const std::vector<std::uint8_t> golden{
        0x4B, 0x53, 0x54, 0x52, 0x01, 0x03, 0x00, 0x00, 0x10, 0x00, 0x00, 0x00, 0x00, 0x00,
        0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0xA0, 0x25, 0x26, 0x00,
        0xB8, 0x17, 0xFE, 0xFF, 0xD4, 0xFE, 0x00, 0x00, 0x58, 0x33, 0x84, 0x30};
    THEN("encode writes exactly the golden bytes") { REQUIRE(kestrel::test::encode_to_vector(f) == golden); }
  }
}

SCENARIO("every kind round-trips field by field", "[hal][codec]") {
  for (const FrameKind kind : kKinds) {
    const std::size_t capacity = kestrel::hal::capacity_of(kind);
    for (const std::size_t count : {std::size_t{0}, std::size_t{1}, capacity / 2, capacity}) {
      GIVEN("a random frame of kind " << static_cast<int>(kind) << " with " << count << " items") {
        std::mt19937 rng(static_cast<std::uint32_t>(1000 * static_cast<std::size_t>(kind) + count));
        const Frame f = kestrel::test::random_frame(rng, kind, count);
        WHEN("it is encoded") {
          std::array<std::uint8_t, wire::kMaxEncodedFrameBytes> buf{};
          std::size_t written = 0;
          REQUIRE(encode(f, buf, written) == Status::kOk);
          THEN("the size is header + prefix + records + CRC") {
            REQUIRE(written == wire::frame_size(kind, count));
          }
          THEN("the bytes equal an independent byte-by-byte build") {
            REQUIRE(std::vector<std::uint8_t>(buf.begin(), buf.begin() + static_cast<std::ptrdiff_t>(written)) ==
                    WireBuilder(kind, f.t_us).items(f).build());
          }
          AND_WHEN("it is decoded, followed by unrelated bytes") {
            std::vector<std::uint8_t> in(buf.begin(), buf.begin() + static_cast<std::ptrdiff_t>(written));
            in.insert(in.end(), {0x4B, 0x53, 0x00, 0x01, 0x02});
            const Decoded d = decode_bytes(in);
            THEN("it is kOk, consumes only the frame and equals the input") {
              REQUIRE(d.status == Status::kOk);
              REQUIRE(d.consumed == written);
              REQUIRE(kestrel::test::frames_equal(d.frame, f));
            }
          }
        }
      }
    }
  }
}

SCENARIO("extreme field values survive the round trip", "[hal][codec]") {
  GIVEN("frames holding the minimum and maximum of every field") {
    Frame radar{};
    radar.kind = FrameKind::kRadar;
    radar.count = 2;
    radar.t_us = INT64_MIN;
    radar.radar[0] = {0, INT32_MIN, INT32_MIN, INT16_MIN, 0, 0};
    radar.radar[1] = {UINT32_MAX, INT32_MAX, INT32_MAX, INT16_MAX, 1, UINT8_MAX};
    Frame sonar{};
    sonar.kind = FrameKind::kSonar;
    sonar.count = 2;
    sonar.t_us = INT64_MAX;
    sonar.sonar[0] = {0, 0, kestrel::hal::ToaPath::kDirect};
    sonar.sonar[1] = {UINT32_MAX, UINT8_MAX, kestrel::hal::ToaPath::kReflected};
    Frame pcl{};
    pcl.kind = FrameKind::kPcl;
    pcl.count = 2;
    pcl.t_us = -1;
    pcl.pcl[0] = {0, INT32_MIN, INT16_MIN};
    pcl.pcl[1] = {UINT32_MAX, INT32_MAX, INT16_MAX};
    THEN("each decodes to itself") {
      for (const Frame& f : {radar, sonar, pcl}) {
        const auto bytes = kestrel::test::encode_to_vector(f);
        const Decoded d = decode_bytes(bytes);
        REQUIRE(d.status == Status::kOk);
        REQUIRE(kestrel::test::frames_equal(d.frame, f));
      }
    }
  }
}

SCENARIO("a truncated frame is kTruncated at every length", "[hal][codec]") {
  for (const FrameKind kind : kKinds) {
    GIVEN("a valid frame of kind " << static_cast<int>(kind)) {
      const auto bytes = sample_frame(kind, 7);
      THEN("every proper prefix decodes as kTruncated, consumes 0 and leaves out untouched") {
        for (std::size_t len = 0; len < bytes.size(); ++len) {
          Frame out = sentinel_frame();
          std::size_t consumed = 99;
          INFO("prefix length " << len);
          REQUIRE(decode(std::span<const std::uint8_t>(bytes).first(len), out, consumed) == Status::kTruncated);
          REQUIRE(consumed == 0);
          REQUIRE(is_sentinel(out));
        }
      }
    }
  }
}

SCENARIO("bytes that do not start with the magic are kBadMagic", "[hal][codec]") {
  GIVEN("a valid frame") {
    const auto good = sample_frame(FrameKind::kRadar, 3);
    THEN("changing any one magic byte gives kBadMagic with consumed 1") {
      for (std::size_t i = 0; i < 4; ++i) {
        auto bytes = good;
        bytes[i] = static_cast<std::uint8_t>(bytes[i] + 1);
        Frame out = sentinel_frame();
        std::size_t consumed = 0;
        REQUIRE(decode(bytes, out, consumed) == Status::kBadMagic);
        REQUIRE(consumed == 1);
        REQUIRE(is_sentinel(out));
      }
    }
    THEN("a short input that already disagrees with the magic is kBadMagic, not kTruncated") {
      const std::vector<std::uint8_t> ks{0x4B, 0x00};
      REQUIRE(decode_bytes(ks).status == Status::kBadMagic);
      REQUIRE(decode_bytes(ks).consumed == 1);
    }
    THEN("the frame one byte later, after a stray byte, is kBadMagic") {
      auto bytes = good;
      bytes.insert(bytes.begin(), 0x4B);
      REQUIRE(decode_bytes(bytes).status == Status::kBadMagic);
    }
  }
}

SCENARIO("header fields outside version 1 are refused with the whole frame consumed", "[hal][codec]") {
  GIVEN("CRC-correct frames with a bad version, kind or flags") {
    for (const std::uint8_t version : {std::uint8_t{0}, std::uint8_t{2}, std::uint8_t{255}}) {
      WireBuilder b(FrameKind::kSonar);
      b.sonar(1000, 1, 0);
      b.version = version;
      const auto bytes = b.build();
      const Decoded d = decode_bytes(bytes);
      CHECK(d.status == Status::kUnsupportedVersion);
      CHECK(d.consumed == bytes.size());
    }
    for (const std::uint8_t kind : {std::uint8_t{0}, std::uint8_t{4}, std::uint8_t{255}}) {
      WireBuilder b(FrameKind::kRadar);
      b.radar(1, 2, 3, 4, 0, 0);
      b.kind = kind;
      const auto bytes = b.build();
      const Decoded d = decode_bytes(bytes);
      CHECK(d.status == Status::kUnknownKind);
      CHECK(d.consumed == bytes.size());
    }
    for (const std::uint16_t flags : {std::uint16_t{1}, std::uint16_t{0x8000}}) {
      WireBuilder b(FrameKind::kPcl);
      b.pcl(1, 2, 3);
      b.flags = flags;
      const auto bytes = b.build();
      const Decoded d = decode_bytes(bytes);
      CHECK(d.status == Status::kMalformedFrame);
      CHECK(d.consumed == bytes.size());
    }
  }
}

SCENARIO("payload content that breaks the layout is kMalformedFrame", "[hal][codec]") {
  const auto expect_malformed = [](const WireBuilder& b) {
    const auto bytes = b.build();
    Frame out = sentinel_frame();
    std::size_t consumed = 0;
    CHECK(decode(bytes, out, consumed) == Status::kMalformedFrame);
    CHECK(consumed == bytes.size());
    CHECK(is_sentinel(out));
  };
  GIVEN("a nonzero payload reserved field") {
    WireBuilder b(FrameKind::kRadar);
    b.radar(1, 2, 3, 4, 1, 0);
    b.reserved = 1;
    THEN("it is malformed") { expect_malformed(b); }
  }
  GIVEN("nonzero reserved bytes in a sonar or PCL record") {
    WireBuilder s(FrameKind::kSonar);
    s.sonar(1, 2, 0).sonar(1, 2, 0, 0x0100);
    WireBuilder p(FrameKind::kPcl);
    p.pcl(1, 2, 3, 1);
    THEN("they are malformed") {
      expect_malformed(s);
      expect_malformed(p);
    }
  }
  GIVEN("a count that disagrees with payload_len") {
    WireBuilder more(FrameKind::kRadar);
    more.radar(1, 2, 3, 4, 0, 0);
    more.count = 2;
    WireBuilder fewer(FrameKind::kPcl);
    fewer.pcl(1, 2, 3).pcl(4, 5, 6);
    fewer.count = 1;
    WireBuilder ragged(FrameKind::kSonar);  // 1.5 records
    ragged.sonar(1, 2, 0);
    const std::array<std::uint8_t, 4> half{1, 2, 3, 4};
    ragged.raw_record_bytes(half);
    THEN("they are malformed") {
      expect_malformed(more);
      expect_malformed(fewer);
      expect_malformed(ragged);
    }
  }
  GIVEN("a payload too short to hold count and reserved") {
    for (std::uint32_t len = 0; len < wire::kPayloadPrefixSize; ++len) {
      // Build the frame by hand: header, `len` payload bytes, CRC.
      WireBuilder b(FrameKind::kRadar);
      auto bytes = b.build();  // 20 header + 4 prefix + 4 CRC
      bytes.resize(wire::kHeaderSize + len + wire::kCrcSize);
      bytes[wire::kPayloadLenOffset] = static_cast<std::uint8_t>(len);
      WireBuilder::fix_crc(bytes);
      const Decoded d = decode_bytes(bytes);
      CHECK(d.status == Status::kMalformedFrame);
      CHECK(d.consumed == bytes.size());
    }
  }
  GIVEN("enum fields out of range: has_range_rate = 2, path = 7") {
    WireBuilder r(FrameKind::kRadar);
    r.radar(1, 2, 3, 4, 1, 0).radar(1, 2, 3, 4, 2, 0);
    WireBuilder s(FrameKind::kSonar);
    s.sonar(1, 2, 7);
    THEN("they are malformed") {
      expect_malformed(r);
      expect_malformed(s);
    }
  }
}

SCENARIO("a payload_len beyond the maximum is refused from the header alone", "[hal][codec]") {
  GIVEN("a header announcing kMaxPayloadBytes + 1 bytes, with nothing after it") {
    WireBuilder b(FrameKind::kRadar);
    b.payload_len = static_cast<std::uint32_t>(wire::kMaxPayloadBytes + 1);
    const auto bytes = b.build();
    const auto header = std::span<const std::uint8_t>(bytes).first(wire::kHeaderSize);
    THEN("decode says kMalformedFrame and consumes one byte, to resync") {
      const Decoded d = decode_bytes(header);
      REQUIRE(d.status == Status::kMalformedFrame);
      REQUIRE(d.consumed == 1);
    }
  }
  GIVEN("a header announcing exactly kMaxPayloadBytes, with nothing after it") {
    WireBuilder b(FrameKind::kRadar);
    b.payload_len = static_cast<std::uint32_t>(wire::kMaxPayloadBytes);
    const auto bytes = b.build();
    THEN("decode waits for the rest") {
      REQUIRE(decode_bytes(std::span<const std::uint8_t>(bytes).first(wire::kHeaderSize)).status ==
              Status::kTruncated);
    }
  }
}

SCENARIO("a flipped bit anywhere never decodes as kOk", "[hal][codec]") {
  for (const FrameKind kind : kKinds) {
    GIVEN("a valid frame of kind " << static_cast<int>(kind)) {
      const auto good = sample_frame(kind, 11, 4);
      THEN("flipping any single bit gives the error of the field it hits") {
        for (std::size_t bit = 0; bit < good.size() * 8; ++bit) {
          auto bytes = good;
          const std::size_t at = bit / 8;
          bytes[at] = static_cast<std::uint8_t>(bytes[at] ^ (1u << (bit % 8)));
          const Decoded d = decode_bytes(bytes);
          INFO("bit " << bit << " status " << kestrel::to_string(d.status));
          REQUIRE(d.status != Status::kOk);
          if (at < 4) {
            REQUIRE(d.status == Status::kBadMagic);
          } else if (at >= wire::kPayloadLenOffset && at < wire::kPayloadLenOffset + 4) {
            // A longer length waits for bytes that are not there, an
            // impossible one is refused, a shorter one moves the CRC.
            REQUIRE((d.status == Status::kTruncated || d.status == Status::kMalformedFrame ||
                     d.status == Status::kBadCrc));
          } else {
            REQUIRE(d.status == Status::kBadCrc);
            REQUIRE(d.consumed == good.size());
          }
        }
      }
    }
  }
}

SCENARIO("a frame over its kind's capacity keeps its first items", "[hal][codec]") {
  for (const FrameKind kind : kKinds) {
    const std::size_t capacity = kestrel::hal::capacity_of(kind);
    GIVEN("a CRC-correct frame of kind " << static_cast<int>(kind) << " with capacity + 5 items") {
      std::mt19937 rng(99);
      // Two in-capacity frames whose concatenated items are the wire order.
      const Frame head = kestrel::test::random_frame(rng, kind, capacity);
      const Frame tail = kestrel::test::random_frame(rng, kind, 5);
      WireBuilder b(kind, head.t_us);
      b.items(head).items(tail);
      const auto bytes = b.build();
      WHEN("it is decoded") {
        Frame out{};
        std::size_t consumed = 0;
        const Status s = decode(bytes, out, consumed);
        THEN("the status is kTooManyCandidates and the first capacity items are kept") {
          REQUIRE(s == Status::kTooManyCandidates);
          REQUIRE(consumed == bytes.size());
          REQUIRE(out.count == capacity);
          REQUIRE(kestrel::test::frames_equal(out, head));
        }
      }
    }
    GIVEN("an over-capacity frame with a bad enum in a record beyond the capacity") {
      WireBuilder b(kind);
      for (std::size_t i = 0; i <= capacity; ++i) {
        const bool last = i == capacity;
        switch (kind) {
          case FrameKind::kRadar: b.radar(1, 2, 3, 4, last ? 2 : 0, 0); break;
          case FrameKind::kSonar: b.sonar(1, 2, last ? 7 : 0); break;
          case FrameKind::kPcl: b.pcl(1, 2, 3, last ? 1 : 0); break;
        }
      }
      THEN("the whole frame is malformed") { REQUIRE(decode_bytes(b.build()).status == Status::kMalformedFrame); }
    }
  }
  GIVEN("the largest radar frame the format allows (255 plots) and one more") {
    WireBuilder max(FrameKind::kRadar);
    for (int i = 0; i < 255; ++i) max.radar(static_cast<std::uint32_t>(i), 0, 0, 0, 0, 0);
    WireBuilder over = max;
    over.radar(255, 0, 0, 0, 0, 0);
    THEN("255 plots decode with the first 32 kept; 256 are refused from the header") {
      const Decoded d = decode_bytes(max.build());
      REQUIRE(d.status == Status::kTooManyCandidates);
      REQUIRE(d.frame.count == kestrel::hal::kMaxRadarPlots);
      REQUIRE(d.frame.radar[31].range_mm == 31);
      const Decoded e = decode_bytes(over.build());
      REQUIRE(e.status == Status::kMalformedFrame);
      REQUIRE(e.consumed == 1);
    }
  }
}

SCENARIO("encode refuses what it cannot write", "[hal][codec]") {
  GIVEN("a full-capacity PCL frame") {
    std::mt19937 rng(5);
    const Frame f = kestrel::test::random_frame(rng, FrameKind::kPcl, kestrel::hal::kMaxPclCandidates);
    const std::size_t needed = wire::frame_size(FrameKind::kPcl, f.count);
    THEN("every smaller buffer gives kBufferTooSmall, writes nothing and reports 0 bytes") {
      std::vector<std::uint8_t> buf(needed);
      for (std::size_t size = 0; size < needed; ++size) {
        std::fill(buf.begin(), buf.end(), std::uint8_t{0xEE});
        std::size_t written = 77;
        REQUIRE(encode(f, std::span<std::uint8_t>(buf).first(size), written) == Status::kBufferTooSmall);
        REQUIRE(written == 0);
        REQUIRE(std::all_of(buf.begin(), buf.end(), [](std::uint8_t x) { return x == 0xEE; }));
      }
      std::size_t written = 0;
      REQUIRE(encode(f, buf, written) == Status::kOk);
      REQUIRE(written == needed);
    }
  }
  GIVEN("frames over capacity or of an unknown kind") {
    Frame over{};
    over.kind = FrameKind::kSonar;
    over.count = kestrel::hal::kMaxSonarArrivals + 1;
    Frame unknown{};
    unknown.kind = static_cast<FrameKind>(9);
    std::array<std::uint8_t, wire::kMaxFrameBytes> buf{};
    std::size_t written = 5;
    THEN("encode returns kTooManyCandidates and kUnknownKind") {
      REQUIRE(encode(over, buf, written) == Status::kTooManyCandidates);
      REQUIRE(written == 0);
      written = 5;
      REQUIRE(encode(unknown, buf, written) == Status::kUnknownKind);
      REQUIRE(written == 0);
    }
  }
}

SCENARIO("encode and decode do not allocate", "[hal][codec][alloc]") {
  GIVEN("a full radar frame, its bytes and a corrupted copy") {
    std::mt19937 rng(8);
    const Frame f = kestrel::test::random_frame(rng, FrameKind::kRadar, kestrel::hal::kMaxRadarPlots);
    std::array<std::uint8_t, wire::kMaxEncodedFrameBytes> buf{};
    auto bad = sample_frame(FrameKind::kSonar, 3);
    bad[30] ^= 0x10;
    WHEN("they are encoded and decoded under an allocation guard") {
      std::size_t allocations = 1;
      Status s_enc = Status::kNoData;
      Status s_dec = Status::kNoData;
      Status s_bad = Status::kNoData;
      {
        kestrel::test::AllocationGuard guard;
        std::size_t n = 0;
        Frame out;
        s_enc = encode(f, buf, n);
        s_dec = decode(std::span<const std::uint8_t>(buf).first(n), out, n);
        s_bad = decode(bad, out, n);
        allocations = guard.allocations();
      }
      THEN("nothing was allocated") {
        REQUIRE(s_enc == Status::kOk);
        REQUIRE(s_dec == Status::kOk);
        REQUIRE(s_bad == Status::kBadCrc);
        REQUIRE(allocations == 0);
      }
    }
  }
}

SCENARIO("encode refuses field values that decode would refuse", "[hal][codec]") {
  std::array<std::uint8_t, wire::kMaxFrameBytes> buf{};
  std::size_t written = 5;
  GIVEN("a radar plot with has_range_rate = 2") {
    Frame f{};
    f.kind = FrameKind::kRadar;
    f.count = 1;
    f.radar[0].has_range_rate = 2;
    THEN("encode returns kMalformedFrame and writes nothing") {
      REQUIRE(encode(f, buf, written) == Status::kMalformedFrame);
      REQUIRE(written == 0);
      f.radar[0].has_range_rate = 1;
      REQUIRE(encode(f, buf, written) == Status::kOk);
    }
  }
  GIVEN("a TOA arrival with path 7") {
    Frame f{};
    f.kind = FrameKind::kSonar;
    f.count = 2;
    f.sonar[0].path = kestrel::hal::ToaPath::kReflected;
    f.sonar[1].path = static_cast<kestrel::hal::ToaPath>(7);
    THEN("encode returns kMalformedFrame") {
      REQUIRE(encode(f, buf, written) == Status::kMalformedFrame);
      REQUIRE(written == 0);
    }
  }
}
