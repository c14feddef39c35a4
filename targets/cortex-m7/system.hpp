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

/// Configure the LDO supply, voltage scale 1, flash wait states, and raise
/// the core to kCoreClockHz (400 MHz) from the internal 64 MHz HSI through
/// PLL1; hclk = 200 MHz, APB1..4 = 100 MHz. On a step that never completes
/// it reports through kestrel_assert_failed (reset).
void configure_clocks();

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
