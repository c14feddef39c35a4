// SPDX-License-Identifier: Apache-2.0
// The few Linux system calls the tracker's code path makes on the
// riscv64-linux board (read, write, clock_gettime; kill and exit_group on a
// failed assertion), issued directly with `ecall` (RISC-V Linux ABI: number
// in a7, arguments in a0..a2, result or -errno in a0; numbers from the
// kernel's asm-generic/unistd.h, which riscv64 uses).
//
// Why not glibc's wrappers: in static glibc they live in archive members
// tied to the process start-up (clock_gettime's vDSO pointer is set up in
// dl-support.o, which brings the dynamic-loader support, gettext and
// malloc). This board's equivalent of a microcontroller's register-level
// driver is the system call itself, so the loop depends on no libc I/O and
// the heap guard can cover every instruction it runs (docs/porting.md).
// The cost: clock_gettime is a real system call (a few hundred ns on
// current SoCs) instead of a vDSO read; the rdtime clock avoids it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <ctime>

namespace kestrel::rv64::sys {

inline constexpr long kRead = 63;
inline constexpr long kWrite = 64;
inline constexpr long kExitGroup = 94;
inline constexpr long kClockGettime = 113;
inline constexpr long kKill = 129;
inline constexpr long kGetpid = 172;

inline long call(long number, long arg0 = 0, long arg1 = 0, long arg2 = 0) {
  register long a0 __asm__("a0") = arg0;
  register long a1 __asm__("a1") = arg1;
  register long a2 __asm__("a2") = arg2;
  register long a7 __asm__("a7") = number;
  __asm__ volatile("ecall" : "+r"(a0) : "r"(a1), "r"(a2), "r"(a7) : "memory");
  return a0;
}

inline long as_arg(const void* p) { return static_cast<long>(reinterpret_cast<std::uintptr_t>(p)); }

/// read(2): bytes read, 0 at end of file, or -errno (-EAGAIN: nothing now).
inline long read(int fd, void* buf, std::size_t n) { return call(kRead, fd, as_arg(buf), static_cast<long>(n)); }

/// write(2): bytes written or -errno.
inline long write(int fd, const void* buf, std::size_t n) {
  return call(kWrite, fd, as_arg(buf), static_cast<long>(n));
}

/// clock_gettime(2) into `ts` (the kernel's 64-bit timespec on riscv64): 0 or -errno.
inline long clock_gettime(clockid_t clock, timespec& ts) { return call(kClockGettime, clock, as_arg(&ts)); }

/// Send `sig` to this process.
inline void kill_self(int sig) { (void)call(kKill, call(kGetpid), sig); }

[[noreturn]] inline void exit_group(int status) {
  (void)call(kExitGroup, status);
  __builtin_unreachable();
}

}  // namespace kestrel::rv64::sys
