// SPDX-License-Identifier: Apache-2.0
// Fixed-point math against exact or long-double references over large random
// sets. sqrt and hypot are checked exactly (the integer square root is
// correctly rounded: r^2 - r < N <= r^2 + r for N the exact radicand);
// atan2, sin, cos and wrap_angle against long double (64-bit mantissa, so
// the reference error is below 2^-20 LSB of either format) with the bound
// the header claims: 0.5 LSB plus 2^-10 LSB for the CORDIC's internal error.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <random>

#include "kestrel/scalar/fixed_point_math.hpp"
#include "kestrel/scalar/fixed_point_io.hpp"

namespace {

__extension__ typedef unsigned __int128 U128;

constexpr int kSamples = 200000;
constexpr long double kPiL = 3.141592653589793238462643383279502884L;
/// Claimed bound of the CORDIC functions, in LSB: the final rounding plus
/// the internal error (below 2^-50 rad, i.e. < 2^-10 LSB of Q23.40).
constexpr long double kCordicBoundLsb = 0.5L + 1.0L / 1024;

std::int64_t random_raw(std::mt19937_64& g, int max_bits) {
  const int bits = static_cast<int>(g() % static_cast<unsigned>(max_bits)) + 1;
  const auto v = static_cast<std::int64_t>(g() >> (64 - bits));
  return (g() & 1) != 0 ? -v : v;
}

template <class Q>
long double exact(Q v) {
  return std::ldexp(static_cast<long double>(v.raw()), -Q::kFractionBits);  // 63 bits fit in 64
}

template <class Q>
long double error_lsb(Q got, long double want) {
  return std::fabs(static_cast<long double>(got.raw()) - std::ldexp(want, Q::kFractionBits));
}

/// true if r = round(sqrt(n)): n in [r^2 - r + 1, r^2 + r] (n = 0 for r = 0).
bool is_rounded_sqrt(std::uint64_t r, U128 n) {
  const U128 rr = static_cast<U128>(r) * r;
  return (r == 0 ? n == 0 : n + r > rr) && n <= rr + r;
}

}  // namespace

TEMPLATE_TEST_CASE("Scenario: sqrt and hypot are correctly rounded", "[fixed_point][math]", kestrel::Q31_32,
                   kestrel::Q23_40) {
  using Q = TestType;
  constexpr int F = Q::kFractionBits;
  std::mt19937_64 g(4242u + F);
  kestrel::reset_fixed_point_overflow_count();
  GIVEN(kSamples << " random non-negative values") {
    int bad = 0;
    for (int i = 0; i < kSamples; ++i) {
      const std::int64_t a = std::abs(random_raw(g, 63));
      const Q r = kestrel::fixed::sqrt(Q::from_raw(a));
      bad += is_rounded_sqrt(static_cast<std::uint64_t>(r.raw()), static_cast<U128>(a) << F) ? 0 : 1;
    }
    THEN("sqrt(a) = round(sqrt(raw * 2^F)) exactly") { CHECK(bad == 0); }
  }
  GIVEN(kSamples << " random pairs, up to the format's full range") {
    int bad = 0;
    for (int i = 0; i < kSamples; ++i) {
      const std::int64_t a = random_raw(g, 62);
      const std::int64_t b = random_raw(g, 62);
      const Q r = kestrel::fixed::hypot(Q::from_raw(a), Q::from_raw(b));
      const U128 n = static_cast<U128>(static_cast<__int128>(a) * a) + static_cast<U128>(static_cast<__int128>(b) * b);
      bad += r.is_finite() && is_rounded_sqrt(static_cast<std::uint64_t>(r.raw()), n) ? 0 : 1;
    }
    THEN("hypot is the rounded root of the exact sum of squares, with no overflow of r^2") {
      CHECK(bad == 0);
      CHECK(kestrel::fixed_point_overflow_count() == 0);
    }
  }
  GIVEN("a negative argument and a result past the range") {
    THEN("both saturate and are counted") {
      CHECK_FALSE(kestrel::fixed::sqrt(Q(-1)).is_finite());
      const Q big = Q::from_raw(INT64_MAX - 1);
      CHECK_FALSE(kestrel::fixed::hypot(big, big).is_finite());
      CHECK(kestrel::fixed_point_overflow_count() == 2);
    }
  }
}

TEMPLATE_TEST_CASE("Scenario: atan2 by CORDIC is within 0.5 LSB of the exact angle", "[fixed_point][math]",
                   kestrel::Q31_32, kestrel::Q23_40) {
  using Q = TestType;
  std::mt19937_64 g(99u + Q::kFractionBits);
  GIVEN(kSamples << " random (y, x) over all quadrants and magnitudes") {
    long double worst = 0;
    for (int i = 0; i < kSamples; ++i) {
      const Q y = Q::from_raw(random_raw(g, 62));
      const Q x = Q::from_raw(random_raw(g, 62));
      const Q got = kestrel::fixed::atan2(y, x);
      long double want = std::atan2(exact(y), exact(x));
      // The cut at -pi: the fixed-point result may round onto -pi_F.
      if (got.raw() < 0 && want > 3) want -= 2 * kPiL;
      worst = std::max(worst, error_lsb(got, want));
    }
    INFO("largest atan2 error: " << static_cast<double>(worst) << " LSB");
    THEN("the error is at most 0.5 LSB plus the CORDIC margin") { CHECK(worst <= kCordicBoundLsb); }
  }
  GIVEN("the axes and the origin") {
    THEN("the results are exact") {
      CHECK(kestrel::fixed::atan2(Q(0), Q(5)) == Q(0));
      CHECK(kestrel::fixed::atan2(Q(0), Q(-5)) == kestrel::ScalarTraits<Q>::pi());
      CHECK(kestrel::fixed::atan2(Q(0), Q(0)) == Q(0));
      CHECK(error_lsb(kestrel::fixed::atan2(Q(3), Q(0)), kPiL / 2) <= 0.5L);
      CHECK(error_lsb(kestrel::fixed::atan2(Q(-3), Q(0)), -kPiL / 2) <= 0.5L);
      CHECK(error_lsb(kestrel::fixed::atan2(Q(1), Q(1)), kPiL / 4) <= 0.5L);
    }
  }
  GIVEN("pi") {
    THEN("ScalarTraits::pi() is pi rounded to the format") {
      CHECK(error_lsb(kestrel::ScalarTraits<Q>::pi(), kPiL) <= 0.5L);
    }
  }
}

