// SPDX-License-Identifier: Apache-2.0
// The riscv64-linux board's definition of the core's assertion hook
// (kestrel/assert.hpp): file, line and expression to stderr with write(2),
// then SIGABRT (a core dump where enabled), as abort() would. No stdio and
// no glibc: this unit is on the tracker's code path and is linked into the
// heap-guard image (linux_syscall.hpp).
#include <csignal>
#include <cstring>

#include "kestrel/assert.hpp"
#include "linux_syscall.hpp"

namespace {

void put(const char* s) {
  // Best effort: nothing useful can be done if stderr is gone.
  (void)kestrel::rv64::sys::write(2, s, std::strlen(s));
}

void put_int(int v) {
  char digits[12];
  char* p = digits + sizeof digits;
  *--p = '\0';
  unsigned u = v < 0 ? 0u - static_cast<unsigned>(v) : static_cast<unsigned>(v);
  do {
    *--p = static_cast<char>('0' + u % 10u);
    u /= 10u;
  } while (u != 0 && p > digits + 1);
  if (v < 0) *--p = '-';
  put(p);
}

}  // namespace

extern "C" [[noreturn]] void kestrel_assert_failed(const char* file, int line, const char* expr) {
  put(file);
  put(":");
  put_int(line);
  put(": KESTREL_ASSERT(");
  put(expr);
  put(") failed\n");
  kestrel::rv64::sys::kill_self(SIGABRT);
  kestrel::rv64::sys::exit_group(128 + SIGABRT);  // SIGABRT blocked or ignored
}
