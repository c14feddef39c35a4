// SPDX-License-Identifier: Apache-2.0
// A program whose counted interval is known exactly, for the counting
// plugin's own test (plugin_test.sh): between the first two marks run the
// marker's return (1), movs + lsls (2), 128,000 x (subs + bne) and the call
// of the second mark (1): 256,004 instructions; between the second and
// third, the return and the call: 2.
#include "support/arm_linux_user.hpp"

extern "C" __attribute__((noinline)) void kestrel_count_mark() { asm volatile("" ::: "memory"); }

extern "C" [[noreturn]] void _start() {
  kestrel_count_mark();
  asm volatile(
      ".syntax unified\n"
      "movs r0, #250\n"
      "lsls r0, r0, #9\n"  // 128,000
      "1: subs r0, #1\n"
      "bne 1b\n"
      ".syntax divided\n" ::: "r0", "cc");
  kestrel_count_mark();
  kestrel_count_mark();
  kestrel::test::arm_linux_user::exit_with(0);
}
