// SPDX-License-Identifier: Apache-2.0
// ScalarTraits<S>: the few operations core needs beyond + - * /, chosen at
// compile time per scalar type (docs/models.md). double and float map to
// <cmath>, except atan2, which is Kestrel's own (math/atan2.hpp), and
// deterministic_exp/deterministic_log (math/exp_log.hpp), for results that
// must not depend on the C library; the
// fixed-point Q type (kestrel/scalar/fixed_point.hpp) brings its
// own specialisation with integer-only implementations. Every model and
// filter calls these, never std:: math directly, so the scalar is a true
// template parameter.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "kestrel/math/atan2.hpp"
#include "kestrel/math/exp_log.hpp"

namespace kestrel {

template <class S>
struct ScalarTraits;

namespace detail {
template <class F>
struct FloatingScalarTraits {
  static constexpr bool kIsFixedPoint = false;
  static constexpr F from_double(double v) { return static_cast<F>(v); }
  static constexpr double to_double(F v) { return static_cast<double>(v); }
  /// An integer count in units of 1/kDenominator (e.g. millimetres, kDenominator = 1000).
  static constexpr F from_ratio(std::int64_t num, std::int64_t den) {
    return static_cast<F>(static_cast<double>(num) / static_cast<double>(den));
  }
  static F pi() { return static_cast<F>(3.14159265358979323846); }
  static bool is_finite(F v) { return std::isfinite(v); }
  static F sqrt(F v) { return std::sqrt(v); }
  static F hypot(F a, F b) { return std::hypot(a, b); }
  /// The same bits on every IEEE platform (no libm atan2: glibc and newlib
  /// differ in the last bit, so a board and the host would not agree).
  static F atan2(F y, F x) { return deterministic_atan2(y, x); }
  static F sin(F v) { return std::sin(v); }
  static F cos(F v) { return std::cos(v); }
  static F abs(F v) { return std::fabs(v); }
  static F log(F v) { return std::log(v); }
  static F exp(F v) { return std::exp(v); }
  /// e^v and ln v (v > 0) with the same bits on every IEEE platform, unlike
  /// libm's (glibc and newlib differ in the last bit). exp: |v| <= 700 in
  /// double, 80 in float.
  static F deterministic_exp(F v) { return detail::deterministic_exp(v); }
  static F deterministic_log(F v) { return detail::deterministic_log(v); }
  static F max_value() { return std::numeric_limits<F>::max(); }
  /// (-pi, pi]: std::remainder gives [-pi, pi] with no loop; map -pi to +pi.
  /// Fast paths, bit for bit what remainder() returns: an angle already in
  /// (-pi, pi] is returned as is (quotient 0), and one in (pi, 2pi] or
  /// (-2pi, -pi] (the difference of two wrapped angles, every bearing
  /// residual) moves by one turn, a subtraction that is exact there
  /// (Sterbenz: the operands are within a factor 2). Both skip a slow libm
  /// call in the common case (every gate test and every CRPF particle).
  static F wrap_angle(F a) {
    constexpr F kTwoPi = static_cast<F>(2.0 * 3.14159265358979323846);
    if (a > -pi() && a <= pi()) return a;
    if (a > pi() && a <= kTwoPi) return a - kTwoPi;
    if (a <= -pi() && a > -kTwoPi) return a + kTwoPi;
    const F r = std::remainder(a, kTwoPi);
    return r <= -pi() ? r + kTwoPi : r;
  }
};
}  // namespace detail

template <>
struct ScalarTraits<double> : detail::FloatingScalarTraits<double> {};
template <>
struct ScalarTraits<float> : detail::FloatingScalarTraits<float> {
  /// num / den rounded once to float, in float and integer arithmetic only
  /// (an FPU without double precision does no soft double here). For |num|
  /// and |den| up to 2^53 the result is the same float, bit for bit, as
  /// float(double(num) / double(den)) (what the double-precision traits
  /// compute): a quotient of two exact doubles rounded to double and then to
  /// float is rounded correctly, since 53 >= 2 * 24 + 2 (Figueroa, "When is
  /// double rounding innocuous?", 1995). Beyond 2^53 this one is the exact one.
  static constexpr float from_ratio(std::int64_t num, std::int64_t den) { return ratio_to_float(num, den); }

