// SPDX-License-Identifier: Apache-2.0
// Integer-only math for FixedPoint and its ScalarTraits specialisation, so
// every model and filter runs on it unchanged: sqrt and hypot are integer
// square roots of exact 128-bit radicands (hypot never forms r^2 in Q
// format), correctly rounded; atan2, sin and cos are 61-step CORDIC at
// 2^-60 rad with the tables of fixed_point_tables.hpp, rounded once to the
// format, so their internal error stays far under the final rounding
// (tests/core/scalar/fixed_point_math_test.cpp checks it against long
// double); wrap_angle returns (-pi_F, pi_F]. Loop counts are fixed. Details
// and figures: docs/fixed-point.md, "Formats".
#pragma once

#include <array>
#include <bit>
#include <cstdint>

#include "kestrel/scalar/fixed_point.hpp"
#include "kestrel/scalar/fixed_point_tables.hpp"
#include "kestrel/scalar/scalar_traits.hpp"

namespace kestrel {
namespace fixed {

namespace detail {

namespace tables = kestrel::fixed_point_tables;

/// round(v / 2^s), ties to even, on the magnitude (symmetric), 0 <= s < 64.
constexpr std::int64_t round_shift_signed(std::int64_t v, int s) {
  const U128 m = round_shift(U128{0, magnitude(v)}, s);
  const auto r = static_cast<std::int64_t>(m.lo);  // |v| / 2^s < 2^63
  return v < 0 ? -r : r;
}

/// a * 2^-F as an angle in units of 2^-60 rad, reduced modulo 2 pi into
/// (-pi, pi] (pi = tables::kPi). Exact remainder; one 64-step division
/// only when |a| > 2 pi.
constexpr std::int64_t reduce_angle(std::int64_t a_raw, int frac_bits) {
  constexpr std::int64_t kTwoPi = 2 * tables::kPi;
  const int s = tables::kAngleBits - frac_bits;
  const std::uint64_t m = magnitude(a_raw);
  const U128 a60 = shl(U128{0, m}, s);
  // |a| <= 2 pi (every bearing residual) needs no division.
  const bool small = a60.hi == 0 && a60.lo <= static_cast<std::uint64_t>(kTwoPi);
  std::int64_t r = static_cast<std::int64_t>(
      small ? a60.lo : udiv(a60, static_cast<std::uint64_t>(kTwoPi)).r);  // both < 2 pi < 2^63
  if (r > tables::kPi) r -= kTwoPi;
  // r in (-pi, pi] for |a|; negate for a < 0 and keep the interval half-open.
  if (a_raw < 0) r = -r;
  if (r == -tables::kPi) r = tables::kPi;
  return r;
}

/// pi in Q(F): round(pi * 2^F).
template <int F>
constexpr std::int64_t pi_raw() {
  return round_shift_signed(tables::kPi, tables::kAngleBits - F);
}

struct SinCos {
  std::int64_t sin;
  std::int64_t cos;
};

/// sin and cos of an angle in 2^-60 rad with |angle| <= pi (+ a few units),
/// in units of 2^-62.
constexpr SinCos cordic_sincos(std::int64_t angle) {
  bool negate = false;
  if (angle > tables::kHalfPi) {
    angle -= tables::kPi;
    negate = true;
  } else if (angle < -tables::kHalfPi) {
    angle += tables::kPi;
    negate = true;
  }
  std::int64_t x = tables::kInverseGain;
  std::int64_t y = 0;
  std::int64_t z = angle;
  for (int i = 0; i < tables::kCordicIterations; ++i) {
    const std::int64_t dx = x >> i;  // arithmetic shift (defined in C++20)
    const std::int64_t dy = y >> i;
    if (z >= 0) {
      x -= dy;
      y += dx;
      z -= tables::kAtan[i];
    } else {
      x += dy;
      y -= dx;
      z += tables::kAtan[i];
    }
  }
  return negate ? SinCos{-y, -x} : SinCos{y, x};
}

}  // namespace detail

// ---- the functions Eigen and ScalarTraits find by argument-dependent lookup --

template <int F>
constexpr FixedPoint<F> abs(FixedPoint<F> a) {
  return a.raw() < 0 ? -a : a;
}

template <int F>
constexpr bool isfinite(FixedPoint<F> a) {
  return a.is_finite();
}
template <int F>
constexpr bool isinf(FixedPoint<F> a) {
  return !a.is_finite();
}
template <int F>
constexpr bool isnan(FixedPoint<F>) {
  return false;
}

/// Correctly rounded square root; a negative argument saturates (counted).
template <int F>
constexpr FixedPoint<F> sqrt(FixedPoint<F> a) {
  if (!a.is_finite()) return FixedPoint<F>::from_raw(detail::kPosOverflow);
  if (a.raw() < 0) {
    detail::note_overflow();
    return FixedPoint<F>::from_raw(detail::kPosOverflow);
  }
  // sqrt(raw / 2^F) * 2^F = sqrt(raw * 2^F).
  const detail::U128 n = detail::shl(detail::U128{0, static_cast<std::uint64_t>(a.raw())}, F);
  return FixedPoint<F>::from_raw(static_cast<std::int64_t>(detail::isqrt_round(n)));
}

/// Correctly rounded sqrt(a^2 + b^2) from the exact 128-bit sum of squares.
template <int F>
constexpr FixedPoint<F> hypot(FixedPoint<F> a, FixedPoint<F> b) {
  if (!a.is_finite() || !b.is_finite()) return FixedPoint<F>::from_raw(detail::kPosOverflow);
  const std::uint64_t ma = detail::magnitude(a.raw());
  const std::uint64_t mb = detail::magnitude(b.raw());
  // (raw_a^2 + raw_b^2) < 2^127: the sum of two < 2^126 squares cannot carry
  // out. A loop, so that a Thumb-1 image holds one inline copy of the product.
  detail::U128 n{0, 0};
  for (const std::uint64_t m : std::array<std::uint64_t, 2>{ma, mb}) n = detail::add(n, detail::mul_wide(m, m));
  return FixedPoint<F>::from_raw(
      detail::to_raw_saturating(detail::U128{0, detail::isqrt_round(n)}, false));
}

/// atan2(y, x) in [-pi_F, pi_F]; atan2(0, 0) = 0 (as std::atan2(+0, +0)).
template <int F>
constexpr FixedPoint<F> atan2(FixedPoint<F> y, FixedPoint<F> x) {
  namespace t = detail::tables;
  using Q = FixedPoint<F>;
  if (!y.is_finite() || !x.is_finite()) return Q::from_raw(detail::kPosOverflow);
  const std::int64_t yr = y.raw();
  const std::int64_t xr = x.raw();
  // Exact on the axes.
  if (yr == 0) return xr >= 0 ? Q{} : Q::from_raw(detail::pi_raw<F>());
  if (xr == 0) {
    const std::int64_t half = detail::round_shift_signed(t::kHalfPi, t::kAngleBits - F);
    return Q::from_raw(yr > 0 ? half : -half);
  }
  // Normalise the larger magnitude to bit 60: the CORDIC gain (1.65) times
  // sqrt(2) keeps every intermediate below 2^63.
  std::uint64_t ux = detail::magnitude(xr);
  std::uint64_t uy = detail::magnitude(yr);
  const std::uint64_t m = ux > uy ? ux : uy;
  const int shift = std::countl_zero(m) - 3;
  if (shift >= 0) {
    ux <<= shift;
    uy <<= shift;
  } else {
    ux >>= -shift;
    uy >>= -shift;
  }
  // Vectoring on (|x|, y): z -> atan(y / |x|) in [-pi/2, pi/2].
  std::int64_t vx = static_cast<std::int64_t>(ux);
  std::int64_t vy = yr < 0 ? -static_cast<std::int64_t>(uy) : static_cast<std::int64_t>(uy);
  std::int64_t z = 0;
  for (int i = 0; i < t::kCordicIterations; ++i) {
    const std::int64_t dx = vx >> i;
    const std::int64_t dy = vy >> i;
    if (vy > 0) {
      vx += dy;
      vy -= dx;
      z += t::kAtan[i];
    } else {
      vx -= dy;
      vy += dx;
      z -= t::kAtan[i];
    }
  }
  // Left half-plane: atan2(y, x) = +-pi - atan(y / |x|).
  if (xr < 0) z = (yr > 0 ? t::kPi : -t::kPi) - z;
  return Q::from_raw(detail::round_shift_signed(z, t::kAngleBits - F));
}

template <int F>
constexpr FixedPoint<F> sin(FixedPoint<F> a) {
  using Q = FixedPoint<F>;
  if (!a.is_finite()) return Q::from_raw(detail::kPosOverflow);
  const auto sc = detail::cordic_sincos(detail::reduce_angle(a.raw(), F));
  return Q::from_raw(detail::round_shift_signed(sc.sin, detail::tables::kVectorBits - F));
}

template <int F>
constexpr FixedPoint<F> cos(FixedPoint<F> a) {
  using Q = FixedPoint<F>;
  if (!a.is_finite()) return Q::from_raw(detail::kPosOverflow);
  const auto sc = detail::cordic_sincos(detail::reduce_angle(a.raw(), F));
  return Q::from_raw(detail::round_shift_signed(sc.cos, detail::tables::kVectorBits - F));
}

/// The angle modulo 2 pi in (-pi_F, pi_F]; an angle already in that interval
/// is returned unchanged (so wrapping is idempotent) and -pi_F maps to pi_F,
/// as -pi does in the floating-point traits.
template <int F>
constexpr FixedPoint<F> wrap_angle(FixedPoint<F> a) {
  using Q = FixedPoint<F>;
  if (!a.is_finite()) return a;
  constexpr std::int64_t kPiF = detail::pi_raw<F>();
  if (a.raw() > -kPiF && a.raw() <= kPiF) return a;
  if (a.raw() == -kPiF) return Q::from_raw(kPiF);
  std::int64_t r =
      detail::round_shift_signed(detail::reduce_angle(a.raw(), F), detail::tables::kAngleBits - F);
  if (r <= -kPiF) r = kPiF;  // rounding can land on -pi_F; the interval is half-open
  return Q::from_raw(r);
}

}  // namespace fixed

/// ScalarTraits for the fixed-point scalar: integer-only implementations.
template <int F>
struct ScalarTraits<FixedPoint<F>> {
  using Q = FixedPoint<F>;
  static constexpr bool kIsFixedPoint = true;
  /// Host code and constant expressions only (see FixedPoint::from_double).
  static constexpr Q from_double(double v) { return Q::from_double(v); }
  static constexpr double to_double(Q v) { return static_cast<double>(v); }
  /// round(num / den): integer sensor units (mm, binary angle) to the scalar.
  static constexpr Q from_ratio(std::int64_t num, std::int64_t den) { return Q::from_ratio(num, den); }
  static constexpr Q pi() { return Q::from_raw(fixed::detail::pi_raw<F>()); }
  static constexpr bool is_finite(Q v) { return v.is_finite(); }
  static constexpr Q sqrt(Q v) { return fixed::sqrt(v); }
  static constexpr Q hypot(Q a, Q b) { return fixed::hypot(a, b); }
  static constexpr Q atan2(Q y, Q x) { return fixed::atan2(y, x); }
  static constexpr Q sin(Q v) { return fixed::sin(v); }
  static constexpr Q cos(Q v) { return fixed::cos(v); }
  static constexpr Q abs(Q v) { return fixed::abs(v); }
  /// Largest finite value.
  static constexpr Q max_value() { return Q::from_raw(fixed::detail::kMaxFinite); }
  static constexpr Q wrap_angle(Q a) { return fixed::wrap_angle(a); }
};

}  // namespace kestrel
