// SPDX-License-Identifier: Apache-2.0
// CycleClock of the Cortex-M0+ board: ARMv6-M has no DWT cycle counter, so
// the 24-bit SysTick counter runs at the processor clock (reload 2^24 - 1,
// counting down) and its interrupt (SysTick_Handler, systick_cycle_clock.cpp)
// counts the wraps, every 2^24 / 125 MHz = 134 ms. now_cycles() combines
// the two into 64 bits: it reads the wrap count, the counter and the wrap
// count again, retries (a bounded number of times) when a wrap was counted
// in between, and counts a wrap that is pending but not yet handled
// (interrupts masked), so it never goes backwards. Cost: one interrupt of a few cycles per 134 ms.
#pragma once

#include <cstdint>

#include "board_config.hpp"

namespace kestrel::m0plus {

class SysTickCycleClock {
 public:
  /// Start SysTick on the processor clock with its interrupt. Call once,
  /// after configure_clocks(), with the clock it left (core_clock_hz()).
  void start(std::uint32_t core_clock_hz);

  /// Processor cycles since start(), 64 bits.
  [[nodiscard]] std::uint64_t now_cycles();

  [[nodiscard]] std::uint64_t cycles_per_second() const { return core_clock_hz_; }

 private:
  std::uint32_t core_clock_hz_ = 0;
};

}  // namespace kestrel::m0plus
