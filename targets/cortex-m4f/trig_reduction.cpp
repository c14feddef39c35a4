// SPDX-License-Identifier: Apache-2.0
// Argument reduction of newlib's sinf and cosf, limited to what the tracker
// needs. newlib's __ieee754_rem_pio2f reduces any float by pi/2; beyond
// |x| = 2^7 pi/2 it calls __kernel_rem_pio2f (Payne-Hanek with a 198-digit
// 2/pi table), 3.2 KiB of flash for arguments a bearing never has. This
// file defines __ieee754_rem_pio2f (as an alias of kestrel_m4f_rem_pio2f),
// so the linker resolves newlib's sinf and cosf to it and never pulls
// libm's member with the large-argument code (were it pulled for another
// symbol, the link would fail with a duplicate definition, not go quiet). Up to 2^7 pi/2 this is the same Cody-Waite reduction, step
// for step and with the same fused multiply-adds as the newlib build that
// ships with arm-none-eabi-gcc 12.2 (so sinf and cosf return the same
// bits; tests/targets/trig_reduction/trig_reduction_test.cpp checks every
// float up to pi and a sample up to 2^7 pi/2 against newlib's own). Beyond it, y[0] and y[1]
// are NaN: sinf and cosf then return NaN, which the filters turn into
// kNonFinite, instead of a wrong value.
#include "trig_reduction.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace {

constexpr float from_bits(std::uint32_t b) { return std::bit_cast<float>(b); }

// pi/2 split for Cody-Waite: pio2_1 is float(pi/2) with its low 7 mantissa
// bits cleared (17 significant bits, so n * pio2_1 is exact for n < 2^7);
// pio2_1t = float(pi/2 - pio2_1); pio2_2 is pio2_1t with 8 bits cleared,
// pio2_2t = float(pi/2 - pio2_1 - pio2_2); and so on.
constexpr float kPio2_1 = from_bits(0x3fc90f80u);   // 1.5707855e+00
constexpr float kPio2_1t = from_bits(0x37354443u);  // 1.0804334e-05
constexpr float kPio2_2 = from_bits(0x37354400u);   // 1.0804273e-05
constexpr float kPio2_2t = from_bits(0x2e85a308u);  // 6.0770999e-11
constexpr float kPio2_3 = from_bits(0x2e85a300u);   // 6.0770944e-11
constexpr float kPio2_3t = from_bits(0x248d3132u);  // 6.1232343e-17
constexpr float kInvPio2 = from_bits(0x3f22f984u);  // float(2/pi)

constexpr std::uint32_t kPiOver4Bits = 0x3f490fd8u;     // |x| up to here: no reduction
constexpr std::uint32_t kThreePiOver4Bits = 0x4016cbe4u;  // below: n = +-1
constexpr std::uint32_t kMediumLimitBits = 0x43490f80u;   // 2^7 pi/2: end of this reduction

/// High bits (low 8 cleared) of float(n pi/2), n = 1..32: where x - n pi/2
/// may cancel so far that a second or third part of pi/2 is needed.
/// newlib reads them from a 32-entry table (npio2_hw); here they are the
/// high bits of the float product n * float(pi/2), which the assertions
/// below prove equal for every n of the table: the same test without its
/// 128 bytes.
constexpr float kPio2 = from_bits(0x3fc90fdbu);  // float(pi/2)
constexpr std::uint32_t npio2_hw(float fn) { return std::bit_cast<std::uint32_t>(fn * kPio2) & 0xffffff00u; }
constexpr bool npio2_hw_matches_newlib() {
  for (std::uint32_t n = 1; n <= 32; ++n) {
    const std::uint32_t newlib =
        std::bit_cast<std::uint32_t>(static_cast<float>(n * 1.57079632679489661923)) & 0xffffff00u;
    if (npio2_hw(static_cast<float>(n)) != newlib) return false;
  }
  return true;
}
static_assert(npio2_hw_matches_newlib(), "n * float(pi/2) must give newlib's npio2_hw for n = 1..32");
static_assert(npio2_hw(1.0f) == 0x3fc90f00u && npio2_hw(2.0f) == 0x40490f00u && npio2_hw(32.0f) == 0x42490f00u);