  static constexpr float ratio_to_float(std::int64_t num, std::int64_t den) {
    constexpr std::int64_t kExact = std::int64_t{1} << 24;  // integers a float holds exactly
    if (num > -kExact && num < kExact && den > 0 && den <= kExact) {
      // Both exact in float: one correctly rounded IEEE division.
      return static_cast<float>(static_cast<std::int32_t>(num)) / static_cast<float>(static_cast<std::int32_t>(den));
    }
    if (den > 0 && (den & (den - 1)) == 0 && num >= std::numeric_limits<std::int32_t>::min() &&
        num <= std::numeric_limits<std::int32_t>::max()) {
      // A power-of-two denominator (e.g. 2^31 for a binary angle): round num
      // once to float, then scale by 2^-k, which is exact at these exponents.
      const int k = std::countr_zero(static_cast<std::uint64_t>(den));
      const float scale = std::bit_cast<float>(static_cast<std::uint32_t>(127 - k) << 23);
      return static_cast<float>(static_cast<std::int32_t>(num)) * scale;
    }
    return ratio_to_float_slow(num, den);
  }

 private:
  /// Correctly rounded num / den by long division: the integer quotient,
  /// then fraction bits until 27 significant bits are known, the remainder
  /// as sticky bit, round to nearest even. Every loop has a constant bound.
  static constexpr float ratio_to_float_slow(std::int64_t num, std::int64_t den) {
    const bool neg = (num < 0) != (den < 0);
    const std::uint64_t a = num < 0 ? std::uint64_t{0} - static_cast<std::uint64_t>(num) : static_cast<std::uint64_t>(num);
    const std::uint64_t b = den < 0 ? std::uint64_t{0} - static_cast<std::uint64_t>(den) : static_cast<std::uint64_t>(den);
    const std::uint32_t sign = neg ? 0x80000000u : 0u;
    if (b == 0) {  // as the double division: +-inf, or NaN for 0 / 0
      return a == 0 ? std::numeric_limits<float>::quiet_NaN() : std::bit_cast<float>(sign | 0x7F800000u);
    }
    if (a == 0) return std::bit_cast<float>(sign);  // 0 / -d is -0, as in double
    std::uint64_t q = 0;
    std::uint64_t r = 0;
    if (a <= 0xFFFFFFFFu && b <= 0xFFFFFFFFu) {  // one 32-bit divide (UDIV on ARMv7-M)
      q = static_cast<std::uint32_t>(a) / static_cast<std::uint32_t>(b);
      r = static_cast<std::uint32_t>(a) % static_cast<std::uint32_t>(b);
    } else {  // 64-bit operands: shift-subtract, one bit of a per step (r < b <= 2^63)
      for (int i = 63; i >= 0; --i) {
        r = (r << 1) | ((a >> i) & 1u);
        q <<= 1;
        if (r >= b) {
          r -= b;
          q |= 1u;
        }
      }
    }
    int exp2 = 0;  // value = (q + r / b) * 2^exp2
    for (int i = 0; i < 96 && q < (std::uint64_t{1} << 26); ++i) {
      r <<= 1;
      q <<= 1;
      if (r >= b) {
        r -= b;
        q |= 1u;
      }
      --exp2;
    }
    const int shift = (64 - std::countl_zero(q)) - 24;  // >= 3: q has 27 or more bits
    std::uint64_t mant = q >> shift;
    const std::uint64_t rest = q & ((std::uint64_t{1} << shift) - 1u);
    const std::uint64_t half = std::uint64_t{1} << (shift - 1);
    if (rest > half || (rest == half && (r != 0 || (mant & 1u) != 0))) ++mant;
    int e = exp2 + shift;
    if (mant == (std::uint64_t{1} << 24)) {
      mant >>= 1;
      ++e;
    }
    // mant in [2^23, 2^24): biased exponent e + 23 + 127, between 41 and 190 here.
    return std::bit_cast<float>(sign | (static_cast<std::uint32_t>(e + 150) << 23) |
                                (static_cast<std::uint32_t>(mant) & 0x7FFFFFu));
  }
};

/// Shorthand for a double constant in scalar S; evaluated at compile time for
/// floating types (the fixed-point type makes it constexpr too).
template <class S>
constexpr S lit(double v) {
  return ScalarTraits<S>::from_double(v);
}

/// Wrap an angle to (-pi, pi]. The single place every bearing wrap goes
/// through (measurement models call it from residual()).
template <class S>
S wrap_angle(S a) {
  return ScalarTraits<S>::wrap_angle(a);
}

}  // namespace kestrel
