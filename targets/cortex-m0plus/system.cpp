// SPDX-License-Identifier: Apache-2.0
// Clock tree, fatal-error path and the board's definition of the core's
// assertion hook (kestrel/assert.hpp). No stdio.
#include "system.hpp"

#include "board_config.hpp"
#include "kestrel/assert.hpp"
#include "registers.hpp"

namespace kestrel::m0plus {
namespace {

__attribute__((section(".noinit"))) AssertRecord g_last_assert;

// PLL_SYS: REFDIV 1 -> 12 MHz reference; VCO = 12 MHz * 125 = 1500 MHz
// (750..1600 MHz allowed); clk_sys = VCO / (6 * 2) = 125 MHz.
constexpr std::uint32_t kFbdiv = 125;
constexpr std::uint32_t kPostDiv1 = 6;
constexpr std::uint32_t kPostDiv2 = 2;
static_assert(kXoscHz * kFbdiv >= 750'000'000u && kXoscHz * kFbdiv <= 1'600'000'000u, "VCO out of range");
static_assert(kXoscHz * kFbdiv / (kPostDiv1 * kPostDiv2) == kCoreClockHz, "PLL settings do not give kCoreClockHz");
// XOSC start-up delay, units of 256 crystal cycles: about 1 ms.
constexpr std::uint32_t kXoscStartupDelay = (kXoscHz / 1000 + 255) / 256;

// Bound of every wait below: far above any lock or switch time at the ring
// oscillator's slowest (about 1.8 MHz: 1'000'000 polls are over 1 s).
constexpr std::uint32_t kSpins = 1'000'000;

struct ClockState {
  std::uint32_t core_hz;
  ClockFallback fallback;
};
// Before configure_clocks(): the ring oscillator the boot ROM left running.
constinit ClockState g_clock{kRoscNominalHz, ClockFallback::kNone};

[[nodiscard]] bool wait_for(regs::Address address, std::uint32_t mask, std::uint32_t value) {
  for (std::uint32_t spins = 0; spins < kSpins; ++spins) {
    if ((regs::reg(address) & mask) == value) return true;
  }
  return false;
}

/// clk_peri (UART0) from clk_sys, whatever clk_sys ended up on, and the record.
ClockFallback finish(std::uint32_t core_hz, ClockFallback why) {
  using namespace regs;
  reg(kClkPeriCtrl) = kClkPeriEnable;  // AUXSRC = 0: clk_sys
  g_clock = ClockState{core_hz, why};
  return why;
}

}  // namespace

bool wait_for_reset_done(std::uint32_t mask) { return wait_for(regs::kResetsResetDone, mask, mask); }

ClockFallback configure_clocks() {
  using namespace regs;
  // IO and pads: without them UART0 cannot reach its pins and the board has
  // no link at all; no other clock or route can stand in, so this is the
  // one step that still asserts (reset; this SRAM image then returns to the
  // boot ROM, it does not start again by itself).
  reg(kResetsReset + kAliasClr) = kResetIoBank0 | kResetPadsBank0;
  if (!wait_for_reset_done(kResetIoBank0 | kResetPadsBank0)) {
    kestrel_assert_failed(__FILE__, __LINE__, "IO/pads stuck in reset");
  }

  // Crystal oscillator. If it never becomes stable, clk_ref and clk_sys
  // stay on the ring oscillator (reset state): the board runs, but its
  // rate is only nominal, so the UART baud is approximate (kRoscNominalHz).
  reg(kXoscCtrl) = kXoscFreqRange1To15MHz;
  reg(kXoscStartup) = kXoscStartupDelay;
  reg(kXoscCtrl + kAliasSet) = kXoscEnable;
  if (!wait_for(kXoscStatus, kXoscStable, kXoscStable)) return finish(kRoscNominalHz, ClockFallback::kXoscNotStable);

  // clk_ref from the crystal first; clk_sys is on clk_ref (reset state), so
  // from here a failure of the PLL leaves an exact 12 MHz.
  reg(kClkRefCtrl) = kClkRefSrcXosc;
  if (!wait_for(kClkRefSelected, 1u << kClkRefSrcXosc, 1u << kClkRefSrcXosc)) {
    reg(kClkRefCtrl) = kClkRefSrcRosc;
    return finish(kRoscNominalHz, ClockFallback::kClkRefNotXosc);
  }
  reg(kClkSysCtrl + kAliasClr) = kClkSysSrcAux;
  if (!wait_for(kClkSysSelected, 1u << 0, 1u << 0)) return finish(kXoscHz, ClockFallback::kClkSysNotOnRef);

  // PLL_SYS from reset: dividers, power up VCO, wait for lock, post dividers.
  reg(kResetsReset + kAliasSet) = kResetPllSys;
  reg(kResetsReset + kAliasClr) = kResetPllSys;
  if (!wait_for_reset_done(kResetPllSys)) return finish(kXoscHz, ClockFallback::kPllNoLock);
  reg(kPllCs) = 1;  // REFDIV
  reg(kPllFbdivInt) = kFbdiv;
  reg(kPllPwr + kAliasClr) = kPllPwrPd | kPllPwrVcoPd;
  if (!wait_for(kPllCs, kPllCsLock, kPllCsLock)) {
    reg(kPllPwr + kAliasSet) = kPllPwrPd | kPllPwrVcoPd;
    return finish(kXoscHz, ClockFallback::kPllNoLock);
  }
  reg(kPllPrim) = (kPostDiv1 << 16) | (kPostDiv2 << 12);
  reg(kPllPwr + kAliasClr) = kPllPwrPostDivPd;

  // clk_sys: select PLL_SYS on the aux mux, then onto the aux mux (the
  // glitchless switch of datasheet 2.15.3.2); back on clk_ref if it fails.
  reg(kClkSysCtrl) = (0u << 5) | kClkSysSrcAux;  // AUXSRC = PLL_SYS
  if (!wait_for(kClkSysSelected, 1u << 1, 1u << 1)) {
    reg(kClkSysCtrl + kAliasClr) = kClkSysSrcAux;
    return finish(kXoscHz, ClockFallback::kPllNotSelected);
  }
  return finish(kCoreClockHz, ClockFallback::kNone);
}

ClockFallback clock_fallback() { return g_clock.fallback; }
std::uint32_t core_clock_hz() { return g_clock.core_hz; }

void halt_and_reset() {
  using namespace regs;
  if ((reg(kDhcsr) & kDhcsrCDebugEn) != 0) {
    __asm volatile("bkpt #0");
  }
  __asm volatile("dsb" ::: "memory");
  reg(kScbAircr) = kAircrVectKey | kAircrSysResetReq;
  __asm volatile("dsb" ::: "memory");
  // Not a wait on the hardware that may never end: the core itself has just
  // requested the system reset (AIRCR.SYSRESETREQ), which takes effect
  // within a few cycles; the loop only keeps it from running on meanwhile.
  for (;;) {
    __asm volatile("nop");
  }
}

AssertRecord& last_assert() { return g_last_assert; }

}  // namespace kestrel::m0plus

extern "C" [[noreturn]] void kestrel_assert_failed(const char* file, int line, const char* expr) {
  kestrel::m0plus::AssertRecord& r = kestrel::m0plus::g_last_assert;
  r.file = file;
  r.expr = expr;
  r.line = line;
  r.magic = kestrel::m0plus::kAssertRecordMagic;
  kestrel::m0plus::halt_and_reset();
}
