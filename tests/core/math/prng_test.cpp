// SPDX-License-Identifier: Apache-2.0
// Core PRNG: xoshiro256** matches the reference algorithm; streams are
// reproducible from the seed and pinned by golden values (so a board and
// the host can be compared bit for bit); the deterministic logarithm and
// exponential agree with the C library to a few ulps, also through
// ScalarTraits and on both sides of 0; the ziggurat normal
// deviates have the moments and the histogram of N(0, 1), tails included.
#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

#include "kestrel/math/prng.hpp"
#include "kestrel/scalar/scalar_traits.hpp"

namespace {

/// Reference xoshiro256** from Blackman and Vigna's public-domain C code,
/// with their SplitMix64 seeding, written independently of core.
struct ReferenceXoshiro {
  std::uint64_t s[4];
  explicit ReferenceXoshiro(std::uint64_t seed) {
    std::uint64_t x = seed;
    for (auto& w : s) {
      std::uint64_t z = (x += 0x9e3779b97f4a7c15ull);
      z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
      z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
      w = z ^ (z >> 31);
    }
  }
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::uint64_t next() {
    const std::uint64_t result = rotl(s[1] * 5, 7) * 9;
    const std::uint64_t t = s[1] << 17;
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = rotl(s[3], 45);
    return result;
  }
};

/// FNV-1a over the bit patterns of a stream of values.
template <class F, class Gen>
std::uint64_t stream_hash(Gen& g, int count) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (int i = 0; i < count; ++i) {
    const F v = g();
    unsigned char bytes[sizeof(F)];
    std::memcpy(bytes, &v, sizeof(F));
    for (unsigned char b : bytes) {
      h ^= b;
      h *= 0x100000001b3ull;
    }
  }
  return h;
}

}  // namespace

SCENARIO("xoshiro256** follows the reference algorithm", "[math][prng]") {
  for (std::uint64_t seed : {0ull, 1ull, 42ull, 0xdeadbeefcafef00dull}) {
    kestrel::Xoshiro256StarStar rng(seed);
    ReferenceXoshiro ref(seed);
    bool same = true;
    for (int i = 0; i < 10000; ++i) same = same && rng.next() == ref.next();
    CHECK(same);
  }
}

SCENARIO("the streams are pinned by golden values", "[math][prng][golden]") {
  // Golden values: change only by a deliberate commit (a changed stream
  // changes every CRPF result). Produced by this implementation on x86-64
  // (GCC 12, -O2, no FMA contraction); a board running this test must match.
  kestrel::Xoshiro256StarStar rng(0);
  CHECK(rng.next() == 0x99ec5f36cb75f2b4ull);
  CHECK(rng.next() == 0xbf6e1f784956452aull);
  kestrel::NormalGenerator<double> nd(2024);
  kestrel::NormalGenerator<float> nf(2024);
  CHECK(stream_hash<double>(nd, 100000) == 0x80065dd3bca1d997ull);
  CHECK(stream_hash<float>(nf, 100000) == 0x5418107e7da8289cull);
}

SCENARIO("a seed reproduces its stream", "[math][prng]") {
  kestrel::NormalGenerator<double> a(5), b(5), c(6);
  const std::uint64_t ha = stream_hash<double>(a, 1000);
  CHECK(ha == stream_hash<double>(b, 1000));
  CHECK(ha != stream_hash<double>(c, 1000));
  a.seed(5);
  CHECK(stream_hash<double>(a, 1000) == ha);
}

SCENARIO("the deterministic logarithm agrees with the C library", "[math][prng]") {
  kestrel::Xoshiro256StarStar rng(3);
  double worst = 0.0;
  for (int i = 0; i < 100000; ++i) {
    const double s = rng.uniform01<double>() + 1e-300;
    const double ref = std::log(s);
    worst = std::max(worst, std::fabs(kestrel::detail::deterministic_log(s) - ref) / std::fabs(ref));
  }
  // Worst case measured: 3 ulp (4.8e-16 relative) just above sqrt(1/2),
  // where e ln 2 and ln m partly cancel; the series itself is exact to
  // f^25 < 1e-19. Bound: 1e-15 relative (about 6 ulp).
  CHECK(worst < 1e-15);
  CHECK(kestrel::detail::deterministic_log(1.0) == 0.0);
  CHECK(kestrel::detail::deterministic_log(0.5f) == Approx(std::log(0.5f)).epsilon(1e-6));
}

