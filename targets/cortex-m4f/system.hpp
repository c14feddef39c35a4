// SPDX-License-Identifier: Apache-2.0
// Board-level system services of the STM32F407 image: the clock tree, the
// fatal-error path (breakpoint if a debugger is attached, then reset) and
// the record of the last failed KESTREL_ASSERT, kept across that reset.
#pragma once

#include <cstdint>

namespace kestrel::m4f {

/// Raise the core to kCoreClockHz (168 MHz) from the internal 16 MHz HSI
/// through the main PLL, with the flash wait states, prefetch and caches
/// that speed needs; APB1 = 42 MHz, APB2 = 84 MHz. On a PLL that does not
/// lock, it reports through kestrel_assert_failed (reset).
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

}  // namespace kestrel::m4f
