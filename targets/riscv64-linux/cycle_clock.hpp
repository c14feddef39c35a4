// SPDX-License-Identifier: Apache-2.0
// CycleClocks of the riscv64-linux board, chosen when configuring with
// -DKESTREL_RV64_CYCLE_CLOCK=monotonic (default) | rdtime | rdcycle:
// MonotonicClock reads clock_gettime(CLOCK_MONOTONIC) in ns on every kernel,
// as a system call (linux_syscall.hpp says why not glibc's vDSO path);
// RdtimeClock reads the platform timer CSR at the device tree's
// timebase-frequency, cheap but coarse; RdcycleClock reads core cycles, which
// Linux 6.6 and later trap in user mode (SIGILL) unless
// kernel.perf_user_access=2. All three give 64-bit counts that never wrap in
// practice, so a step's duration is the difference of two reads. Trade-offs:
// docs/porting.md, "riscv64-linux".
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
