// SPDX-License-Identifier: Apache-2.0
// KTRK v2: the binary track record every board's sink emits, so a consumer
// reads the same bytes from a Cortex-M UART, a RISC-V Linux process or a
// file: one fixed-size, CRC-checked 64-byte record per track report, its
// state components chosen at compile time from the filter's state layout.
// The layout, the codes and the rounding rules: docs/wire_format.md,
// "Track records (KTRK v2)"; tools/ktrk_decode.py reads it.
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