SCENARIO("the deterministic exponential agrees with the C library", "[math][prng]") {
  kestrel::Xoshiro256StarStar rng(4);
  double worst = 0.0;
  for (int i = 0; i < 100000; ++i) {
    const double y = -12.0 * rng.uniform01<double>();
    const double ref = std::exp(y);
    worst = std::max(worst, std::fabs(kestrel::detail::deterministic_exp(y) - ref) / ref);
  }
  // Taylor series to r^13 (|r| <= ln2/2) evaluated in 13 rounded steps:
  // a few ulps; bound 1e-15 relative.
  CHECK(worst < 1e-15);
  CHECK(kestrel::detail::deterministic_exp(0.0) == 1.0);
  CHECK(kestrel::detail::deterministic_exp(-1.0f) == Approx(std::exp(-1.0f)).epsilon(1e-6));
}

TEMPLATE_TEST_CASE("Scenario: ScalarTraits' deterministic exp and log hold on both sides of 0", "[math][prng]", double,
                   float) {
  using S = TestType;
  using T = kestrel::ScalarTraits<S>;
  kestrel::Xoshiro256StarStar rng(5);
  double worst_exp = 0.0, worst_log = 0.0;
  // The IMM's switching matrix takes exp of ln p_ii (dt/T0 - 1): positive for
  // dt < T0, down to -80 for long gaps.
  for (int i = 0; i < 100000; ++i) {
    const S y = S(160.0 * rng.uniform01<double>() - 80.0);
    const S e = T::deterministic_exp(y);
    CHECK_FALSE(e != kestrel::detail::deterministic_exp(y));  // the traits forward, bit for bit
    const double ref = std::exp(double(y));
    worst_exp = std::max(worst_exp, std::fabs(double(e) - ref) / ref);
    const S p = S(rng.uniform01<double>()) + S(1e-30);
    worst_log = std::max(worst_log, std::fabs(double(T::deterministic_log(p)) - std::log(double(p))) /
                                        std::max(1e-30, std::fabs(std::log(double(p)))));
  }
  // The reference is exp/log in double of the same argument. Double: a few
  // ulp. Float: log a few ulp (measured 2.5e-7); exp loses more as |y|
  // grows, since the reduction's k ln2_hi is rounded in float (the split of
  // ln 2 is double's): measured 4.1e-6 relative at |y| <= 80.
  const bool is_float = std::is_same_v<S, float>;
  INFO("worst relative error: exp " << worst_exp << ", log " << worst_log);
  CHECK(worst_exp < (is_float ? 1e-5 : 1e-15));
  CHECK(worst_log < (is_float ? 5e-7 : 1e-15));
  CHECK(T::deterministic_exp(S(0)) == S(1));
  CHECK(T::deterministic_log(S(1)) == S(0));
}

/// e^y as deterministic_exp computed it with std::ldexp for the scaling:
/// the reference its 2^k-from-bits multiply must equal, bit for bit.
template <class F>
F exp_scaled_by_ldexp(F y) {
  const F kf = y * static_cast<F>(1.44269504088896340736);
  const int k = static_cast<int>(kf < F(0) ? kf - F(0.5) : kf + F(0.5));
  const F fk = static_cast<F>(k);
  const F r = (y - fk * static_cast<F>(0.693147180369123816490)) - fk * static_cast<F>(1.90821492927058770002e-10);
  F p = F(1);
  for (int j = 13; j >= 1; --j) p = F(1) + p * r * (F(1) / F(j));
  return std::ldexp(p, k);
}

