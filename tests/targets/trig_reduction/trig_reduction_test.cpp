// SPDX-License-Identifier: Apache-2.0
// The Cortex-M4F image's sinf/cosf argument reduction
// (targets/cortex-m4f/trig_reduction.cpp) against newlib's own
// __ieee754_rem_pio2f, both built with the board's code generation and run
// under qemu-arm: quadrant and both parts must be equal bit for bit
//   - for every float with pi/4 < |x| <= pi (every bearing the tracker's
//     sinf/cosf reduce; 33.6 million arguments),
//   - for +-8192 floats around each n pi/2, n = 1..128 (the cancelling ones),
//   - for every 61st float from pi to 2^7 pi/2;
// and beyond 2^7 pi/2 both parts must be NaN. Prints one summary line; exit
// status 0 when everything agrees.
#include <bit>
#include <cstdint>

#include "support/arm_linux_user.hpp"
#include "trig_reduction.hpp"

extern "C" int __ieee754_rem_pio2f(float x, float* y);  // newlib (libm.a)

namespace {

using kestrel::test::arm_linux_user::exit_with;
using kestrel::test::arm_linux_user::write_text;

std::uint32_t g_checked = 0;
std::uint32_t g_differ = 0;
std::uint32_t g_first_bad = 0;

void check(std::uint32_t bits) {
  const float x = std::bit_cast<float>(bits);
  float ours[2] = {0.0f, 0.0f};
  float ref[2] = {0.0f, 0.0f};
  const int n_ours = kestrel_m4f_rem_pio2f(x, ours);
  const int n_ref = __ieee754_rem_pio2f(x, ref);
  ++g_checked;
  if (n_ours != n_ref || std::bit_cast<std::uint32_t>(ours[0]) != std::bit_cast<std::uint32_t>(ref[0]) ||
      std::bit_cast<std::uint32_t>(ours[1]) != std::bit_cast<std::uint32_t>(ref[1])) {
    if (g_differ == 0) g_first_bad = bits;
    ++g_differ;
  }
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
  constexpr std::uint32_t kPiOver4 = 0x3f490fd8u;
  constexpr std::uint32_t kPi = 0x40490fdbu;  // float(pi) rounds up: every |x| <= pi
  constexpr std::uint32_t kMediumLimit = 0x43490f80u;
  for (std::uint32_t b = kPiOver4 + 1; b <= kPi; ++b) {
    check(b);
    check(b | 0x80000000u);
  }
  for (std::uint32_t n = 1; n <= 128; ++n) {
    const auto centre = std::bit_cast<std::uint32_t>(static_cast<float>(static_cast<double>(n) * 1.57079632679489661923));
    for (std::uint32_t b = centre - 8192; b <= centre + 8192 && b <= kMediumLimit; ++b) {
      check(b);
      check(b | 0x80000000u);
    }
  }
  for (std::uint32_t b = kPi; b <= kMediumLimit; b += 61) {
    check(b);
    check(b | 0x80000000u);
  }
  check(kMediumLimit);
  // Beyond the reduction's range: NaN, never a wrong number.
  std::uint32_t not_nan = 0;
  for (std::uint32_t b = kMediumLimit + 1; b < 0x7f800000u; b += 0x10001u) {
    float y[2] = {0.0f, 0.0f};
    (void)kestrel_m4f_rem_pio2f(std::bit_cast<float>(b), y);
    if ((std::bit_cast<std::uint32_t>(y[0]) & 0x7fffffffu) <= 0x7f800000u ||
        (std::bit_cast<std::uint32_t>(y[1]) & 0x7fffffffu) <= 0x7f800000u) {
      ++not_nan;  // a NaN's magnitude bits are above those of infinity
    }
  }
  char line[] = "checked xxxxxxxx differ xxxxxxxx first xxxxxxxx large-not-nan xxxxxxxx\n";
  put_hex(line + 8, g_checked);
  put_hex(line + 24, g_differ);
  put_hex(line + 39, g_first_bad);
  put_hex(line + 62, not_nan);
  write_text(line);
  exit_with(g_differ == 0 && not_nan == 0 && g_checked > 33000000u ? 0 : 1);
}
