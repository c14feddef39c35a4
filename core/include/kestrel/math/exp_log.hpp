// SPDX-License-Identifier: Apache-2.0
// Natural logarithm and exponential for float and double with the same bits
// on every IEEE platform: ScalarTraits' deterministic_log/deterministic_exp
// (the IMM's switching matrix over dt) and the ziggurat's wedge and tail
// (prng.hpp). std::log/std::exp are not correctly rounded and differ
// between C libraries (glibc, newlib), so a run replayed on a board would
// not give the host's bits. Here: exact exponent handling (bits or
// frexp/ldexp) plus fixed polynomials evaluated with + - * / only; IEEE 754
// makes each of those correctly rounded, so the result is the same
// everywhere as long as a*b+c is not contracted into an FMA (kestrel::core
// compiles with -ffp-contract=off). Accuracy (tests/core/math/prng_test.cpp):
// a few ulp in double, and for log in float; exp in float loses more as |y|
// grows, about 4e-6 relative at |y| = 80, because the split of ln 2 is
// double's and k ln2_hi rounds in float (a float split would change the
// float PRNG stream's bits).
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <type_traits>

namespace kestrel {

namespace detail {

/// s = m * 2^e with m in [0.5, 1), as std::frexp; exact. Normal numbers
/// are split from their bits (no libm call), others go to std::frexp.
template <class F>
F split_exponent(F s, int& e) {
  if constexpr (sizeof(F) == 8) {
    const auto bits = std::bit_cast<std::uint64_t>(s);
    const int biased = static_cast<int>((bits >> 52) & 0x7FFu);
    if (biased != 0 && biased != 0x7FF) {
      e = biased - 1022;
      return std::bit_cast<F>((bits & 0x000FFFFFFFFFFFFFull) | (std::uint64_t{1022} << 52));
    }
  } else if constexpr (sizeof(F) == 4) {
    const auto bits = std::bit_cast<std::uint32_t>(s);
    const int biased = static_cast<int>((bits >> 23) & 0xFFu);
    if (biased != 0 && biased != 0xFF) {
      e = biased - 126;
      return std::bit_cast<F>((bits & 0x007FFFFFu) | (std::uint32_t{126} << 23));
    }
  }
  return std::frexp(s, &e);
}

/// Natural logarithm of s > 0 from + - * / only (see the header note):
/// s = m 2^e with m in [sqrt(1/2), sqrt(2)), ln m = 2 atanh(f), f = (m-1)/(m+1),
/// |f| <= 0.1716, and the atanh series sum_k f^(2k+1) / (2k+1) to k = 10
/// (truncation below 1e-18 relative), evaluated by Estrin's scheme (a fixed
/// order of operations, shorter dependency chains than Horner).
template <class F>
F deterministic_log(F s) {
  int e = 0;
  F m = split_exponent(s, e);
  if (m < static_cast<F>(0.70710678118654752440)) {
    m = m + m;
    e -= 1;
  }
  const F f = (m - F(1)) / (m + F(1));
  const F x = f * f;
  const F x2 = x * x;
  const F x4 = x2 * x2;
  const F x8 = x4 * x4;
  // Coefficients 1/(2k+1), each a correctly rounded constant.
  constexpr F c1 = F(1) / F(3), c2 = F(1) / F(5), c3 = F(1) / F(7), c4 = F(1) / F(9);
  constexpr F c5 = F(1) / F(11), c6 = F(1) / F(13), c7 = F(1) / F(15), c8 = F(1) / F(17);
  constexpr F c9 = F(1) / F(19), c10 = F(1) / F(21);
  const F p01 = F(1) + c1 * x;
  const F p23 = c2 + c3 * x;
  const F p45 = c4 + c5 * x;
  const F p67 = c6 + c7 * x;
  const F p89 = c8 + c9 * x;
  const F p10 = c10;
  const F q0 = p01 + p23 * x2;
  const F q1 = p45 + p67 * x2;
  const F q2 = p89 + p10 * x2;
  const F poly = (q0 + q1 * x4) + q2 * x8;
  const F ln2_hi = static_cast<F>(0.693147180369123816490);     // upper bits of ln 2
  const F ln2_lo = static_cast<F>(1.90821492927058770002e-10);  // ln 2 - ln2_hi
  const F fe = static_cast<F>(e);
  return fe * ln2_hi + (fe * ln2_lo + F(2) * f * poly);
}

/// e^y for |y| <= 700 (double) or 80 (float) from + - * / only: y = k ln 2 + r with
/// |r| <= ln2 / 2, e^r by its Taylor series to r^13 (truncation below 5e-18),
/// and the exact scaling by 2^k: a multiply by 2^k built from its bits while
/// 2^k and the result are normal (p is in [0.7, 1.5), so no rounding: what
/// ldexp returns, without the libm call), ldexp beyond.
template <class F>
F deterministic_exp(F y) {
  constexpr F kInvLn2 = static_cast<F>(1.44269504088896340736);
  const F ln2_hi = static_cast<F>(0.693147180369123816490);
  const F ln2_lo = static_cast<F>(1.90821492927058770002e-10);
  const F kf = y * kInvLn2;
  const int k = static_cast<int>(kf < F(0) ? kf - F(0.5) : kf + F(0.5));
  const F fk = static_cast<F>(k);
  const F r = (y - fk * ln2_hi) - fk * ln2_lo;
  // Horner on 1 + r/1 (1 + r/2 (1 + ... (1 + r/13))), with 1/j as correctly
  // rounded constants (a multiply is cheaper than a divide).
  static constexpr F kInv[14] = {F(0),         F(1),         F(1) / F(2),  F(1) / F(3),  F(1) / F(4),
                                 F(1) / F(5),  F(1) / F(6),  F(1) / F(7),  F(1) / F(8),  F(1) / F(9),
                                 F(1) / F(10), F(1) / F(11), F(1) / F(12), F(1) / F(13)};
  // Static (a local array would be built on the stack at every call) and
  // unrolled; the same operations in the same order.
  F p = F(1);
#pragma GCC unroll 13
  for (int j = 13; j >= 1; --j) p = F(1) + p * r * kInv[j];
  // 2^k from its IEEE bits (biased exponent k + 1023 or k + 127).
  if constexpr (std::is_same_v<F, double>) {
    if (k >= -1021 && k <= 1023) return p * std::bit_cast<F>(static_cast<std::uint64_t>(k + 1023) << 52);
  } else if constexpr (std::is_same_v<F, float>) {
    if (k >= -125 && k <= 127) return p * std::bit_cast<F>(static_cast<std::uint32_t>(k + 127) << 23);
  }
  return std::ldexp(p, k);
}

}  // namespace detail

}  // namespace kestrel
