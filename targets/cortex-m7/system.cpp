// SPDX-License-Identifier: Apache-2.0
// Caches, power and clock tree, fatal-error path and the board's definition
// of the core's assertion hook (kestrel/assert.hpp). No stdio: an assertion
// leaves its file, line and expression in a .noinit record and resets.
#include "system.hpp"

#include "board_config.hpp"
#include "kestrel/assert.hpp"
#include "registers.hpp"

namespace kestrel::m7 {
namespace {

// Not zeroed by Reset_Handler (section .noinit, see stm32h743.ld).
__attribute__((section(".noinit"))) AssertRecord g_last_assert;

// PLL1 from HSI (64 MHz at reset, HSIDIV = 1): ref = 64 / M = 16 MHz (input
// range 8-16 MHz), VCO = ref * N = 800 MHz (wide range 192-960 MHz),
// sys_ck = VCO / P = 400 MHz; Q and R = VCO / 4 = 200 MHz (pll1_q_ck is the
// default SDMMC/SPI kernel clock, which must stay <= 200 MHz).
constexpr std::uint32_t kPllM = 4;
constexpr std::uint32_t kPllN = 50;
constexpr std::uint32_t kPllP = 2;
constexpr std::uint32_t kPllQ = 4;
constexpr std::uint32_t kPllR = 4;
static_assert(kHsiHz / kPllM >= 8'000'000 && kHsiHz / kPllM <= 16'000'000, "PLL1 input out of its 8-16 MHz range");
static_assert(kHsiHz / kPllM * kPllN >= 192'000'000u && kHsiHz / kPllM * kPllN <= 960'000'000u,
              "PLL1 VCO out of the wide range");
static_assert(kHsiHz / kPllM * kPllN / kPllP == kCoreClockHz, "PLL settings do not give kCoreClockHz");

// Flash read latency for hclk = 200 MHz at VOS1: RM0433 asks for 2 wait
// states (WRHIGHFREQ = 2) from 185 to 210 MHz; 4 is what ST's own 400 MHz
// examples program, kept here because this image cannot be tried on a board
// from CI. The L1 instruction cache hides the difference on the hot loop.
constexpr std::uint32_t kFlashLatency = 4;
constexpr std::uint32_t kFlashWrHighFreq = 2u << 4;

// Upper bound of every busy wait below (regulator, PLL lock, switch): far
// above their datasheet times (PLL lock < 150 us) at 64 MHz.
constexpr std::uint32_t kSpins = 1'000'000;

// Clock tree as configured now: constant-initialised to the reset state
// (HSI 64 MHz, every prescaler 1), which is also what a fallback leaves.
struct ClockState {
  std::uint32_t core_hz;
  std::uint32_t apb1_hz;
  ClockFallback fallback;
};
constinit ClockState g_clock{kHsiHz, kHsiHz, ClockFallback::kNone};

/// Poll until (register & mask) == value, at most kSpins times.
[[nodiscard]] bool wait_for(regs::Address address, std::uint32_t mask, std::uint32_t value) {
  for (std::uint32_t spins = 0; spins < kSpins; ++spins) {
    if ((regs::reg(address) & mask) == value) return true;
  }
  return false;
}

/// Stay on (or go back to) the HSI at its reset settings: system clock
/// switch to HSI, PLL1 off, every bus prescaler back to its reset value 1
/// (the state the part boots in, valid at any voltage scale). Supply,
/// voltage scale and flash wait states are left as they are: each is valid
/// for 64 MHz whether or not its step completed (the reset latency, 7 wait
/// states, is the slowest). The switch to HSI, the reset clock, which is
/// never switched off here, is not waited for.
ClockFallback fall_back_to_hsi(ClockFallback why) {
  using namespace regs;
  reg(kRccCfgr) = (reg(kRccCfgr) & ~kRccCfgrSwMask) | kRccCfgrSwHsi;
  reg(kRccCr) &= ~kRccCrPll1On;
  reg(kRccD1cfgr) = 0;
  reg(kRccD2cfgr) = 0;
  reg(kRccD3cfgr) = 0;
  g_clock = ClockState{kHsiHz, kHsiHz, why};
  return why;
}

}  // namespace

void enable_caches() {
  using namespace regs;
  // Instruction cache: invalidate all, then enable.
  __asm volatile("dsb\n\tisb" ::: "memory");
  reg(kScbIciallu) = 0;
  __asm volatile("dsb\n\tisb" ::: "memory");
  reg(kScbCcr) |= kCcrIc;
  __asm volatile("dsb\n\tisb" ::: "memory");

  // Data cache: its contents are undefined after reset, so invalidate every
  // line by set and way (geometry from CCSIDR of the L1 data cache), then
  // enable. Line length 32 bytes -> set index at bit 5; 4 ways -> way at bit 30.
  reg(kScbCsselr) = 0;
  __asm volatile("dsb" ::: "memory");
  const std::uint32_t ccsidr = reg(kScbCcsidr);
  const std::uint32_t sets = ((ccsidr >> 13) & 0x7FFFu) + 1u;
  const std::uint32_t ways = ((ccsidr >> 3) & 0x3FFu) + 1u;
  for (std::uint32_t set = 0; set < sets; ++set) {
    for (std::uint32_t way = 0; way < ways; ++way) {
      reg(kScbDcisw) = ((set << 5) & 0x3FE0u) | ((way << 30) & 0xC0000000u);
    }
  }
  __asm volatile("dsb" ::: "memory");
  reg(kScbCcr) |= kCcrDc;
  __asm volatile("dsb\n\tisb" ::: "memory");
}

ClockFallback configure_clocks() {
  using namespace regs;
  // 1. Supply: the core from the LDO (the NUCLEO-H743ZI's wiring). CR3 can
  //    be written once after reset; then wait until the regulator follows.
  reg(kPwrCr3) = (reg(kPwrCr3) & ~(kPwrCr3Bypass | kPwrCr3LdoEn | kPwrCr3ScuEn)) | kPwrCr3LdoEn;
  if (!wait_for(kPwrCsr1, kPwrCsr1ActVosRdy, kPwrCsr1ActVosRdy)) {
    return fall_back_to_hsi(ClockFallback::kSupplyNotReady);
  }

  // 2. Voltage scale 1 (needed above 300 MHz).
  reg(kPwrD3cr) = (reg(kPwrD3cr) & ~kPwrD3crVosMask) | kPwrD3crVos1;
  if (!wait_for(kPwrD3cr, kPwrD3crVosRdy, kPwrD3crVosRdy)) return fall_back_to_hsi(ClockFallback::kVoltageScale);

  // 3. Flash wait states before the clock goes up.
  reg(kFlashAcr) = (reg(kFlashAcr) & ~(kFlashAcrLatencyMask | kFlashAcrWrHighFreqMask)) | kFlashLatency |
                   kFlashWrHighFreq;
  if ((reg(kFlashAcr) & kFlashAcrLatencyMask) != kFlashLatency) {
    return fall_back_to_hsi(ClockFallback::kFlashLatency);
  }

  // 4. PLL1: source HSI, M; input range, wide VCO, integer mode, P output on.
  reg(kRccPllckselr) = (reg(kRccPllckselr) & ~(0x3u | (0x3Fu << 4))) | (kPllM << 4);  // PLLSRC = 0: HSI
  reg(kRccPllcfgr) =
      (reg(kRccPllcfgr) & ~(kRccPllcfgrPll1FracEn | kRccPllcfgrPll1VcoSel | kRccPllcfgrPll1RgeMask)) |
      kRccPllcfgrPll1Rge8To16 | kRccPllcfgrDivP1En;
  reg(kRccPll1divr) = (kPllN - 1u) | ((kPllP - 1u) << 9) | ((kPllQ - 1u) << 16) | ((kPllR - 1u) << 24);
  reg(kRccCr) |= kRccCrPll1On;
  if (!wait_for(kRccCr, kRccCrPll1Rdy, kRccCrPll1Rdy)) return fall_back_to_hsi(ClockFallback::kPllNoLock);

  // 5. Bus prescalers before the switch, so hclk never exceeds 200 MHz.
  reg(kRccD1cfgr) = kRccD1cfgrHpreDiv2 | kRccD1cfgrD1ppreDiv2;  // D1CPRE = /1
  reg(kRccD2cfgr) = kRccD2cfgrD2ppre1Div2 | kRccD2cfgrD2ppre2Div2;
  reg(kRccD3cfgr) = kRccD3cfgrD3ppreDiv2;

  // 6. System clock switch to PLL1.
  reg(kRccCfgr) = (reg(kRccCfgr) & ~kRccCfgrSwMask) | kRccCfgrSwPll1;
  if (!wait_for(kRccCfgr, kRccCfgrSwsMask, kRccCfgrSwsPll1)) {
    return fall_back_to_hsi(ClockFallback::kPllNotSelected);
  }
  g_clock = ClockState{kCoreClockHz, kApb1Hz, ClockFallback::kNone};
  return ClockFallback::kNone;
}

ClockFallback clock_fallback() { return g_clock.fallback; }
std::uint32_t core_clock_hz() { return g_clock.core_hz; }
std::uint32_t apb1_clock_hz() { return g_clock.apb1_hz; }

void halt_and_reset() {
  using namespace regs;
  if ((reg(kDhcsr) & kDhcsrCDebugEn) != 0) {
    __asm volatile("bkpt #0");  // without a debugger BKPT would escalate to HardFault
  }
  __asm volatile("dsb" ::: "memory");
  reg(kScbAircr) = kAircrVectKey | (reg(kScbAircr) & (0x7u << 8)) | kAircrSysResetReq;  // keep PRIGROUP
  __asm volatile("dsb" ::: "memory");
  // Not a wait on the hardware that may never end: the core itself has just
  // requested the system reset (AIRCR.SYSRESETREQ), which takes effect
  // within a few cycles; the loop only keeps it from running on meanwhile.
  for (;;) {
    __asm volatile("nop");
  }
}

AssertRecord& last_assert() { return g_last_assert; }

}  // namespace kestrel::m7

extern "C" [[noreturn]] void kestrel_assert_failed(const char* file, int line, const char* expr) {
  kestrel::m7::AssertRecord& r = kestrel::m7::g_last_assert;
  r.file = file;
  r.expr = expr;
  r.line = line;
  r.magic = kestrel::m7::kAssertRecordMagic;
  kestrel::m7::halt_and_reset();
}
