// SPDX-License-Identifier: Apache-2.0
// Table-driven CRC-32 (reflected 0xEDB88320). The table is computed by a
// constexpr function at compile time, so there is no generated source to
// keep in step and no start-up cost; it lands in .rodata (flash on a board).
// Two table sizes give the same CRC: 256 entries, one byte per step (1 KiB,
// the default), or with KESTREL_HAL_CRC32_NIBBLE defined 16 entries, four
// bits per step (64 bytes, two lookups per byte), for a board whose flash
// matters more than the few cycles per frame byte (docs/footprint.md).
#include "kestrel/hal/crc32.hpp"

#include <array>
#include <cstddef>

namespace kestrel::hal {
namespace {

constexpr std::uint32_t kPolynomial = 0xEDB88320u;  // 0x04C11DB7 bit-reversed

/// Table of the CRC of every value of the low kBits bits, shifted out kBits times.
template <int kBits>
constexpr std::array<std::uint32_t, (1u << kBits)> make_table() {
  std::array<std::uint32_t, (1u << kBits)> table{};
  for (std::uint32_t i = 0; i < (1u << kBits); ++i) {
    std::uint32_t c = i;
    for (int bit = 0; bit < kBits; ++bit) {
      c = (c & 1u) != 0 ? (c >> 1) ^ kPolynomial : c >> 1;
    }
    table[i] = c;
  }
  return table;
}

#ifdef KESTREL_HAL_CRC32_NIBBLE
constexpr std::array<std::uint32_t, 16> kTable = make_table<4>();
// Spot checks: entry i of the nibble table is entry 16 i of the byte table.
static_assert(kTable[1] == 0x1DB71064u);
static_assert(kTable[8] == 0xEDB88320u);
static_assert(kTable[15] == 0xBDBDF21Cu);
#else
constexpr std::array<std::uint32_t, 256> kTable = make_table<8>();
// Spot checks against the published table (e.g. zlib crc32.h).
static_assert(kTable[1] == 0x77073096u);
static_assert(kTable[128] == 0xEDB88320u);
static_assert(kTable[255] == 0x2D02EF8Du);
#endif

}  // namespace

std::uint32_t crc32_update(std::uint32_t crc, std::span<const std::uint8_t> data) {
  std::uint32_t c = crc ^ 0xFFFFFFFFu;  // undo the final xor of the previous CRC
  for (const std::uint8_t byte : data) {
#ifdef KESTREL_HAL_CRC32_NIBBLE
    c ^= byte;
    c = kTable[c & 0xFu] ^ (c >> 4);  // low nibble, then high nibble
    c = kTable[c & 0xFu] ^ (c >> 4);
#else
    c = kTable[(c ^ byte) & 0xFFu] ^ (c >> 8);
#endif
  }
  return c ^ 0xFFFFFFFFu;
}

std::uint32_t crc32(std::span<const std::uint8_t> data) { return crc32_update(kCrc32Empty, data); }

}  // namespace kestrel::hal
