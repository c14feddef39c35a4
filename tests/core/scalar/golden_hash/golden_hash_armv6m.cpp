// SPDX-License-Identifier: Apache-2.0
// The golden-hash program for the Cortex-M0+ code generation: the same S1
// runs as golden_hash_main.cpp, compiled with the board's flags
// (-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft -Os, newlib-nano) and run
// under qemu-arm's Linux user mode, which executes ARMv6-M Thumb code
// unchanged. No semihosting and no printf: the hashes go out through the
// Linux write system call, and the exit status says whether both equal the
// checked-in constants. Build and run (from the repository root):
//   arm-none-eabi-g++ -mcpu=cortex-m0plus -mthumb -mfloat-abi=soft -Os -std=c++20 \
//     -fno-exceptions -fno-rtti -DEIGEN_NO_MALLOC -nostartfiles --specs=nano.specs \
//     -Icore/include -Ihal/include -Itests -isystem /usr/include/eigen3 \
//     tests/core/scalar/golden_hash/golden_hash_armv6m.cpp -o golden_hash_m0plus.elf
//   qemu-arm golden_hash_m0plus.elf
// (tests/core/scalar/CMakeLists.txt does this when both tools exist.)
#include <cstddef>
#include <cstdint>

#include "core/scalar/kernel_hash.hpp"
#include "core/scalar/s1_integer_scenario.hpp"
#include "support/arm_linux_user.hpp"

namespace {

using kestrel::test::arm_linux_user::exit_with;
using kestrel::test::arm_linux_user::write_text;

void write_hash(const char* label, std::uint64_t h, bool ok) {
  char line[64];
  std::size_t i = 0;
  for (const char* p = label; *p != '\0'; ++p) line[i++] = *p;
  line[i++] = ' ';
  line[i++] = '0';
  line[i++] = 'x';
  for (int d = 15; d >= 0; --d) line[i++] = "0123456789abcdef"[(h >> (4 * d)) & 0xFu];
  for (const char* p = ok ? " ok\n" : " MISMATCH\n"; *p != '\0'; ++p) line[i++] = *p;
  line[i] = '\0';
  write_text(line);
}

}  // namespace

extern "C" [[noreturn]] void kestrel_assert_failed(const char*, int, const char*) {
  write_text("assertion failed\n");
  exit_with(2);
}

extern "C" [[noreturn]] void _start() {
  const std::uint64_t k31 = kestrel::test::kernel_hash<32>();
  const std::uint64_t k23 = kestrel::test::kernel_hash<40>();
  const bool kernels_ok = k31 == kestrel::test::kKernelHashQ31_32 && k23 == kestrel::test::kKernelHashQ23_40;
  write_hash("kernels Q31.32", k31, k31 == kestrel::test::kKernelHashQ31_32);
  write_hash("kernels Q23.40", k23, k23 == kestrel::test::kKernelHashQ23_40);
  const std::uint64_t q31 = kestrel::test::s1_golden_hash<32>();
  const std::uint64_t q23 = kestrel::test::s1_golden_hash<40>();
  const bool ok31 = q31 == kestrel::test::kS1GoldenHashQ31_32;
  const bool ok23 = q23 == kestrel::test::kS1GoldenHashQ23_40;
  write_hash("Q31.32", q31, ok31);
  write_hash("Q23.40", q23, ok23);
  const bool clean = kestrel::fixed_point_overflow_count() == 0;
  write_text(clean ? "ARMv6-M (Cortex-M0+ code), overflow events 0\n" : "overflow events counted\n");
  exit_with(kernels_ok && ok31 && ok23 && clean ? 0 : 1);
}
