// SPDX-License-Identifier: Apache-2.0
// FixedPoint arithmetic against exact references: every +, -, *, / and
// conversion over large random sets equals the exactly rounded result (round
// to nearest, ties to even) computed with the host's __int128, i.e. an error
// <= 0.5 LSB with correct tie breaking; saturation is counted and sticks.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "kestrel/scalar/fixed_point.hpp"
#include "kestrel/scalar/fixed_point_io.hpp"

namespace {

__extension__ typedef __int128 I128;
__extension__ typedef unsigned __int128 U128;

constexpr std::int64_t kMaxFinite = INT64_MAX - 1;
constexpr int kSamples = 200000;

/// round(v / 2^s), ties to even, symmetric in sign.
I128 ref_round_shift(I128 v, int s) {
  const bool neg = v < 0;
  U128 m = neg ? static_cast<U128>(-v) : static_cast<U128>(v);
  U128 q = m >> s;
  const U128 rem = m - (q << s);
  const U128 half = static_cast<U128>(1) << (s - 1);
  if (rem > half || (rem == half && (q & 1) != 0)) ++q;
  return neg ? -static_cast<I128>(q) : static_cast<I128>(q);
}

/// round(n / d), ties to even.
I128 ref_round_div(I128 n, I128 d) {
  const bool neg = (n < 0) != (d < 0);
  const U128 un = n < 0 ? static_cast<U128>(-n) : static_cast<U128>(n);
  const U128 ud = d < 0 ? static_cast<U128>(-d) : static_cast<U128>(d);
  U128 q = un / ud;
  const U128 r2 = (un % ud) * 2;
  if (r2 > ud || (r2 == ud && (q & 1) != 0)) ++q;
  return neg ? -static_cast<I128>(q) : static_cast<I128>(q);
}

bool fits(I128 v) { return v <= kMaxFinite && v >= -kMaxFinite; }

/// Raw values spread over every magnitude: a random bit length, then random bits.
std::int64_t random_raw(std::mt19937_64& g, int max_bits = 63) {
  const int bits = static_cast<int>(g() % static_cast<unsigned>(max_bits)) + 1;
  std::uint64_t m = g() >> (64 - bits);
  if (m > static_cast<std::uint64_t>(kMaxFinite)) m = static_cast<std::uint64_t>(kMaxFinite);
  const auto v = static_cast<std::int64_t>(m);
  return (g() & 1) != 0 ? -v : v;
}

}  // namespace

