// SPDX-License-Identifier: Apache-2.0
// Board-level system services of the RP2040 image: the clock tree, the
// fatal-error path (breakpoint if a debugger is attached, then reset) and
// the record of the last failed KESTREL_ASSERT.
#pragma once

#include <cstdint>

namespace kestrel::m0plus {

/// Why configure_clocks() left clk_sys below kCoreClockHz (kNone: it did not).
enum class ClockFallback : std::uint8_t {
  kNone = 0,        ///< clk_sys on PLL_SYS at kCoreClockHz.
  kXoscNotStable,   ///< The crystal never reported stable: ring oscillator, about kRoscNominalHz.
  kClkRefNotXosc,   ///< clk_ref did not switch to the crystal: ring oscillator.
  kClkSysNotOnRef,  ///< clk_sys did not report clk_ref before the PLL switch: crystal, kXoscHz.
  kPllNoLock,       ///< PLL_SYS stuck in reset or not locked (powered down again): crystal, kXoscHz.
  kPllNotSelected,  ///< clk_sys did not switch to PLL_SYS (put back on clk_ref): crystal, kXoscHz.
};

/// Release IO and pads from reset, start the 12 MHz crystal, lock PLL_SYS
/// at 1500 MHz VCO and run clk_sys from it at kCoreClockHz (125 MHz),
/// clk_ref from the crystal and clk_peri from clk_sys. Every wait is
/// bounded. A clock step that does not complete leaves clk_sys on the best
/// clock reached so far (the crystal at kXoscHz, else the ring oscillator),
/// records why (clock_fallback()) and carries on; clk_peri is enabled on
/// every path. Only IO/pads stuck in reset asserts: without them there is
/// no UART link, and no other clock or route replaces them.
ClockFallback configure_clocks();

/// What configure_clocks() did; kNone before it runs.
[[nodiscard]] ClockFallback clock_fallback();
/// clk_sys = clk_peri in Hz as configured now (nominal on the ring oscillator).
[[nodiscard]] std::uint32_t core_clock_hz();

/// Poll RESETS.RESET_DONE until every bit of mask is set, a bounded number
/// of times; false if a peripheral did not leave reset.
[[nodiscard]] bool wait_for_reset_done(std::uint32_t mask);

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
