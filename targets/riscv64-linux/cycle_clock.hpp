// SPDX-License-Identifier: Apache-2.0
// CycleClocks of the riscv64-linux board (docs/tracking.md: rdcycle/mcycle on
// RISC-V). Which one the board uses is chosen when configuring:
//   -DKESTREL_RV64_CYCLE_CLOCK=monotonic (default) | rdtime | rdcycle
//
//   MonotonicClock  clock_gettime(CLOCK_MONOTONIC), nanoseconds. Works on
//                   every kernel. Issued as a system call (linux_syscall.hpp
//                   says why not through glibc's vDSO path), which adds a
//                   few hundred ns per read on current SoCs: two reads per
//                   step, so part of one is in each measured step.
//   RdtimeClock     the `rdtime` instruction: the platform timer (CSR time),
//                   readable from user mode on Linux, at the device tree's
//                   timebase-frequency (4 MHz on the JH7110, 24 MHz on the
//                   D1, 10 MHz on QEMU virt). The cheapest read, but coarse:
//                   one tick is tens to hundreds of core cycles.
//   RdcycleClock    the `rdcycle` instruction: core cycles. Linux 6.6 and
//                   later stop user-mode access to the cycle CSR by default
//                   (the instruction traps and the process gets SIGILL)
//                   unless the administrator sets
//                   `sysctl kernel.perf_user_access=2`; older kernels allow
//                   it. Its rate is the core clock, which the shell reads
//                   from cpufreq or takes from --clock-hz.
// All three give 64-bit counts that never wrap in practice, so a step's
// duration is the difference of two reads.
#pragma once

#include <cstdint>
#include <ctime>

#include "linux_syscall.hpp"

namespace kestrel::rv64 {

class MonotonicClock {
 public:
  [[nodiscard]] std::uint64_t now_cycles() const {
    timespec ts{};
    (void)sys::clock_gettime(CLOCK_MONOTONIC, ts);  // cannot fail for CLOCK_MONOTONIC
    return static_cast<std::uint64_t>(ts.tv_sec) * 1'000'000'000u + static_cast<std::uint64_t>(ts.tv_nsec);
  }
  [[nodiscard]] std::uint64_t cycles_per_second() const { return 1'000'000'000u; }
  void set_rate(std::uint64_t /*hz*/) {}
  static constexpr const char* kName = "clock_gettime(CLOCK_MONOTONIC)";
  static constexpr bool kNeedsRate = false;
};

class RdtimeClock {
 public:
  [[nodiscard]] std::uint64_t now_cycles() const {
    std::uint64_t t;
    __asm__ volatile("rdtime %0" : "=r"(t));
    return t;
  }
  [[nodiscard]] std::uint64_t cycles_per_second() const { return hz_; }
  /// The timebase frequency (device tree /cpus/timebase-frequency).
  void set_rate(std::uint64_t hz) { hz_ = hz; }
  static constexpr const char* kName = "rdtime (platform timer)";
  static constexpr bool kNeedsRate = true;

 private:
  std::uint64_t hz_ = 0;
};

class RdcycleClock {
 public:
  [[nodiscard]] std::uint64_t now_cycles() const {
    std::uint64_t c;
    __asm__ volatile("rdcycle %0" : "=r"(c));
    return c;
  }
  [[nodiscard]] std::uint64_t cycles_per_second() const { return hz_; }
  /// The core clock (cpufreq, or --clock-hz).
  void set_rate(std::uint64_t hz) { hz_ = hz; }
  static constexpr const char* kName = "rdcycle (core cycles)";
  static constexpr bool kNeedsRate = true;

 private:
  std::uint64_t hz_ = 0;
};

#if defined(KESTREL_RV64_CLOCK_RDTIME)
using CycleClock = RdtimeClock;
#elif defined(KESTREL_RV64_CLOCK_RDCYCLE)
using CycleClock = RdcycleClock;
#else
using CycleClock = MonotonicClock;
#endif

}  // namespace kestrel::rv64