TEMPLATE_TEST_CASE("Scenario: fixed-point + - * / are exact or correctly rounded", "[fixed_point]",
                   kestrel::Q31_32, kestrel::Q23_40) {
  using Q = TestType;
  constexpr int F = Q::kFractionBits;
  std::mt19937_64 g(20240601u + F);
  GIVEN(kSamples << " random pairs over every magnitude") {
    int overflows = 0;
    int mismatches = 0;
    kestrel::reset_fixed_point_overflow_count();
    for (int i = 0; i < kSamples; ++i) {
      const Q a = Q::from_raw(random_raw(g));
      const Q b = Q::from_raw(random_raw(g));
      const I128 ar = a.raw();
      const I128 br = b.raw();
      auto check = [&](Q got, I128 want) {
        if (fits(want)) {
          mismatches += got.raw() != static_cast<std::int64_t>(want) ? 1 : 0;
        } else {
          ++overflows;
          mismatches += got.is_finite() || ((got.raw() < 0) != (want < 0)) ? 1 : 0;
        }
      };
      check(a + b, ar + br);
      check(a - b, ar - br);
      check(a * b, ref_round_shift(ar * br, F));
      if (br != 0) check(a / b, ref_round_div(ar << F, br));
    }
    THEN("every finite result equals the reference and every overflow saturates with the right sign") {
      CHECK(mismatches == 0);
      CHECK(overflows > 0);  // the set does reach the edges
      AND_THEN("each overflow was counted once") {
        CHECK(kestrel::fixed_point_overflow_count() == static_cast<std::uint32_t>(overflows));
      }
    }
  }
  GIVEN("exact ties of a product") {
    const Q half_lsb_times_1 = Q::from_raw(1) * Q::from_raw(std::int64_t{1} << (F - 1));  // 0.5 LSB
    const Q three_halves = Q::from_raw(3) * Q::from_raw(std::int64_t{1} << (F - 1));      // 1.5 LSB
    const Q five_halves = Q::from_raw(-5) * Q::from_raw(std::int64_t{1} << (F - 1));      // -2.5 LSB
    THEN("they round to even, symmetrically in sign") {
      CHECK(half_lsb_times_1.raw() == 0);
      CHECK(three_halves.raw() == 2);
      CHECK(five_halves.raw() == -2);
    }
  }
  GIVEN("exact ties of a quotient") {
    THEN("they round to even") {
      CHECK((Q::from_raw(1) / Q(2)).raw() == 0);
      CHECK((Q::from_raw(3) / Q(2)).raw() == 2);
      CHECK((Q::from_raw(-3) / Q(2)).raw() == -2);
    }
  }
  GIVEN("sums and differences at the edges of + and -'s unchecked path (|raw| near 2^61) and of the range") {
    constexpr std::int64_t k61 = std::int64_t{1} << 61;
    constexpr std::int64_t k62 = std::int64_t{1} << 62;
    const std::int64_t edges[] = {-k61 - 1,        -k61,        -k61 + 1,    k61 - 1,      k61,
                                  -k62 - 1,        -k62,        -k62 + 1,    -k62 + 2,     k62 - 2,
                                  k62 - 1,         k62,         k62 + 1,     -kMaxFinite,  kMaxFinite,
                                  -kMaxFinite + 1, kMaxFinite - 1, 0,        -1,           1};
    int mismatches = 0;
    int overflows = 0;
    kestrel::reset_fixed_point_overflow_count();
    for (const std::int64_t x : edges) {
      for (const std::int64_t y : edges) {
        for (const bool subtract : {false, true}) {
          const Q got = subtract ? Q::from_raw(x) - Q::from_raw(y) : Q::from_raw(x) + Q::from_raw(y);
          const I128 want = subtract ? I128{x} - I128{y} : I128{x} + I128{y};
          if (fits(want)) {
            mismatches += got.raw() != static_cast<std::int64_t>(want) ? 1 : 0;
          } else {
            ++overflows;
            mismatches += got.is_finite() || ((got.raw() < 0) != (want < 0)) ? 1 : 0;
          }
        }
      }
    }
    THEN("each equals the reference or saturates with the right sign, and each saturation is counted") {
      // -2^62 + -2^62 = INT64_MIN and -2^62 + (-2^62 + 1) = -saturation's raw
      // value: both must saturate, counted, like any other overflow.
      CHECK((Q::from_raw(-k62) + Q::from_raw(-k62)).raw() == -INT64_MAX);
      CHECK(mismatches == 0);
      CHECK(overflows > 0);
      CHECK(kestrel::fixed_point_overflow_count() == static_cast<std::uint32_t>(overflows) + 1);
    }
  }
}

SCENARIO("the 16-bit-limb 32 x 32-bit product (Thumb-1) equals the native one", "[fixed_point]") {
  std::mt19937_64 g(20261204u);
  GIVEN("random operands and the carry edges") {
    int mismatches = 0;
    auto check = [&](std::uint32_t a, std::uint32_t b) {
      mismatches += kestrel::fixed::detail::mul_32x32_limbs(a, b) != std::uint64_t{a} * b ? 1 : 0;
    };
    for (int i = 0; i < kSamples; ++i) {
      const auto b = static_cast<std::uint32_t>(g() >> 7);  // own statement: argument order is unspecified
      check(static_cast<std::uint32_t>(g()), b);
    }
    for (const std::uint32_t a : {0u, 1u, 0xFFFFu, 0x10000u, 0xFFFF0000u, 0x8000FFFFu, 0xFFFFFFFFu}) {
      for (const std::uint32_t b : {0u, 1u, 0xFFFFu, 0x10000u, 0xFFFF0000u, 0x8000FFFFu, 0xFFFFFFFFu}) check(a, b);
    }
    THEN("every product is exact") { CHECK(mismatches == 0); }
  }
}

