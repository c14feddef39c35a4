// SPDX-License-Identifier: Apache-2.0
// Board-level system services of the STM32H743 image: the L1 caches, the
// power and clock tree, the fatal-error path (breakpoint if a debugger is
// attached, then reset) and the record of the last failed KESTREL_ASSERT,
// kept across that reset.
#pragma once

#include <cstdint>

namespace kestrel::m7 {

/// Invalidate and enable the Cortex-M7 L1 instruction and data caches
/// (ARMv7-M B2.2.7 maintenance operations). Call once, early; the image
/// uses no DMA, so no buffer needs cache maintenance afterwards (DTCM,
/// where all data lives, is never cached).
void enable_caches();

/// Why configure_clocks() left the core on the HSI (kNone: it did not).
enum class ClockFallback : std::uint8_t {
  kNone = 0,        ///< PLL1 selected: sys_ck kCoreClockHz, APB1 kApb1Hz.
  kSupplyNotReady,  ///< PWR_CSR1.ACTVOSRDY not set within the bound.
  kVoltageScale,    ///< PWR_D3CR.VOSRDY not set after asking for scale 1.
  kFlashLatency,    ///< FLASH_ACR did not read back the wait states.
  kPllNoLock,       ///< PLL1RDY not set within the bound; PLL1 switched off again.
  kPllNotSelected,  ///< SWS did not report PLL1; SW set back to HSI, prescalers to 1.
};

/// Configure the LDO supply, voltage scale 1, flash wait states, and raise
/// the core to kCoreClockHz (400 MHz) from the internal 64 MHz HSI through
/// PLL1; hclk = 200 MHz, APB1..4 = 100 MHz. Every wait is bounded: on a
/// step that does not complete the core stays on the HSI at kHsiHz with
/// every prescaler 1 (the reset clock tree), the reason is recorded
/// (clock_fallback()) and start-up carries on. Returns clock_fallback().
ClockFallback configure_clocks();

/// What configure_clocks() did; kNone before it runs.
[[nodiscard]] ClockFallback clock_fallback();
/// The core clock (sys_ck, DWT CYCCNT's rate) in Hz as configured now.
[[nodiscard]] std::uint32_t core_clock_hz();
/// The APB1 clock (USART3's kernel clock) in Hz as configured now.
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

}  // namespace kestrel::m7
