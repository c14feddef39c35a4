// KTRK v1: the binary track record every board's sink emits, so a consumer
// reads the same bytes from a Cortex-M UART, a RISC-V Linux process or a
// file (SPEC section 8: the same core and the same wire formats on every
// board). Each track report becomes one fixed-size record; a record is never
// split, so a consumer can always resynchronise on the magic.
//
// Binary rather than text: 56 bytes per track instead of ~120 characters,
// no number formatting code (printf is banned from the images), integer
// fields in the same units as the wire frames, and a CRC-32 so the host
// can tell a damaged record from a real jump. Layout, all little-endian:
//
//   off size field
//    0  u32  magic 'K' 'T' 'R' 'K' (0x4B52544B)
//    4  u8   version (1)
//    5  u8   TrackStatus (1 tentative, 2 confirmed)
//    6  u8   flags: bit 0 = associated in this frame
//    7  u8   reserved, 0
//    8  u32  track_id
//   12  i64  t_us, frame time, microseconds
//   20  i32  x_mm       position x, millimetres (sensor frame)
//   24  i32  y_mm       position y, millimetres
//   28  i32  vx_mmps    velocity x, mm/s
//   32  i32  vy_mmps    velocity y, mm/s
//   36  u32  pos_sigma_mm  sqrt(var x + var y), millimetres
//   40  u16  age, frames
//   42  u16  hits
//   44  u16  misses (consecutive)
//   46  i16  measurement_index (-1: none)
//   48  u16  nis_centi  NIS x 100 of this frame's association
//   50  u16  reserved, 0
//   52  u32  CRC-32 (hal/crc32.hpp) of bytes 0..51
//
// Scalars are converted to float, then rounded and saturated to the field
// (float resolves 1 mm up to 16.7 km, and the fields are integers anyway);
// NaN is written as the field's minimum (INT32_MIN, or the unsigned maximum
// for unsigned fields). Written by the Cortex-M4F engineer for that board
// (targets/cortex-m4f/uart_sink.hpp) and moved here unchanged so every board
// shares one encoder. A fixed-point tracker (issue 8) is encoded with integer
// arithmetic only, rounding half away from zero as the float path does; a
// saturated value is written as the field's end of its sign.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>

#include "kestrel/hal/crc32.hpp"
#include "kestrel/hal/frame_format.hpp"
#include "kestrel/scalar/fixed_point_math.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/tracking/track.hpp"

