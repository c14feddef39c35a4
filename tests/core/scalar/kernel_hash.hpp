// SPDX-License-Identifier: Apache-2.0
// The fixed-point kernels' hash: +, -, *, /, a prepared divisor, sqrt and
// hypot on pairs of raw values spread over every magnitude (saturated
// operands included), hashed with the saturations they count. The host test
// (fixed_point_kernels_test.cpp) checks every one of these results against
// an exact __int128 reference and the hash against the checked-in
// constant; the golden-hash programs recompute the hash where they run
// (x86-64 at -O0/-O2, i386, the Cortex-M0+ code under qemu-arm). So a
// board's own code paths (the Thumb-1 division loop, the short product)
// are held to the exact results, edge cases included, not only to the
// values one S1 run happens to meet.
#pragma once

#include <cstdint>

#include "core/scalar/s1_integer_scenario.hpp"
#include "kestrel/scalar/fixed_point_math.hpp"

namespace kestrel::test {

enum class KernelOp : std::uint8_t { kAdd, kSub, kMul, kDiv, kDivisor, kSqrt, kHypot };

/// A raw value with a random bit length (1..63), random bits and sign,
/// capped at the largest finite magnitude; one in 64 is a saturated value.
inline std::int64_t spread_raw(SplitMix64& g) {
  constexpr std::int64_t kMaxFinite = INT64_MAX - 1;
  const std::uint64_t pick = g.next();
  if ((pick & 63u) == 0) return (pick & 64u) != 0 ? INT64_MAX : -INT64_MAX;
  const int bits = static_cast<int>((pick >> 8) % 63u) + 1;
  std::uint64_t m = g.next() >> (64 - bits);
  if (m > static_cast<std::uint64_t>(kMaxFinite)) m = static_cast<std::uint64_t>(kMaxFinite);
  const auto v = static_cast<std::int64_t>(m);
  return (pick & 128u) != 0 ? -v : v;
}

/// visit(op, a_raw, b_raw, result_raw) for every kernel on `pairs` random
/// pairs (seeded, the same everywhere). The divisor takes |b| (it needs a
/// positive one), sqrt |a|.
template <int F, class Visit>
void run_kernels(int pairs, Visit&& visit) {
  using Q = FixedPoint<F>;
  SplitMix64 g(0x6B65726E656C73ull + F);
  for (int i = 0; i < pairs; ++i) {
    const Q a = Q::from_raw(spread_raw(g));
    const Q b = Q::from_raw(spread_raw(g));
    const Q abs_a = a.raw() < 0 ? -a : a;
    const Q abs_b = b.raw() < 0 ? -b : b;
    visit(KernelOp::kAdd, a.raw(), b.raw(), (a + b).raw());
    visit(KernelOp::kSub, a.raw(), b.raw(), (a - b).raw());
    visit(KernelOp::kMul, a.raw(), b.raw(), (a * b).raw());
    visit(KernelOp::kDiv, a.raw(), b.raw(), (a / b).raw());
    visit(KernelOp::kDivisor, a.raw(), abs_b.raw(), Q::divisor(abs_b).divide(a).raw());
    visit(KernelOp::kSqrt, abs_a.raw(), 0, fixed::sqrt(abs_a).raw());
    visit(KernelOp::kHypot, a.raw(), b.raw(), fixed::hypot(a, b).raw());
  }
}

inline constexpr int kKernelHashPairs = 4000;

/// Hash of every result of run_kernels(kKernelHashPairs) and of the
/// saturations they counted. Leaves the overflow counter reset.
template <int F>
std::uint64_t kernel_hash() {
  reset_fixed_point_overflow_count();
  Fnv1a64 h;
  run_kernels<F>(kKernelHashPairs, [&h](KernelOp, std::int64_t, std::int64_t, std::int64_t r) { h.add_signed(r); });
  h.add(fixed_point_overflow_count());
  reset_fixed_point_overflow_count();
  return h.value();
}

/// Checked-in values of kernel_hash(): exact results (fixed_point_kernels_test
/// checks each one), so they change only if a kernel's result does.
inline constexpr std::uint64_t kKernelHashQ31_32 = 0x2906c8022233af67ull;
inline constexpr std::uint64_t kKernelHashQ23_40 = 0x1558c043dde61d8aull;

}  // namespace kestrel::test
