// SPDX-License-Identifier: Apache-2.0
// hypotf for the Cortex-M4F image. newlib has no float hypotf of its own in
// this build: std::hypot(float, float) links libstdc++'s stub
// (math_stubs_float.o), which scales by s = |x| + |y| and calls newlib's
// sqrtf, a wrapper that sets errno for a negative argument around
// __ieee754_sqrtf (one VSQRT.F32): 160 bytes with __errno for a square
// root the FPU does in one instruction. This is the stub's arithmetic,
// operation for operation as that build compiles it (including its fused
// multiply-add), with VSQRT.F32 inline; the argument of the square root is
// never negative, so the wrapper would have returned VSQRT's result
// unchanged and the bits are the same.
// tests/targets/remainderf/remainderf_test.cpp compares the two under
// qemu-arm.
#include "hypotf.hpp"

#include <cmath>

extern "C" float kestrel_m4f_hypotf(float x, float y) {
  const float s = std::fabs(x) + std::fabs(y);
  // The stub's test "s == 0" (s is never negative): a zero is returned as is, NaN goes on.
  if (!(s > 0.0f) && !std::isnan(s)) return s;
  const float xs = x / s;
  const float ys = y / s;
  // -fno-math-errno (kestrel_firmware_flags): a VSQRT.F32, no call.
  return s * std::sqrt(std::fma(xs, xs, ys * ys));
}

#ifndef KESTREL_M4F_KEEP_LIBSTDCXX_HYPOTF
extern "C" float hypotf(float x, float y) __attribute__((alias("kestrel_m4f_hypotf")));
#endif
