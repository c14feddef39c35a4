// SPDX-License-Identifier: Apache-2.0
// remainderf for the Cortex-M4F image, limited to what the tracker needs.
// wrap_angle (kestrel/scalar/scalar_traits.hpp) calls remainderf(a, 2 pi)
// only for an angle outside (-2 pi, 2 pi]; newlib's remainderf with its
// fmodf (a bit-by-bit long division over any exponent range) is 656 bytes
// for that. This file defines remainderf (as an alias of
// kestrel_m4f_remainderf), so the linker never pulls newlib's member (were
// it pulled for another symbol, the link would fail with a duplicate
// definition). For finite x, normal y with |y| / 2 normal, and
// |x| <= 2^20 |y| the result is exact, so it is newlib's, bit for bit:
// with t = x / y rounded and m = t rounded to the nearest integer (ties to
// even), m is n or n +- 1, and x - m y is a multiple of the smaller of
// ulp(x) and ulp(y) below 2^24 times it, so one fused multiply-add
// (VFMA.F32) gives it exactly; a result beyond |y| / 2 (m off by one) moves
// by |y|, exactly (Sterbenz). tests/targets/remainderf/remainderf_test.cpp
// compares it with newlib's under qemu-arm. Beyond that range the result
// is NaN, which the filters turn into kNonFinite.
#include "remainderf.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace {

constexpr float kMaxQuotient = 1048576.0f;           // 2^20
constexpr float kRoundShift = 12582912.0f;           // 1.5 * 2^23: t + it - it rounds t to an integer
constexpr float kMinDivisor = 2.3509887e-38f;        // 2^-125: |y| / 2 still normal
constexpr float kMaxFinite = std::numeric_limits<float>::max();

}  // namespace

extern "C" float kestrel_m4f_remainderf(float x, float y) {
  const float ax = std::fabs(x);
  const float ay = std::fabs(y);
  // Written so that NaN fails every test.
  if (!(ax <= kMaxFinite) || !(ay >= kMinDivisor && ay <= kMaxFinite) || !(ax <= kMaxQuotient * ay)) {
    return std::numeric_limits<float>::quiet_NaN();
  }
  // |x / y| <= 2^20, so t + 1.5 * 2^23 lies in [2^23, 2^24), where floats
  // are the integers: the addition rounds t to the nearest, ties to even.
  const float m = (x / y + kRoundShift) - kRoundShift;
  float r = std::fma(-m, y, x);
  const float half = 0.5f * ay;
  if (r > half) {
    r -= ay;
  } else if (r < -half) {
    r += ay;
  }
  // An exact zero has the sign of x (fma's exact zero sum is +0).
  if ((std::bit_cast<std::uint32_t>(r) & 0x7fffffffu) == 0) return std::copysign(0.0f, x);
  return r;
}

#ifndef KESTREL_M4F_KEEP_NEWLIB_REMAINDERF
extern "C" float remainderf(float x, float y) __attribute__((alias("kestrel_m4f_remainderf")));
#endif
