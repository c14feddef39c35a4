// SPDX-License-Identifier: Apache-2.0
// Board-level system services of the RP2040 image: the clock tree, the
// fatal-error path (breakpoint if a debugger is attached, then reset) and
// the record of the last failed KESTREL_ASSERT.
#pragma once

#include <cstdint>

namespace kestrel::m0plus {

/// Release IO and pads from reset, start the 12 MHz crystal, lock PLL_SYS
/// at 1500 MHz VCO and run clk_sys from it at kCoreClockHz (125 MHz),
/// clk_ref from the crystal and clk_peri from clk_sys. A step that never
/// completes reports through kestrel_assert_failed.
void configure_clocks();

/// Stop at a breakpoint when a debugger is attached, then request a system
/// reset (AIRCR.SYSRESETREQ). Note that this image runs from SRAM (see
/// rp2040_ram.ld): after a reset the boot ROM runs, not the image.
[[noreturn]] void halt_and_reset();

/// What the last failed KESTREL_ASSERT said (valid when magic ==
/// kAssertRecordMagic); read it with the debugger that loaded the image.
struct AssertRecord {
  std::uint32_t magic;
  const char* file;
  const char* expr;
  int line;
};
inline constexpr std::uint32_t kAssertRecordMagic = 0xA55E7F0Du;

AssertRecord& last_assert();

}  // namespace kestrel::m0plus
