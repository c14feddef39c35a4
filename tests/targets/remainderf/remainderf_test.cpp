// SPDX-License-Identifier: Apache-2.0
// The Cortex-M4F image's remainderf (targets/cortex-m4f/remainderf.cpp)
// against newlib's own, both built with the board's code generation and run
// under qemu-arm. The results must be equal bit for bit
//   - for y = float(2 pi) (wrap_angle's divisor) and every float x with
//     pi <= |x| <= 4 pi (the angles wrap_angle hands to remainderf lie
//     beyond 2 pi; this covers one turn either side of it),
//   - for y = float(2 pi) and +-512 floats around each k pi, k = 1..4096
//     (the ties and the near-ties of the quotient), and every 61st float
//     from 4 pi to 2^20 * 2 pi,
//   - for 4 million pairs from a fixed pseudo-random sequence: y of any
//     normal magnitude from 2^-125 to 2^100 and either sign, |x| up to
//     2^20 |y|, with a quarter of them near a multiple of y / 2;
// and beyond the range (|x| > 2^20 |y|, non-finite x or y, |y| < 2^-125)
// the result must be NaN. The image's hypotf (targets/cortex-m4f/hypotf.cpp)
// against libstdc++'s stub, bit for bit: 8 million pairs from the same
// sequence (any finite magnitudes, either sign, exponents of the two legs at
// most 30 apart for half of them) and every pair of a list of special values
// (zeros, subnormals, infinities, NaN). Prints one summary line; exit status
// 0 when everything agrees.
#include <bit>
#include <cstdint>

#include "hypotf.hpp"
#include "remainderf.hpp"
#include "support/arm_linux_user.hpp"

extern "C" float remainderf(float x, float y);  // newlib (libm.a)
extern "C" float hypotf(float x, float y);      // libstdc++ (math_stubs_float.o)

namespace {

using kestrel::test::arm_linux_user::exit_with;
using kestrel::test::arm_linux_user::write_text;

std::uint32_t g_checked = 0;
std::uint32_t g_differ = 0;
std::uint32_t g_first_bad_x = 0;
std::uint32_t g_first_bad_y = 0;

bool is_nan(float v) { return (std::bit_cast<std::uint32_t>(v) & 0x7fffffffu) > 0x7f800000u; }

void check(float x, float y) {
  const float ours = kestrel_m4f_remainderf(x, y);
  const float ref = remainderf(x, y);
  ++g_checked;
  if (std::bit_cast<std::uint32_t>(ours) != std::bit_cast<std::uint32_t>(ref)) {
    if (g_differ == 0) {
      g_first_bad_x = std::bit_cast<std::uint32_t>(x);
      g_first_bad_y = std::bit_cast<std::uint32_t>(y);
    }
    ++g_differ;
  }
}

std::uint32_t g_hypot_checked = 0;
std::uint32_t g_hypot_differ = 0;

void check_hypot(float x, float y) {
  ++g_hypot_checked;
  if (std::bit_cast<std::uint32_t>(kestrel_m4f_hypotf(x, y)) != std::bit_cast<std::uint32_t>(hypotf(x, y))) {
    ++g_hypot_differ;
  }
}

void check_both_signs(std::uint32_t xbits, float y) {
  check(std::bit_cast<float>(xbits), y);
  check(std::bit_cast<float>(xbits | 0x80000000u), y);
}

// xorshift32: a fixed sequence, the same on every run.
std::uint32_t g_state = 0x9e3779b9u;
std::uint32_t next() {
  g_state ^= g_state << 13;
  g_state ^= g_state >> 17;
  g_state ^= g_state << 5;
  return g_state;
}

void put_hex(char* out, std::uint32_t v) {
  for (int i = 7; i >= 0; --i) {
    out[i] = "0123456789abcdef"[v & 0xfu];
    v >>= 4;
  }
}

}  // namespace

extern "C" [[noreturn]] void kestrel_assert_failed(const char*, int, const char*) { exit_with(2); }

