// SPDX-License-Identifier: Apache-2.0
// CRC-32 against the published check value and zlib, and the incremental
// API against the one-shot one.
#include "kestrel/hal/crc32.hpp"

#include <array>
#include <catch2/catch.hpp>
#include <cstdint>
#include <random>
#include <span>
#include <vector>

namespace {

std::span<const std::uint8_t> bytes_of(const char* s, std::size_t n) {
  return {reinterpret_cast<const std::uint8_t*>(s), n};
}

}  // namespace

SCENARIO("CRC-32 matches the IEEE 802.3 / zlib reference values", "[hal][crc32]") {
  GIVEN("the standard check string \"123456789\"") {
    const auto msg = bytes_of("123456789", 9);
    THEN("its CRC is the catalogue check value 0xCBF43926") { REQUIRE(kestrel::hal::crc32(msg) == 0xCBF43926u); }
  }
  GIVEN("the empty message") {
    THEN("its CRC is 0") { REQUIRE(kestrel::hal::crc32({}) == 0u); }
  }
  GIVEN("strings whose CRC was computed with Python's zlib.crc32") {
    // python3 -c "import zlib; print(hex(zlib.crc32(b'The quick brown fox jumps over the lazy dog')))"
    const char* fox = "The quick brown fox jumps over the lazy dog";
    const std::array<std::uint8_t, 4> zeros{0, 0, 0, 0};  // zlib.crc32(bytes(4)) = 0x2144df1c
    THEN("the CRCs agree") {
      REQUIRE(kestrel::hal::crc32(bytes_of(fox, 43)) == 0x414FA339u);
      REQUIRE(kestrel::hal::crc32(zeros) == 0x2144DF1Cu);
    }
  }
}

SCENARIO("crc32_update chains like zlib's crc32", "[hal][crc32]") {
  GIVEN("a random message") {
    std::mt19937 rng(12345);
    std::vector<std::uint8_t> msg(1000);
    for (auto& b : msg) b = static_cast<std::uint8_t>(rng());
    const std::uint32_t whole = kestrel::hal::crc32(msg);
    WHEN("it is fed in two parts split at every position") {
      THEN("the chained CRC equals the one-shot CRC") {
        const std::span<const std::uint8_t> s(msg);
        for (std::size_t split = 0; split <= msg.size(); ++split) {
          const std::uint32_t first = kestrel::hal::crc32_update(kestrel::hal::kCrc32Empty, s.first(split));
          REQUIRE(kestrel::hal::crc32_update(first, s.subspan(split)) == whole);
        }
      }
    }
    WHEN("one bit is flipped") {
      THEN("the CRC changes (CRC-32 detects every single-bit error)") {
        for (std::size_t bit = 0; bit < msg.size() * 8; bit += 7) {
          auto m = msg;
          m[bit / 8] = static_cast<std::uint8_t>(m[bit / 8] ^ (1u << (bit % 8)));
          REQUIRE(kestrel::hal::crc32(m) != whole);
        }
      }
    }
  }
}
