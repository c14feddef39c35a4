// SPDX-License-Identifier: Apache-2.0
// Standalone golden-hash program (no Catch2, no host board library): runs
// S1 seed 1 on Q31.32 and Q23.40 and compares the hash of every step's
// state and covariance with the checked-in constants of
// s1_integer_scenario.hpp. CTest builds it at -O0, -O2 and, where the
// compiler can, -m32 (golden_hash/CMakeLists.txt): the fixed-point result
// must not depend on the optimiser or the word size.
// Exit status 0 when both hashes match.
#include <cstdio>
#include <cstdlib>

#include "core/scalar/kernel_hash.hpp"
#include "core/scalar/s1_integer_scenario.hpp"

extern "C" [[noreturn]] void kestrel_assert_failed(const char* file, int line, const char* expr) {
  std::fprintf(stderr, "%s:%d: assertion failed: %s\n", file, line, expr);
  std::abort();
}

int main() {
  const std::uint64_t k31 = kestrel::test::kernel_hash<32>();
  const std::uint64_t k23 = kestrel::test::kernel_hash<40>();
  const bool kernels_ok = k31 == kestrel::test::kKernelHashQ31_32 && k23 == kestrel::test::kKernelHashQ23_40;
  std::printf("kernels Q31.32 0x%08lx%08lx, Q23.40 0x%08lx%08lx %s\n", static_cast<unsigned long>(k31 >> 32),
              static_cast<unsigned long>(k31 & 0xFFFFFFFFu), static_cast<unsigned long>(k23 >> 32),
              static_cast<unsigned long>(k23 & 0xFFFFFFFFu), kernels_ok ? "ok" : "MISMATCH");
  const std::uint64_t q31 = kestrel::test::s1_golden_hash<32>();
  const std::uint64_t q23 = kestrel::test::s1_golden_hash<40>();
  const bool ok31 = q31 == kestrel::test::kS1GoldenHashQ31_32;
  const bool ok23 = q23 == kestrel::test::kS1GoldenHashQ23_40;
  // Two 32-bit halves: newlib's printf has no PRIx64 on every target.
  std::printf("Q31.32 0x%08lx%08lx %s\n", static_cast<unsigned long>(q31 >> 32),
              static_cast<unsigned long>(q31 & 0xFFFFFFFFu), ok31 ? "ok" : "MISMATCH");
  std::printf("Q23.40 0x%08lx%08lx %s\n", static_cast<unsigned long>(q23 >> 32),
              static_cast<unsigned long>(q23 & 0xFFFFFFFFu), ok23 ? "ok" : "MISMATCH");
  std::printf("sizeof(void*) = %u, overflow events = %u\n", static_cast<unsigned>(sizeof(void*)),
              static_cast<unsigned>(kestrel::fixed_point_overflow_count()));
  return kernels_ok && ok31 && ok23 && kestrel::fixed_point_overflow_count() == 0 ? 0 : 1;
}
