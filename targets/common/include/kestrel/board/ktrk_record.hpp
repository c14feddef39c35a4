// SPDX-License-Identifier: Apache-2.0
// KTRK v2: the binary track record every board's sink emits, so a consumer
// reads the same bytes from a Cortex-M UART, a RISC-V Linux process or a
// file (docs/architecture.md). One fixed-size record per track report, never
// split, so a consumer can always resynchronise on the magic; the CRC-32
// tells a damaged record from a real jump. Why binary, the older v1 and the
// rounding choices: docs/porting.md, "KTRK records". Layout, all
// little-endian (tools/ktrk_decode.py reads it):
//
//   off size field
//    0  u32  magic 'K' 'T' 'R' 'K' (0x4B52544B)
//    4  u8   version (2)
//    5  u8   TrackStatus (1 tentative, 2 confirmed)
//    6  u8   flags: bit 0 = associated in this frame
//    7  u8   state layout code (StateLayout below)
//    8  u32  track_id
//   12  i64  t_us, frame time, microseconds
//   20  i32  c[0..5]  state components, x 1000 in the layout's SI units
//                     (mm, mm/s, mm/s^2); those past the count are 0
//   44  u32  sigma_milli  sqrt of the sum of the variances the layout names,
//                         x 1000 (mm)
//   48  u16  age, frames
//   50  u16  hits
//   52  u16  misses (consecutive)
//   54  i16  measurement_index (-1: none)
//   56  u16  nis_centi  NIS x 100 of this frame's association
//   58  u8   component count (0..6)
//   59  u8   reserved, 0
//   60  u32  CRC-32 (hal/crc32.hpp) of bytes 0..59
//
//   layout                  c[0..count-1]                        sigma of
//   1 Cartesian 2-D CV      x_mm y_mm vx_mmps vy_mmps            x, y
//   2 Cartesian 2-D CA      x_mm y_mm vx_mmps vy_mmps            x, y
//                           ax_mmps2 ay_mmps2
//   3 bistatic 1-D          rb_mm drb_mmps (Rb, dRb of PCL)      Rb
//
// The layout code comes from the filter's named state layout
// (Motion::Layout) at compile time: a layout with no code here does not
// compile (add a code and a row to tools/ktrk_decode.py). Scalars are
// rounded half away from zero and saturated to the field in the tracker's
// own precision (integer arithmetic only for a fixed-point tracker); a
// saturated value is the field's end of its sign, and NaN is written as the
// field's minimum (INT32_MIN, or the unsigned maximum for unsigned fields).
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
inline constexpr std::uint8_t kVersion = 2;
inline constexpr std::size_t kMaxComponents = 6;
inline constexpr std::size_t kComponentsOffset = 20;
inline constexpr std::size_t kCrcOffset = 60;
inline constexpr std::size_t kSize = 64;
}  // namespace report_record

/// What the state components of a record mean (byte 7).
enum class StateLayout : std::uint8_t {
  kCartesian2dCv = 1,  ///< x_mm, y_mm, vx_mmps, vy_mmps; sigma of x, y.
  kCartesian2dCa = 2,  ///< as kCartesian2dCv, then ax_mmps2, ay_mmps2.
  kBistatic1d = 3,     ///< rb_mm, drb_mmps (bistatic range and its rate); sigma of Rb.
};

