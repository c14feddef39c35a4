// SPDX-License-Identifier: Apache-2.0
// ScalarTraits<float>::from_ratio divides in float and integers only (no soft
// double on a single-precision FPU) and must give, bit for bit, the float
// that the double route float(double(num) / double(den)) gives: the route it
// replaced, which the double traits still take.
#include <bit>
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>
#include <random>

#include "kestrel/scalar/scalar_traits.hpp"

namespace {

float via_double(std::int64_t num, std::int64_t den) {
  return static_cast<float>(static_cast<double>(num) / static_cast<double>(den));
}

std::uint32_t bits(float f) {
  std::uint32_t u = 0;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

/// Number of (num, den) pairs whose two routes differ in any bit.
template <class Gen>
int count_differences(Gen&& next, int n) {
  int differ = 0;
  for (int i = 0; i < n; ++i) {
    const auto [num, den] = next();
    if (bits(kestrel::ScalarTraits<float>::from_ratio(num, den)) != bits(via_double(num, den))) {
      if (differ < 5) UNSCOPED_INFO("num " << num << " den " << den);
      ++differ;
    }
  }
  return differ;
}

}  // namespace

// A few at compile time (the function is constexpr, as the double one),
// compared as bits.
static_assert(std::bit_cast<std::uint32_t>(kestrel::ScalarTraits<float>::from_ratio(1500, 1000)) ==
              std::bit_cast<std::uint32_t>(1.5f));
static_assert(std::bit_cast<std::uint32_t>(kestrel::ScalarTraits<float>::from_ratio(-1073741824, 2147483648LL)) ==
              std::bit_cast<std::uint32_t>(-0.5f));
static_assert(std::bit_cast<std::uint32_t>(kestrel::ScalarTraits<float>::from_ratio(3000000000LL, 1000)) ==
              std::bit_cast<std::uint32_t>(3000000.0f));

SCENARIO("float from_ratio equals the double route bit for bit") {
  std::mt19937_64 g(29);
  GIVEN("the adapters' and the tracker's conversions: millimetres, binary angles, microseconds") {
    std::uniform_int_distribution<std::int64_t> mm(-5'000'000'000LL, 5'000'000'000LL);
    std::uniform_int_distribution<std::int64_t> bam(INT32_MIN, INT32_MAX);
    std::uniform_int_distribution<std::int64_t> us(-100'000'000'000LL, 100'000'000'000LL);
    THEN("range_mm / 1000 agrees") {
      CHECK(count_differences([&] { return std::pair{mm(g), std::int64_t{1000}}; }, 400000) == 0);
    }
    THEN("bearing_bam / 2^31 agrees") {
      CHECK(count_differences([&] { return std::pair{bam(g), std::int64_t{2147483648LL}}; }, 400000) == 0);
    }
    THEN("dt_us / 10^6 agrees, also beyond 2^24 us") {
      CHECK(count_differences([&] { return std::pair{us(g), std::int64_t{1000000}}; }, 400000) == 0);
    }
  }
  GIVEN("numerators and denominators of every magnitude up to 2^53, either sign") {
    auto any = [&] {
      const int na = static_cast<int>(g() % 54);
      const int nb = static_cast<int>(g() % 54);
      auto num = static_cast<std::int64_t>(g() >> (64 - na - 1)) >> 1;  // |num| < 2^na
      auto den = static_cast<std::int64_t>(g() >> (64 - nb - 1)) >> 1;
      if ((g() & 1u) != 0) num = -num;
      if ((g() & 1u) != 0) den = -den;
      if (den == 0) den = 1;
      return std::pair{num, den};
    };
    THEN("they agree") { CHECK(count_differences(any, 1000000) == 0); }
  }
  GIVEN("halfway cases: odd multiples of half an ulp above 2^24, over small powers of two") {
    THEN("ties round to even as in the double route") {
      int differ = 0;
      for (std::int64_t m = (1 << 24) - 3; m < (1 << 24) + 4000; ++m) {
        for (std::int64_t den : {1LL, 2LL, 3LL, 4LL, 5LL, 1000LL, 1LL << 30, (1LL << 40) + 1}) {
          differ += bits(kestrel::ScalarTraits<float>::from_ratio(m, den)) != bits(via_double(m, den)) ? 1 : 0;
          differ += bits(kestrel::ScalarTraits<float>::from_ratio(-m * 3, den)) != bits(via_double(-m * 3, den)) ? 1 : 0;
        }
      }
      CHECK(differ == 0);
    }
  }
  GIVEN("a zero numerator or denominator") {
    THEN("the signs of zero and infinity and the NaN match the double route") {
      CHECK(bits(kestrel::ScalarTraits<float>::from_ratio(0, 7)) == bits(via_double(0, 7)));
      CHECK(bits(kestrel::ScalarTraits<float>::from_ratio(0, -(1LL << 40))) == bits(via_double(0, -(1LL << 40))));
      CHECK(bits(kestrel::ScalarTraits<float>::from_ratio(5, 0)) == bits(via_double(5, 0)));
      CHECK(bits(kestrel::ScalarTraits<float>::from_ratio(-(1LL << 40), 0)) == bits(via_double(-(1LL << 40), 0)));
      CHECK(std::isnan(kestrel::ScalarTraits<float>::from_ratio(0, 0)));
    }
  }
}