TEMPLATE_TEST_CASE("Scenario: sin and cos by CORDIC are within 0.5 LSB", "[fixed_point][math]", kestrel::Q31_32,
                   kestrel::Q23_40) {
  using Q = TestType;
  std::mt19937_64 g(7u + Q::kFractionBits);
  std::uniform_real_distribution<double> angle(-25.0, 25.0);
  GIVEN(kSamples << " random angles in [-8 pi, 8 pi]") {
    long double worst = 0;
    for (int i = 0; i < kSamples; ++i) {
      const Q a = Q::from_double(angle(g));
      worst = std::max(worst, error_lsb(kestrel::fixed::sin(a), std::sin(exact(a))));
      worst = std::max(worst, error_lsb(kestrel::fixed::cos(a), std::cos(exact(a))));
    }
    INFO("largest sin/cos error: " << static_cast<double>(worst) << " LSB");
    THEN("the error is at most 0.5 LSB plus the CORDIC margin") { CHECK(worst <= kCordicBoundLsb); }
  }
  GIVEN("large angles (up to 2^20 rad)") {
    long double worst = 0;
    long double bound = 0;
    for (int i = 0; i < kSamples / 10; ++i) {
      const Q a = Q::from_raw(random_raw(g, Q::kFractionBits + 20));
      // pi is held to 2^-61 rad: a reduction by k turns adds k * 2^-60 rad at most.
      const long double k = std::fabs(exact(a)) / (2 * kPiL) + 1;
      const long double extra = std::ldexp(k, Q::kFractionBits - 60);
      bound = std::max(bound, kCordicBoundLsb + extra);
      worst = std::max(worst, error_lsb(kestrel::fixed::sin(a), std::sin(exact(a))) - extra);
    }
    INFO("largest sin error beyond the reduction allowance: " << static_cast<double>(worst) << " LSB");
    THEN("the error is within the bound plus the reduction allowance") { CHECK(worst <= kCordicBoundLsb); }
  }
  GIVEN("exact points") {
    THEN("sin 0 = 0, cos 0 = 1, sin(pi/2) = 1") {
      CHECK(kestrel::fixed::sin(Q(0)) == Q(0));
      CHECK(kestrel::fixed::cos(Q(0)) == Q(1));
      CHECK(kestrel::fixed::sin(kestrel::ScalarTraits<Q>::pi() / Q(2)) == Q(1));
    }
  }
}

TEMPLATE_TEST_CASE("Scenario: wrap_angle maps into (-pi_F, pi_F]", "[fixed_point][math][wrap]", kestrel::Q31_32,
                   kestrel::Q23_40) {
  using Q = TestType;
  using T = kestrel::ScalarTraits<Q>;
  std::mt19937_64 g(5u + Q::kFractionBits);
  const Q pi = T::pi();
  GIVEN(kSamples << " random angles up to 2^20 rad") {
    int out_of_interval = 0;
    int not_idempotent = 0;
    long double worst = 0;
    for (int i = 0; i < kSamples; ++i) {
      const Q a = Q::from_raw(random_raw(g, Q::kFractionBits + 20));
      const Q w = T::wrap_angle(a);
      out_of_interval += (w > -pi && w <= pi) ? 0 : 1;
      not_idempotent += T::wrap_angle(w) == w ? 0 : 1;
      // Same angle: the difference is a multiple of 2 pi (up to rounding).
      const long double d = std::remainder(exact(w) - exact(a), 2 * kPiL);
      const long double k = std::fabs(exact(a)) / (2 * kPiL) + 1;
      worst = std::max(worst, std::ldexp(std::fabs(d), Q::kFractionBits) - std::ldexp(k, Q::kFractionBits - 60));
    }
    INFO("largest wrap error beyond the reduction allowance: " << static_cast<double>(worst) << " LSB");
    THEN("the result is in the interval, wrapping is idempotent, and the angle is kept") {
      CHECK(out_of_interval == 0);
      CHECK(not_idempotent == 0);
      CHECK(worst <= 0.5L + 1.0L / 1024);
    }
  }
  GIVEN("the ends of the interval") {
    THEN("-pi_F maps to pi_F, pi_F and in-range angles are unchanged") {
      CHECK(T::wrap_angle(-pi) == pi);
      CHECK(T::wrap_angle(pi) == pi);
      CHECK(T::wrap_angle(Q(3)) == Q(3));
      CHECK(kestrel::wrap_angle(Q(4)) == T::wrap_angle(Q(4)));  // the generic entry point
      CHECK(error_lsb(T::wrap_angle(Q(7)), 7 - 2 * kPiL) <= 0.5L);
      CHECK(error_lsb(T::wrap_angle(Q(-7)), -7 + 2 * kPiL) <= 0.5L);
    }
  }
}
