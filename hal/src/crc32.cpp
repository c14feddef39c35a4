// SPDX-License-Identifier: Apache-2.0
// Table-driven CRC-32 (reflected 0xEDB88320). The table is computed by a
// constexpr function at compile time, so there is no generated source to
// keep in step and no start-up cost; it lands in .rodata (flash on a board).
#include "kestrel/hal/crc32.hpp"

#include <array>
#include <cstddef>

namespace kestrel::hal {
namespace {

constexpr std::uint32_t kPolynomial = 0xEDB88320u;  // 0x04C11DB7 bit-reversed

constexpr std::array<std::uint32_t, 256> make_table() {
  std::array<std::uint32_t, 256> table{};
  for (std::uint32_t i = 0; i < 256; ++i) {
    std::uint32_t c = i;
    for (int bit = 0; bit < 8; ++bit) {
      c = (c & 1u) != 0 ? (c >> 1) ^ kPolynomial : c >> 1;
    }
    table[i] = c;
  }
  return table;
}

constexpr std::array<std::uint32_t, 256> kTable = make_table();

// Spot checks against the published table (e.g. zlib crc32.h).
static_assert(kTable[1] == 0x77073096u);
static_assert(kTable[128] == 0xEDB88320u);
static_assert(kTable[255] == 0x2D02EF8Du);

}  // namespace

std::uint32_t crc32_update(std::uint32_t crc, std::span<const std::uint8_t> data) {
  std::uint32_t c = crc ^ 0xFFFFFFFFu;  // undo the final xor of the previous CRC
  for (const std::uint8_t byte : data) {
    c = kTable[(c ^ byte) & 0xFFu] ^ (c >> 8);
  }
  return c ^ 0xFFFFFFFFu;
}

std::uint32_t crc32(std::span<const std::uint8_t> data) { return crc32_update(kCrc32Empty, data); }

}  // namespace kestrel::hal