TEMPLATE_TEST_CASE("Scenario: a prepared divisor divides within 1.5 LSB", "[fixed_point]", kestrel::Q31_32,
                   kestrel::Q23_40) {
  using Q = TestType;
  constexpr int F = Q::kFractionBits;
  std::mt19937_64 g(20261203u + F);
  GIVEN(kSamples << " random pairs, positive divisors of every magnitude") {
    int far = 0;         // finite quotients more than 1.5 LSB from the rounded one
    int wrong_sat = 0;   // saturation where the quotient fits, or none where it does not
    int exact = 0;
    int in_range = 0;
    for (int i = 0; i < kSamples; ++i) {
      const Q a = Q::from_raw(random_raw(g));
      std::int64_t dr = random_raw(g);
      if (dr < 0) dr = -dr;
      if (dr == 0) dr = 1;
      const Q d = Q::from_raw(dr);
      const Q got = Q::divisor(d).divide(a);
      const I128 want = ref_round_div(static_cast<I128>(a.raw()) << F, dr);
      if (fits(want) && want < kMaxFinite / 2 && want > -kMaxFinite / 2) {
        ++in_range;
        const I128 err = static_cast<I128>(got.raw()) - want;
        // |err| <= 1 in integers: 0.5 LSB of the rounded reference plus
        // 1.5 LSB of the prepared reciprocal, both in whole LSBs.
        far += (err > 1 || err < -1 || !got.is_finite()) ? 1 : 0;
        exact += err == 0 ? 1 : 0;
      } else if (!fits(want)) {
        wrong_sat += got.is_finite() ? 1 : 0;
      }
    }
    THEN("every quotient is within one LSB of the correctly rounded one, mostly equal to it") {
      CHECK(in_range > kSamples / 4);
      CHECK(far == 0);
      CHECK(wrong_sat == 0);
      CHECK(exact > in_range * 9 / 10);
    }
  }
  GIVEN("a divisor that is not positive and finite") {
    THEN("every quotient saturates") {
      kestrel::reset_fixed_point_overflow_count();
      CHECK_FALSE(Q::divisor(Q(0)).divide(Q(1)).is_finite());
      CHECK_FALSE(Q::divisor(Q(-2)).divide(Q(1)).is_finite());
      CHECK_FALSE(Q::divisor(Q::from_raw(INT64_MAX)).divide(Q(1)).is_finite());
    }
  }
}