int biased_exponent(float v) { return static_cast<int>((std::bit_cast<std::uint32_t>(v) >> 23) & 0xffu); }

}  // namespace

extern "C" int kestrel_m4f_rem_pio2f(float x, float* y) {
  const std::int32_t hx = std::bit_cast<std::int32_t>(x);
  const std::uint32_t ix = static_cast<std::uint32_t>(hx) & 0x7fffffffu;
  if (ix <= kPiOver4Bits) {
    y[0] = x;
    y[1] = 0.0f;
    return 0;
  }
  if (ix < kThreePiOver4Bits) {  // n = +-1; a 24 + 24 bit pi/2, or 24 + 24 + 24 near pi/2
    const bool near_pio2 = (ix & 0xfffffff0u) == 0x3fc90fd0u;
    if (hx > 0) {
      float z = x - kPio2_1;
      const float tail = near_pio2 ? kPio2_2t : kPio2_1t;
      if (near_pio2) z -= kPio2_2;
      y[0] = z - tail;
      y[1] = (z - y[0]) - tail;
      return 1;
    }
    float z = x + kPio2_1;
    const float tail = near_pio2 ? kPio2_2t : kPio2_1t;
    if (near_pio2) z += kPio2_2;
    y[0] = z + tail;
    y[1] = (z - y[0]) + tail;
    return -1;
  }
  if (ix > kMediumLimitBits) {  // inf or NaN: NaN as newlib; a finite large x: NaN, see above
    const float nan = ix >= 0x7f800000u ? x - x : std::numeric_limits<float>::quiet_NaN();
    y[0] = nan;
    y[1] = nan;
    return 0;
  }
  // Medium: n = nearest integer to |x| 2/pi (n < 2^7), r = |x| - n pi/2 in
  // up to three parts, with the products fused where newlib's build fuses them.
  const float t = std::fabs(x);
  const auto n = static_cast<std::int32_t>(std::fmaf(t, kInvPio2, 0.5f));
  const auto fn = static_cast<float>(n);
  float r = std::fmaf(-fn, kPio2_1, t);  // exact: n pio2_1 has at most 24 bits
  float w = fn * kPio2_1t;
  if (n < 32 && (ix & 0xffffff00u) != npio2_hw(fn)) {
    y[0] = r - w;  // no cancellation possible
  } else {
    const int j = static_cast<int>(ix >> 23);
    y[0] = r - w;
    if (j - biased_exponent(y[0]) > 8) {  // second part of pi/2: good to 57 bits
      float t2 = r;
      r = std::fmaf(-fn, kPio2_2, t2);
      w = std::fmaf(fn, kPio2_2t, -std::fmaf(-fn, kPio2_2, t2 - r));
      y[0] = r - w;
      if (j - biased_exponent(y[0]) > 25) {  // third part: good to 74 bits
        t2 = r;
        r = std::fmaf(-fn, kPio2_3, t2);
        w = std::fmaf(fn, kPio2_3t, -std::fmaf(-fn, kPio2_3, t2 - r));
        y[0] = r - w;
      }
    }
  }
  y[1] = (r - y[0]) - w;
  if (hx < 0) {
    y[0] = -y[0];
    y[1] = -y[1];
    return -n;
  }
  return n;
}

// What newlib's sinf and cosf call. Left out of the test program that
// compares this reduction with newlib's (tests/targets/trig_reduction).
#ifndef KESTREL_M4F_KEEP_NEWLIB_REM_PIO2F
extern "C" int __ieee754_rem_pio2f(float x, float* y) __attribute__((alias("kestrel_m4f_rem_pio2f")));
#endif
