// SPDX-License-Identifier: Apache-2.0
// Entry point of the heap-guard image (kestrel-rv64-guard.elf): the board
// loop and nothing else, linked with no start-up files against static glibc
// with every allocator wrapped to an undefined symbol. The image is never
// run; that it links at all is the proof that nothing reachable from the
// loop (the tracker step, the feed's framing and read(2), the sink's
// encoding and write(2), the clock, the assertion hook, the static
// constructors of the board objects) references the heap. Its symbol table
// then goes through the same check as the microcontroller images.
#include <cstdint>

#include "linux_syscall.hpp"
#include "loop.hpp"

// The two stand-ins of this image, both for glibc's stack protector: Debian
// builds glibc with -fstack-protector-strong, so libm's functions read the
// canary __stack_chk_guard and call __stack_chk_fail when it was
// overwritten. Static glibc defines the canary in libc-start.o (the process
// start-up: __libc_start_main, TLS set-up, locale, gettext, atexit, all of
// which allocate) and __stack_chk_fail in a member that formats a message
// through the fatal-error machinery. Neither is the tracker's code path: the
// first runs before main, the second only when the process is already being
// killed for a smashed stack. The process image (kestrel-rv64) links glibc's
// real ones.
extern "C" {
std::uintptr_t __stack_chk_guard = 0;
[[noreturn]] void __stack_chk_fail() { kestrel::rv64::sys::exit_group(127); }
}

extern "C" [[noreturn]] void kestrel_rv64_guard_entry() {
  kestrel::rv64::loop_init(0, 1, 0);
  for (;;) {
    (void)kestrel::rv64::loop_poll_once();
  }
}
