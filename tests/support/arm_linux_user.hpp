// SPDX-License-Identifier: Apache-2.0
// Output and exit for test programs built with a Cortex-M board's code
// generation (no start files, no C library I/O) and run under qemu-arm's
// Linux user mode: the Linux write and exit system calls through `svc 0`.
#pragma once

#include <cstddef>

namespace kestrel::test::arm_linux_user {

inline long syscall3(long number, long a, long b, long c) {
  register long r0 asm("r0") = a;
  register long r1 asm("r1") = b;
  register long r2 asm("r2") = c;
  register long r7 asm("r7") = number;
  asm volatile("svc 0" : "+r"(r0) : "r"(r1), "r"(r2), "r"(r7) : "memory");
  return r0;
}

/// write(1, data, size).
inline void write_stdout(const char* data, std::size_t size) {
  syscall3(4 /* write */, 1, reinterpret_cast<long>(data), static_cast<long>(size));
}

/// write(1, s, strlen(s)).
inline void write_text(const char* s) {
  std::size_t n = 0;
  while (s[n] != '\0') ++n;
  write_stdout(s, n);
}

[[noreturn]] inline void exit_with(long status) {
  syscall3(1 /* exit */, status, 0, 0);
  __builtin_unreachable();
}

}  // namespace kestrel::test::arm_linux_user