TEMPLATE_TEST_CASE("Scenario: deterministic exp scales by 2^k as ldexp does, bit for bit, over its whole range",
                   "[math][prng]", double, float) {
  using F = TestType;
  // |y| up to 700 (double) or 80 (float), and past the ends where the result
  // is subnormal or infinite and ldexp takes over.
  const F limit = std::is_same_v<F, double> ? F(760) : F(110);
  kestrel::Xoshiro256StarStar rng(11);
  int differ = 0;
  for (int i = 0; i < 400000; ++i) {
    const F y = static_cast<F>((2.0 * rng.uniform01<double>() - 1.0) * double(limit));
    const F a = kestrel::detail::deterministic_exp(y);
    const F b = exp_scaled_by_ldexp(y);
    if (std::memcmp(&a, &b, sizeof(F)) != 0) ++differ;
  }
  CHECK(differ == 0);
  // The ends of the bit path and the first values past them, k = -1022,
  // -1021, 1023, 1024 (double) and -126, -125, 127, 128 (float).
  const int ends[] = {std::numeric_limits<F>::min_exponent - 1, std::numeric_limits<F>::min_exponent,
                      std::numeric_limits<F>::max_exponent - 1, std::numeric_limits<F>::max_exponent};
  for (const int k : ends) {
    for (const double r : {-0.34, 0.0, 0.34}) {
      const F y = static_cast<F>(k * 0.69314718055994530942 + r);
      INFO("k " << k << " r " << r);
      const F a = kestrel::detail::deterministic_exp(y);
      const F b = exp_scaled_by_ldexp(y);
      CHECK(std::memcmp(&a, &b, sizeof(F)) == 0);
    }
  }
}

TEMPLATE_TEST_CASE("Scenario: normal deviates follow N(0, 1) in the histogram and the tails", "[math][prng]", double,
                   float) {
  kestrel::NormalGenerator<TestType> n(23);
  const int count = 1000000;
  // 24 bins of width 0.5 over [-6, 6) plus the two tails beyond +-6 folded
  // into the outer bins; expected counts from the normal CDF.
  constexpr int kBins = 24;
  int hist[kBins] = {};
  int beyond_r = 0;  // |x| > R = 3.4426: drawn by the tail algorithm
  for (int i = 0; i < count; ++i) {
    const double v = static_cast<double>(n());
    int b = static_cast<int>(std::floor((v + 6.0) / 0.5));
    b = std::min(std::max(b, 0), kBins - 1);
    ++hist[b];
    beyond_r += std::fabs(v) > 3.442619855899 ? 1 : 0;
  }
  const auto cdf = [](double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); };
  double chi2 = 0.0;
  int dof = 0;
  for (int b = 0; b < kBins; ++b) {
    const double lo = b == 0 ? -1e9 : -6.0 + 0.5 * b;
    const double hi = b == kBins - 1 ? 1e9 : -6.0 + 0.5 * (b + 1);
    const double expected = count * (cdf(hi) - cdf(lo));
    if (expected < 5.0) continue;  // chi-square needs populated bins
    chi2 += (hist[b] - expected) * (hist[b] - expected) / expected;
    ++dof;
  }
  --dof;
  // 99.99 % point of chi-square with about 15 dof is about 44: a correct
  // generator fails this once in 10^4 seeds, and this seed is fixed.
  INFO("chi2 " << chi2 << " with " << dof << " dof");
  CHECK(chi2 < 44.0);
  // P(|x| > R) = 5.76e-4: 576 expected, sd 24; bound at 5 sd.
  const double tail_expected = count * 2.0 * cdf(-3.442619855899);
  CHECK(std::fabs(beyond_r - tail_expected) < 5.0 * std::sqrt(tail_expected));
}

TEMPLATE_TEST_CASE("Scenario: normal deviates have mean 0 and variance 1", "[math][prng]", double, float) {
  kestrel::NormalGenerator<TestType> n(17);
  const int count = 200000;
  double sum = 0.0, sum2 = 0.0, sum4 = 0.0;
  for (int i = 0; i < count; ++i) {
    const double v = static_cast<double>(n());
    sum += v;
    sum2 += v * v;
    sum4 += v * v * v * v;
  }
  const double mean = sum / count;
  const double var = sum2 / count - mean * mean;
  // Standard errors at 2e5 draws: mean 0.0022, variance 0.0032, 4th moment
  // (3 for a Gaussian) 0.022; bounds at about 5 standard errors.
  CHECK(std::fabs(mean) < 0.011);
  CHECK(std::fabs(var - 1.0) < 0.016);
  CHECK(std::fabs(sum4 / count - 3.0) < 0.11);
}
