// SPDX-License-Identifier: Apache-2.0
// Board-level system services of the STM32F407 image: the clock tree, the
// fatal-error path (breakpoint if a debugger is attached, then reset) and
// the record of the last failed KESTREL_ASSERT, kept across that reset.
#pragma once

#include <cstdint>

namespace kestrel::m4f {

/// Why configure_clocks() left the core on the HSI (kNone: it did not).
enum class ClockFallback : std::uint8_t {
  kNone = 0,           ///< PLL selected: HCLK kCoreClockHz, APB1 kCoreClockHz / 4.
  kFlashLatency,       ///< FLASH_ACR did not take 5 wait states; the PLL was not started.
  kPllNoLock,          ///< PLLRDY not set within kPllLockSpins polls; PLL switched off again.
  kPllNotSelected,     ///< SWS did not report the PLL within the bound; SW set back to HSI.
};

/// Raise the core to kCoreClockHz (168 MHz) from the internal 16 MHz HSI
/// through the main PLL, with the flash wait states, prefetch and caches
/// that speed needs; APB1 = 42 MHz, APB2 = 84 MHz. Every wait on the
/// hardware is bounded. If a step does not complete within its bound (a
/// board whose PLL never locks, an emulator that does not model the RCC),
/// the core stays on the HSI at kHsiHz with AHB and APB prescalers at 1
/// (APB1 = 16 MHz), the reason is recorded (clock_fallback()) and start-up
/// carries on: a slower board that still tracks and reports, rather than
/// one that resets for ever. Returns the same value as clock_fallback().
ClockFallback configure_clocks();

/// What configure_clocks() did; kNone before it runs (the reset clock is
/// the HSI, which core_clock_hz() then reports).
[[nodiscard]] ClockFallback clock_fallback();
/// The core clock (HCLK, also DWT CYCCNT's rate) in Hz as configured now:
/// kCoreClockHz, or kHsiHz before configure_clocks() and after a fallback.
[[nodiscard]] std::uint32_t core_clock_hz();
/// The APB1 clock (USART2's kernel clock) in Hz as configured now.
[[nodiscard]] std::uint32_t apb1_clock_hz();

/// Stop at a breakpoint when a debugger is attached, then request a system
/// reset (AIRCR.SYSRESETREQ). Safe from any context, including faults.
[[noreturn]] void halt_and_reset();

/// What the last failed KESTREL_ASSERT said. Lives in .noinit, so it
/// survives the reset that follows; valid when magic == kAssertRecordMagic.
struct AssertRecord {
  std::uint32_t magic;
  const char* file;
  const char* expr;
  int line;
};
inline constexpr std::uint32_t kAssertRecordMagic = 0xA55E7F0Du;

/// The record (read it with a debugger, or report it after start-up).
AssertRecord& last_assert();

}  // namespace kestrel::m4f
