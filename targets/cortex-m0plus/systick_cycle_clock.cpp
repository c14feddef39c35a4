// SPDX-License-Identifier: Apache-2.0
// SysTick cycle clock (see systick_cycle_clock.hpp) and its interrupt.
#include "systick_cycle_clock.hpp"

#include <atomic>

#include "registers.hpp"

namespace kestrel::m0plus {
namespace {

constexpr std::uint32_t kReload = 0x00FFFFFFu;  // 2^24 - 1: the full 24-bit range

// Written by SysTick_Handler only (a plain load and store: ARMv6-M has no
// exclusive access, and a single writer needs none).
constinit std::atomic<std::uint32_t> g_wraps{0};

}  // namespace

void SysTickCycleClock::start(std::uint32_t core_clock_hz) {
  using namespace regs;
  core_clock_hz_ = core_clock_hz;
  reg(kSysTickCsr) = 0;
  reg(kSysTickRvr) = kReload;
  reg(kSysTickCvr) = 0;  // any write clears the counter and COUNTFLAG
  g_wraps.store(0, std::memory_order_relaxed);
  reg(kSysTickCsr) = kSysTickEnable | kSysTickTickInt | kSysTickClkSourceCpu;
}

std::uint64_t SysTickCycleClock::now_cycles() {
  using namespace regs;
  // The handler runs at most once per 2^24 cycles, so a second attempt
  // never sees it run again; kAttempts only bounds the loop.
  constexpr int kAttempts = 3;
  std::uint32_t wraps = 0;
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    const std::uint32_t before = g_wraps.load(std::memory_order_acquire);
    const std::uint32_t down = reg(kSysTickCvr);
    const bool pending = (reg(kScbIcsr) & kIcsrPendStSet) != 0;
    wraps = g_wraps.load(std::memory_order_acquire);
    if (before != wraps) continue;  // the handler ran in between: read again
    if (!pending) return (static_cast<std::uint64_t>(wraps) << 24) | (kReload - down);
    // A wrap is pending but not counted (interrupts masked, or the handler
    // is about to run): count it here, with the counter read after it.
    return (static_cast<std::uint64_t>(wraps + 1u) << 24) | (kReload - reg(kSysTickCvr));
  }
  return (static_cast<std::uint64_t>(wraps) << 24) | (kReload - reg(kSysTickCvr));
}

}  // namespace kestrel::m0plus

extern "C" void SysTick_Handler() {
  using kestrel::m0plus::g_wraps;
  g_wraps.store(g_wraps.load(std::memory_order_relaxed) + 1u, std::memory_order_release);
}
