// SPDX-License-Identifier: Apache-2.0
// ScalarTraits<S>: the few operations core needs beyond + - * /, chosen at
// compile time per scalar type (SPEC section 2). double and float map to
// <cmath>; the fixed-point Q type (kestrel/scalar/fixed_point.hpp) brings its
// own specialisation with integer-only implementations. Every model and
// filter calls these, never std:: math directly, so the scalar is a true
// template parameter.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

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
  static F atan2(F y, F x) { return std::atan2(y, x); }
  static F sin(F v) { return std::sin(v); }
  static F cos(F v) { return std::cos(v); }
  static F abs(F v) { return std::fabs(v); }
  static F log(F v) { return std::log(v); }
  static F exp(F v) { return std::exp(v); }
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
struct ScalarTraits<float> : detail::FloatingScalarTraits<float> {};

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
