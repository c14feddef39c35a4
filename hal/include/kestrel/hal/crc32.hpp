// SPDX-License-Identifier: Apache-2.0
// CRC-32 as in IEEE 802.3 and zlib's crc32(): reflected polynomial
// 0xEDB88320, initial value 0xFFFFFFFF, final xor 0xFFFFFFFF; check value
// crc32("123456789") = 0xCBF43926. It protects header and payload of a wire
// frame (frame_format.hpp). Table-driven and built at compile time: one
// byte per step with a 1 KiB table, or, where a board defines
// KESTREL_HAL_CRC32_NIBBLE for its hal build, four bits per step with a
// 64-byte table (same CRC).
#pragma once

#include <cstdint>
#include <span>

namespace kestrel::hal {

/// CRC of the empty message; the starting value for crc32_update().
inline constexpr std::uint32_t kCrc32Empty = 0;

/// Extend a CRC over more bytes, zlib style: `crc` is the finished CRC of
/// the bytes seen so far (kCrc32Empty for none) and the result is the
/// finished CRC of those bytes followed by `data`, so
/// crc32_update(crc32(a), b) == crc32(a ++ b).
/// @param crc  CRC-32 of the preceding bytes.
/// @param data bytes to append (may be empty).
/// @return the CRC-32 of the concatenation. Never fails.
[[nodiscard]] std::uint32_t crc32_update(std::uint32_t crc, std::span<const std::uint8_t> data);

/// One-shot CRC-32 of `data` (= crc32_update(kCrc32Empty, data)).
[[nodiscard]] std::uint32_t crc32(std::span<const std::uint8_t> data);

}  // namespace kestrel::hal
