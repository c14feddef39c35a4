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

constexpr std::uint32_t kSpins = 1'000'000;  // far above any lock time at the ring oscillator's ~6 MHz

void wait_for(regs::Address address, std::uint32_t mask, std::uint32_t value, const char* what) {
  std::uint32_t spins = 0;
  while ((regs::reg(address) & mask) != value) {
    if (++spins == kSpins) kestrel_assert_failed(__FILE__, __LINE__, what);
  }
}

void unreset(std::uint32_t mask) {
  using namespace regs;
  reg(kResetsReset + kAliasClr) = mask;
  wait_for(kResetsResetDone, mask, mask, "peripheral stuck in reset");
}

}  // namespace

void configure_clocks() {
  using namespace regs;
  unreset(kResetIoBank0 | kResetPadsBank0);

  // Crystal oscillator.
  reg(kXoscCtrl) = kXoscFreqRange1To15MHz;
  reg(kXoscStartup) = kXoscStartupDelay;
  reg(kXoscCtrl + kAliasSet) = kXoscEnable;
  wait_for(kXoscStatus, kXoscStable, kXoscStable, "XOSC not stable");

  // PLL_SYS from reset: dividers, power up VCO, wait for lock, post dividers.
  reg(kResetsReset + kAliasSet) = kResetPllSys;
  unreset(kResetPllSys);
  reg(kPllCs) = 1;  // REFDIV
  reg(kPllFbdivInt) = kFbdiv;
  reg(kPllPwr + kAliasClr) = kPllPwrPd | kPllPwrVcoPd;
  wait_for(kPllCs, kPllCsLock, kPllCsLock, "PLL_SYS did not lock");
  reg(kPllPrim) = (kPostDiv1 << 16) | (kPostDiv2 << 12);
  reg(kPllPwr + kAliasClr) = kPllPwrPostDivPd;

  // clk_ref from the crystal; clk_sys: off the aux mux, select PLL_SYS on
  // it, back onto the aux mux (the glitchless switch of datasheet 2.15.3.2).
  reg(kClkRefCtrl) = kClkRefSrcXosc;
  wait_for(kClkRefSelected, 1u << kClkRefSrcXosc, 1u << kClkRefSrcXosc, "clk_ref not on XOSC");
  reg(kClkSysCtrl + kAliasClr) = kClkSysSrcAux;
  wait_for(kClkSysSelected, 1u << 0, 1u << 0, "clk_sys not on clk_ref");
  reg(kClkSysCtrl) = (0u << 5) | kClkSysSrcAux;  // AUXSRC = PLL_SYS
  wait_for(kClkSysSelected, 1u << 1, 1u << 1, "clk_sys not on PLL_SYS");

  // clk_peri (UART) from clk_sys.
  reg(kClkPeriCtrl) = kClkPeriEnable;  // AUXSRC = 0: clk_sys
}

void halt_and_reset() {
  using namespace regs;
  if ((reg(kDhcsr) & kDhcsrCDebugEn) != 0) {
    __asm volatile("bkpt #0");
  }
  __asm volatile("dsb" ::: "memory");
  reg(kScbAircr) = kAircrVectKey | kAircrSysResetReq;
  __asm volatile("dsb" ::: "memory");
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
