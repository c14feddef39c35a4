// SPDX-License-Identifier: Apache-2.0
// The kernel set the golden-hash programs hash on every build and board
// (kernel_hash.hpp): here each of its results is checked against an exact
// __int128 reference, so a matching hash elsewhere means exact results
// there too.
#include <catch2/catch.hpp>
#include <cstdint>

#include "core/scalar/kernel_hash.hpp"

namespace {

__extension__ typedef __int128 I128;
__extension__ typedef unsigned __int128 U128;

constexpr I128 kMaxFinite = INT64_MAX - 1;

bool finite(std::int64_t raw) { return raw > -INT64_MAX && raw < INT64_MAX; }

U128 magnitude(I128 v) { return v < 0 ? static_cast<U128>(-v) : static_cast<U128>(v); }

/// round(n / d) of magnitudes, ties to even.
U128 round_div(U128 n, U128 d) {
  U128 q = n / d;
  const U128 r2 = (n % d) * 2;
  if (r2 > d || (r2 == d && (q & 1) != 0)) ++q;
  return q;
}

/// The correctly rounded signed result of sign * mag, or saturation.
bool matches(std::int64_t got, bool negative, U128 mag) {
  if (mag > static_cast<U128>(kMaxFinite)) return got == (negative ? -INT64_MAX : INT64_MAX);
  const I128 want = negative ? -static_cast<I128>(mag) : static_cast<I128>(mag);
  return got == static_cast<std::int64_t>(want);
}

/// true if r = round(sqrt(n)).
bool is_rounded_sqrt(U128 r, U128 n) {
  const U128 rr = r * r;
  return (r == 0 ? n == 0 : n + r > rr) && n <= rr + r;
}

/// Whether one kernel result is the exact one (a prepared divisor: within
/// 1.5 LSB of the exact quotient).
template <int F>
bool exact(kestrel::test::KernelOp op, std::int64_t a, std::int64_t b, std::int64_t got) {
  using kestrel::test::KernelOp;
  const bool operands_finite = finite(a) && (op == KernelOp::kSqrt || finite(b));
  if (!operands_finite) {
    if (op == KernelOp::kDiv && finite(a)) return got == 0;  // finite / "infinite"
    return !finite(got);                                    // saturation sticks
  }
  const bool negative = (a < 0) != (b < 0);
  switch (op) {
    case KernelOp::kAdd:
    case KernelOp::kSub: {
      const I128 s = op == KernelOp::kAdd ? static_cast<I128>(a) + b : static_cast<I128>(a) - b;
      return matches(got, s < 0, magnitude(s));
    }
    case KernelOp::kMul: {
      const U128 m = magnitude(a) * magnitude(b);
      U128 q = m >> F;
      const U128 rem = m - (q << F);
      const U128 half = U128{1} << (F - 1);
      if (rem > half || (rem == half && (q & 1) != 0)) ++q;
      return matches(got, negative && q != 0, q);
    }
    case KernelOp::kDiv:
      if (b == 0) return !finite(got);
      return matches(got, negative, round_div(magnitude(a) << F, magnitude(b)));
    case KernelOp::kDivisor: {
      if (b <= 0) return !finite(got);
      const U128 mag = magnitude(a) << F;  // the exact quotient is mag / b
      const U128 b2 = 2 * static_cast<U128>(b);
      const U128 slack = 3 * static_cast<U128>(b);  // 1.5 LSB, times 2b
      const U128 lo = 2 * mag > slack ? (2 * mag - slack + b2 - 1) / b2 : 0;
      const U128 hi = (2 * mag + slack) / b2;
      if (!finite(got)) return hi > static_cast<U128>(kMaxFinite);
      const U128 g = magnitude(got);
      return g >= lo && g <= hi && (g == 0 || (got < 0) == (a < 0));
    }
    case KernelOp::kSqrt:
      return got >= 0 && is_rounded_sqrt(static_cast<U128>(got), static_cast<U128>(a) << F);
    case KernelOp::kHypot: {
      const U128 n = magnitude(a) * magnitude(a) + magnitude(b) * magnitude(b);
      const U128 r_max = static_cast<U128>(kMaxFinite);
      if (!finite(got)) return n > r_max * r_max + r_max;  // round(sqrt(n)) > the largest finite raw
      return is_rounded_sqrt(static_cast<U128>(got), n);
    }
  }
  return false;
}

template <int F>
void check_kernel_set(std::uint64_t checked_in) {
  int results = 0;
  int wrong = 0;
  int saturated = 0;
  kestrel::test::run_kernels<F>(kestrel::test::kKernelHashPairs,
                                [&](kestrel::test::KernelOp op, std::int64_t a, std::int64_t b, std::int64_t got) {
                                  ++results;
                                  saturated += finite(got) ? 0 : 1;
                                  if (!exact<F>(op, a, b, got)) {
                                    ++wrong;
                                    UNSCOPED_INFO("op " << static_cast<int>(op) << " a " << a << " b " << b
                                                        << " got " << got);
                                  }
                                });
  THEN("every result is the exact one and the set reaches saturation") {
    CHECK(results == 7 * kestrel::test::kKernelHashPairs);
    CHECK(wrong == 0);
    CHECK(saturated > 100);
    AND_THEN("its hash is the checked-in value the boards and builds compare with") {
      const std::uint64_t h = kestrel::test::kernel_hash<F>();
      INFO("kernel_hash = 0x" << std::hex << h);
      CHECK(h == checked_in);
    }
  }
}

}  // namespace

SCENARIO("the kernel set the golden-hash programs hash is exact on the host", "[fixed_point]") {
  GIVEN("Q31.32") { check_kernel_set<32>(kestrel::test::kKernelHashQ31_32); }
  GIVEN("Q23.40") { check_kernel_set<40>(kestrel::test::kKernelHashQ23_40); }
}