extern "C" [[noreturn]] void _start() {
  constexpr float kTwoPi = 6.28318548f;          // float(2 pi), wrap_angle's divisor
  constexpr std::uint32_t kPi = 0x40490fdbu;     // float(pi)
  constexpr std::uint32_t kFourPi = 0x41490fdbu; // float(4 pi)
  constexpr float kLimit = 1048576.0f * kTwoPi;  // 2^20 * float(2 pi), exact
  const std::uint32_t limit_bits = std::bit_cast<std::uint32_t>(kLimit);
  for (std::uint32_t b = kPi; b <= kFourPi; ++b) check_both_signs(b, kTwoPi);
  for (std::uint32_t k = 1; k <= 4096; ++k) {
    const auto centre = std::bit_cast<std::uint32_t>(static_cast<float>(static_cast<double>(k) * 3.14159265358979323846));
    for (std::uint32_t b = centre - 512; b <= centre + 512 && b <= limit_bits; ++b) check_both_signs(b, kTwoPi);
  }
  for (std::uint32_t b = kFourPi; b <= limit_bits; b += 61) check_both_signs(b, kTwoPi);
  check_both_signs(limit_bits, kTwoPi);
  for (std::uint32_t i = 0; i < 4000000u; ++i) {
    // y: exponent 2^-125 .. 2^100, any mantissa, either sign.
    const std::uint32_t ybits = ((2u + next() % 226u) << 23) | (next() & 0x807fffffu);
    const float y = std::bit_cast<float>(ybits);
    // x: |x / y| below 2^20 (exponent at most 20 above y's), any mantissa.
    const std::int32_t yexp = static_cast<std::int32_t>(ybits >> 23 & 0xffu);
    std::int32_t xexp = yexp - 24 + static_cast<std::int32_t>(next() % 45u);
    if (xexp < 1) xexp = 1;
    std::uint32_t xbits = (static_cast<std::uint32_t>(xexp) << 23) | (next() & 0x807fffffu);
    if ((i & 3u) == 0) {
      // Near a multiple of y / 2: the quotient's ties and near-ties.
      const float q = static_cast<float>(next() % 2097152u) * 0.5f;
      xbits = std::bit_cast<std::uint32_t>(q * y) + (next() % 9u) - 4u;
    }
    const float x = std::bit_cast<float>(xbits);
    const float ax = x < 0.0f ? -x : x;
    const float ay = y < 0.0f ? -y : y;
    if (ax <= 1048576.0f * ay && ax <= 3.4028235e38f) check(x, y);
  }
  // Beyond the range: NaN, never a wrong number.
  std::uint32_t not_nan = 0;
  for (std::uint32_t b = limit_bits + 1; b < 0x7f800000u; b += 0x10001u) {
    not_nan += is_nan(kestrel_m4f_remainderf(std::bit_cast<float>(b), kTwoPi)) ? 0u : 1u;
  }
  const float inf = std::bit_cast<float>(0x7f800000u);
  const float nan = std::bit_cast<float>(0x7fc00000u);
  const float bad_x[] = {inf, -inf, nan};
  for (float x : bad_x) not_nan += is_nan(kestrel_m4f_remainderf(x, kTwoPi)) ? 0u : 1u;
  // Divisors: infinite, NaN, zero, subnormal, and 2^-126 (half of it is subnormal).
  const float bad_y[] = {inf, -inf, nan, 0.0f, -0.0f, 1e-39f, 1.17549435e-38f};
  for (float y : bad_y) {
    not_nan += is_nan(kestrel_m4f_remainderf(1e-30f, y)) ? 0u : 1u;
  }
  for (std::uint32_t i = 0; i < 8000000u; ++i) {
    const std::uint32_t a = next() & 0xff7fffffu;  // exponent field below 255: finite
    std::uint32_t b = next() & 0xff7fffffu;
    if ((i & 1u) == 0) {
      // Legs of comparable size: exponents at most 30 apart.
      const std::int32_t ea = static_cast<std::int32_t>(a >> 23 & 0xffu);
      std::int32_t eb = ea - 30 + static_cast<std::int32_t>(next() % 61u);
      eb = eb < 0 ? 0 : (eb > 254 ? 254 : eb);
      b = (b & 0x807fffffu) | (static_cast<std::uint32_t>(eb) << 23);
    }
    check_hypot(std::bit_cast<float>(a), std::bit_cast<float>(b));
  }
  const float special[] = {0.0f, -0.0f, 1e-45f, -1e-45f, 1e-39f, 1.17549435e-38f, 1.0f, -3.0f, 4.0f,
                           3.4028235e38f, -3.4028235e38f, inf, -inf, nan};
  for (float x : special) {
    for (float y : special) check_hypot(x, y);
  }
  char line[] = "checked xxxxxxxx differ xxxxxxxx first xxxxxxxx xxxxxxxx out-of-range-not-nan xxxxxxxx\n";
  put_hex(line + 8, g_checked);
  put_hex(line + 24, g_differ);
  put_hex(line + 39, g_first_bad_x);
  put_hex(line + 48, g_first_bad_y);
  put_hex(line + 78, not_nan);
  write_text(line);
  char hypot_line[] = "hypotf checked xxxxxxxx differ xxxxxxxx\n";
  put_hex(hypot_line + 15, g_hypot_checked);
  put_hex(hypot_line + 31, g_hypot_differ);
  write_text(hypot_line);
  exit_with(g_differ == 0 && not_nan == 0 && g_checked > 30000000u && g_hypot_differ == 0 &&
                    g_hypot_checked > 8000000u
                ? 0
                : 1);
}