TEMPLATE_TEST_CASE("Scenario: conversions into fixed point", "[fixed_point]", kestrel::Q31_32, kestrel::Q23_40) {
  using Q = TestType;
  constexpr int F = Q::kFractionBits;
  std::mt19937_64 g(77u + F);
  GIVEN("literals") {
    THEN("the consteval double constructor and integers give the exact raw values") {
      STATIC_REQUIRE(Q(0.5).raw() == (std::int64_t{1} << (F - 1)));
      STATIC_REQUIRE(Q(-3).raw() == -3 * (std::int64_t{1} << F));
      // 2^F = 3 q + 1 for even F, so round(2^F / 3) = q = (2^F + 1) / 3 in integers.
      STATIC_REQUIRE((Q(1) / Q(3)).raw() == ((std::int64_t{1} << F) + 1) / 3);
      STATIC_REQUIRE(static_cast<double>(Q(2.25)) == 2.25);
    }
  }
  GIVEN(kSamples << " random doubles") {
    int mismatches = 0;
    for (int i = 0; i < kSamples; ++i) {
      const double v = std::ldexp(static_cast<double>(random_raw(g, 53)), -static_cast<int>(g() % 80));
      const double scaled = std::ldexp(v, F);  // exact: a power-of-two scaling
      if (std::fabs(scaled) >= 9.2e18) continue;
      const auto want = static_cast<std::int64_t>(std::nearbyint(scaled));  // ties to even
      mismatches += Q::from_double(v).raw() != want ? 1 : 0;
    }
    THEN("from_double rounds to nearest, ties to even") { CHECK(mismatches == 0); }
  }
  GIVEN(kSamples << " random integer ratios (sensor units)") {
    int mismatches = 0;
    for (int i = 0; i < kSamples; ++i) {
      const std::int64_t num = random_raw(g, 40);
      std::int64_t den = random_raw(g, 31);
      if (den == 0) den = 1000;
      const I128 want = ref_round_div(static_cast<I128>(num) << F, den);
      const Q got = Q::from_ratio(num, den);
      mismatches += fits(want) ? (got.raw() != static_cast<std::int64_t>(want) ? 1 : 0) : (got.is_finite() ? 1 : 0);
    }
    THEN("from_ratio is the correctly rounded quotient") { CHECK(mismatches == 0); }
    THEN("millimetres and microseconds convert as on the wire") {
      CHECK(Q::from_ratio(1500, 1000) == Q(1.5));
      CHECK(Q::from_ratio(500000, 1000000) == Q(0.5));
      CHECK(Q::from_ratio(-7, 2) == Q(-3.5));
    }
  }
}

TEMPLATE_TEST_CASE("Scenario: saturation is counted, sticks, and never wraps", "[fixed_point][overflow]",
                   kestrel::Q31_32, kestrel::Q23_40) {
  using Q = TestType;
  constexpr int F = Q::kFractionBits;
  const Q big = Q::from_raw(kMaxFinite);
  kestrel::reset_fixed_point_overflow_count();
  GIVEN("operations whose exact result leaves the range") {
    const Q sum = big + Q::from_raw(1);
    const Q diff = -big - Q(1);
    const Q prod = big * Q(2);
    const Q quot = big / Q(0.5);
    const Q by_zero = Q(1) / Q(0);
    const Q from_int = Q(std::int64_t{1} << (63 - F));
    const Q from_nan = Q::from_double(std::numeric_limits<double>::quiet_NaN());
    THEN("each saturates to the right sign, is non-finite, and is counted once") {
      CHECK_FALSE(sum.is_finite());
      CHECK(sum.raw() == INT64_MAX);
      CHECK_FALSE(diff.is_finite());
      CHECK(diff.raw() == -INT64_MAX);
      CHECK_FALSE(prod.is_finite());
      CHECK_FALSE(quot.is_finite());
      CHECK_FALSE(by_zero.is_finite());
      CHECK_FALSE(from_int.is_finite());
      CHECK_FALSE(from_nan.is_finite());
      CHECK(kestrel::fixed_point_overflow_count() == 7);
    }
    THEN("a saturated value stays saturated through further arithmetic, without new counts") {
      CHECK_FALSE((sum - Q(1000)).is_finite());
      CHECK_FALSE((sum * Q(0.001)).is_finite());
      CHECK_FALSE((prod / Q(3)).is_finite());
      CHECK_FALSE((diff * Q(-1)).is_finite());
      CHECK((diff * Q(-1)).raw() == INT64_MAX);
      CHECK(kestrel::fixed_point_overflow_count() == 7);
    }
  }
  GIVEN("the largest finite value") {
    THEN("it is finite and its negation is exact") {
      CHECK(big.is_finite());
      CHECK((-big).raw() == -kMaxFinite);
      CHECK((big - big).raw() == 0);
      CHECK(kestrel::fixed_point_overflow_count() == 0);
    }
  }
}