namespace kestrel::board {

namespace report_record {
inline constexpr std::uint32_t kMagic = 0x4B52544Bu;  ///< 'K' 'T' 'R' 'K' on the wire.
inline constexpr std::uint8_t kVersion = 1;
inline constexpr std::size_t kCrcOffset = 52;
inline constexpr std::size_t kSize = 56;
}  // namespace report_record

namespace detail {

/// round(v * scale), half away from zero, saturated to int32; NaN -> INT32_MIN.
/// Plain float arithmetic (no libm rounding call).
inline std::int32_t to_i32(float v, float scale) {
  const float s = v * scale;
  constexpr float kMax = 2147483520.0f;  // largest float below 2^31
  if (!(s >= -kMax)) return INT32_MIN;   // below range, or NaN
  if (s > kMax) return INT32_MAX;
  return static_cast<std::int32_t>(s + (s >= 0.0f ? 0.5f : -0.5f));
}

/// round(v * scale), half up, saturated to [0, max of U]; NaN -> max of U.
template <class U>
U to_unsigned(float v, float scale) {
  constexpr U kMax = static_cast<U>(~U{0});
  const float s = v * scale;
  if (s < 0.0f) return U{0};
  if (!(s < static_cast<float>(kMax))) return kMax;  // at or above range, or NaN
  return static_cast<U>(s + 0.5f);
}

/// round(v * scale) of a fixed-point value, half away from zero, saturated to
/// [lo, hi]: exact 128-bit product, integer arithmetic only (a fixed-point
/// image links no float).
template <class Q>
std::int64_t fixed_to_int(Q v, std::uint32_t scale, std::int64_t lo, std::int64_t hi) {
  namespace fd = fixed::detail;
  if (!v.is_finite()) return v.raw() < 0 ? lo : hi;
  const bool negative = v.raw() < 0;
  const fd::U128 half{0, std::uint64_t{1} << (Q::kFractionBits - 1)};
  const fd::U128 q = fd::shr(fd::add(fd::mul_wide(fd::magnitude(v.raw()), scale), half), Q::kFractionBits);
  if (q.hi != 0 || q.lo > static_cast<std::uint64_t>(INT64_MAX)) return negative ? lo : hi;
  const std::int64_t r = negative ? -static_cast<std::int64_t>(q.lo) : static_cast<std::int64_t>(q.lo);
  return r < lo ? lo : (r > hi ? hi : r);
}

}  // namespace detail

/// Encode `r` as a KTRK v1 record into `out`.
template <class Filter>
void encode_track_record(const TrackReport<Filter>& r, std::span<std::uint8_t, report_record::kSize> out) {
  using Scalar = typename Filter::Scalar;
  using L = typename Filter::Layout;
  static_assert(std::is_floating_point_v<Scalar> || ScalarTraits<Scalar>::kIsFixedPoint,
                "the KTRK encoder takes a floating-point or fixed-point tracker");
  namespace w = hal::wire;

  w::store_u32(out, 0, report_record::kMagic);
  w::store_u8(out, 4, report_record::kVersion);
  w::store_u8(out, 5, static_cast<std::uint8_t>(r.status));
  w::store_u8(out, 6, r.associated ? 1u : 0u);
  w::store_u8(out, 7, 0);
  w::store_u32(out, 8, r.track_id);
  w::store_i64(out, 12, r.t_us);
  if constexpr (ScalarTraits<Scalar>::kIsFixedPoint) {
    const auto i32 = [](Scalar v) {
      return static_cast<std::int32_t>(detail::fixed_to_int(v, 1000, INT32_MIN, INT32_MAX));
    };
    w::store_i32(out, 20, i32(r.x(L::kX)));
    w::store_i32(out, 24, i32(r.x(L::kY)));
    w::store_i32(out, 28, i32(r.x(L::kVx)));
    w::store_i32(out, 32, i32(r.x(L::kVy)));
    const Scalar pos_sigma = ScalarTraits<Scalar>::sqrt(r.P(L::kX, L::kX) + r.P(L::kY, L::kY));
    w::store_u32(out, 36, static_cast<std::uint32_t>(detail::fixed_to_int(pos_sigma, 1000, 0, UINT32_MAX)));
    w::store_u16(out, 48, static_cast<std::uint16_t>(detail::fixed_to_int(r.nis, 100, 0, UINT16_MAX)));
  } else {
    const auto f = [](Scalar v) { return static_cast<float>(v); };
    w::store_i32(out, 20, detail::to_i32(f(r.x(L::kX)), 1000.0f));
    w::store_i32(out, 24, detail::to_i32(f(r.x(L::kY)), 1000.0f));
    w::store_i32(out, 28, detail::to_i32(f(r.x(L::kVx)), 1000.0f));
    w::store_i32(out, 32, detail::to_i32(f(r.x(L::kVy)), 1000.0f));
    const float pos_var = f(r.P(L::kX, L::kX)) + f(r.P(L::kY, L::kY));
    w::store_u32(out, 36, detail::to_unsigned<std::uint32_t>(std::sqrt(pos_var), 1000.0f));
    w::store_u16(out, 48, detail::to_unsigned<std::uint16_t>(f(r.nis), 100.0f));
  }
  w::store_u16(out, 40, r.age);
  w::store_u16(out, 42, r.hits);
  w::store_u16(out, 44, r.misses);
  w::store_i16(out, 46, r.measurement_index);
  w::store_u16(out, 50, 0);
  const std::uint32_t crc = hal::crc32(std::span<const std::uint8_t>(out.data(), report_record::kCrcOffset));
  w::store_u32(out, report_record::kCrcOffset, crc);
}

}  // namespace kestrel::board