namespace detail {

/// round(v * scale), half away from zero, saturated to int32; NaN -> INT32_MIN.
/// Plain arithmetic in F, the tracker's float or double (no libm rounding call).
template <class F>
std::int32_t to_i32(F v, F scale) {
  const F s = v * scale;
  // Largest F below 2^31: 2^31 - 128 in float, 2^31 - 1 in double.
  constexpr F kMax = sizeof(F) == sizeof(float) ? F(2147483520.0) : F(2147483647.0);
  if (!(s >= -kMax)) return INT32_MIN;  // below range, or NaN
  if (s > kMax) return INT32_MAX;
  return static_cast<std::int32_t>(s + (s >= F(0) ? F(0.5) : F(-0.5)));
}

/// round(v * scale), half up, saturated to [0, max of U]; NaN -> max of U.
template <class U, class F>
U to_unsigned(F v, F scale) {
  constexpr U kMax = static_cast<U>(~U{0});
  const F s = v * scale;
  if (s < F(0)) return U{0};
  if (!(s < static_cast<F>(kMax))) return kMax;  // at or above range, or NaN
  return static_cast<U>(s + F(0.5));
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

template <class L>
concept BistaticLayout = requires { L::kRb; L::kDRb; };
template <class L>
concept Cartesian2dLayout = requires { L::kX; L::kY; L::kVx; L::kVy; } && !requires { L::kZ; };
template <class L>
concept Cartesian2dCaLayout = Cartesian2dLayout<L> && requires { L::kAx; L::kAy; };

/// Which state entries a layout puts in the record, in record order, and
/// whose variances sum to the sigma field.
struct RecordState {
  StateLayout code;
  std::size_t count;
  int index[report_record::kMaxComponents];
  std::size_t sigma_count;
  int sigma_index[2];
};

template <class L>
constexpr RecordState record_state() {
  if constexpr (BistaticLayout<L>) {
    return {StateLayout::kBistatic1d, 2, {L::kRb, L::kDRb, 0, 0, 0, 0}, 1, {L::kRb, 0}};
  } else if constexpr (Cartesian2dCaLayout<L>) {
    return {StateLayout::kCartesian2dCa, 6, {L::kX, L::kY, L::kVx, L::kVy, L::kAx, L::kAy}, 2, {L::kX, L::kY}};
  } else {
    static_assert(Cartesian2dLayout<L>, "this state layout has no KTRK layout code: add one (ktrk_record.hpp)");
    return {StateLayout::kCartesian2dCv, 4, {L::kX, L::kY, L::kVx, L::kVy, 0, 0}, 2, {L::kX, L::kY}};
  }
}

}  // namespace detail

/// The KTRK layout code of a filter's state.
template <class Filter>
inline constexpr StateLayout kRecordLayout = detail::record_state<typename Filter::Layout>().code;

/// Encode `r` as a KTRK v2 record into `out`.
template <class Filter>
void encode_track_record(const TrackReport<Filter>& r, std::span<std::uint8_t, report_record::kSize> out) {
  using Scalar = typename Filter::Scalar;
  using L = typename Filter::Layout;
  static_assert(std::is_floating_point_v<Scalar> || ScalarTraits<Scalar>::kIsFixedPoint,
                "the KTRK encoder takes a floating-point or fixed-point tracker");
  namespace w = hal::wire;

  constexpr detail::RecordState kState = detail::record_state<L>();
  static_assert(kState.count <= report_record::kMaxComponents);

  w::store_u32(out, 0, report_record::kMagic);
  w::store_u8(out, 4, report_record::kVersion);
  w::store_u8(out, 5, static_cast<std::uint8_t>(r.status));
  w::store_u8(out, 6, r.associated ? 1u : 0u);
  w::store_u8(out, 7, static_cast<std::uint8_t>(kState.code));
  w::store_u32(out, 8, r.track_id);
  w::store_i64(out, 12, r.t_us);
  for (std::size_t k = 0; k < report_record::kMaxComponents; ++k) {
    std::int32_t c = 0;
    if (k < kState.count) {
      const Scalar v = r.x(kState.index[k]);
      if constexpr (ScalarTraits<Scalar>::kIsFixedPoint) {
        c = static_cast<std::int32_t>(detail::fixed_to_int(v, 1000, INT32_MIN, INT32_MAX));
      } else {
        c = detail::to_i32<Scalar>(v, Scalar(1000));
      }
    }
    w::store_i32(out, report_record::kComponentsOffset + 4 * k, c);
  }
  if constexpr (ScalarTraits<Scalar>::kIsFixedPoint) {
    Scalar var = r.P(kState.sigma_index[0], kState.sigma_index[0]);
    for (std::size_t k = 1; k < kState.sigma_count; ++k) var = var + r.P(kState.sigma_index[k], kState.sigma_index[k]);
    const Scalar sigma = ScalarTraits<Scalar>::sqrt(var);
    w::store_u32(out, 44, static_cast<std::uint32_t>(detail::fixed_to_int(sigma, 1000, 0, UINT32_MAX)));
    w::store_u16(out, 56, static_cast<std::uint16_t>(detail::fixed_to_int(r.nis, 100, 0, UINT16_MAX)));
  } else {
    Scalar var = r.P(kState.sigma_index[0], kState.sigma_index[0]);
    for (std::size_t k = 1; k < kState.sigma_count; ++k) var += r.P(kState.sigma_index[k], kState.sigma_index[k]);
    w::store_u32(out, 44, detail::to_unsigned<std::uint32_t, Scalar>(std::sqrt(var), Scalar(1000)));
    w::store_u16(out, 56, detail::to_unsigned<std::uint16_t, Scalar>(r.nis, Scalar(100)));
  }
  w::store_u16(out, 48, r.age);
  w::store_u16(out, 50, r.hits);
  w::store_u16(out, 52, r.misses);
  w::store_i16(out, 54, r.measurement_index);
  w::store_u8(out, 58, static_cast<std::uint8_t>(kState.count));
  w::store_u8(out, 59, 0);
  const std::uint32_t crc = hal::crc32(std::span<const std::uint8_t>(out.data(), report_record::kCrcOffset));
  w::store_u32(out, report_record::kCrcOffset, crc);
}

}  // namespace kestrel::board
