// SPDX-License-Identifier: Apache-2.0
// Clock tree, fatal-error path and the board's definition of the core's
// assertion hook (kestrel/assert.hpp). No stdio: an assertion leaves its
// file, line and expression in a .noinit record and resets the core.
#include "system.hpp"

#include "board_config.hpp"
#include "kestrel/assert.hpp"
#include "registers.hpp"

namespace kestrel::m4f {
namespace {

// Not zeroed by Reset_Handler (section .noinit, see stm32f407.ld).
__attribute__((section(".noinit"))) AssertRecord g_last_assert;

// PLL: VCO in = 16 MHz / M = 1 MHz; VCO out = 1 MHz * N = 336 MHz;
// SYSCLK = VCO / P = 168 MHz; 48 MHz domain = VCO / Q = 48 MHz.
constexpr std::uint32_t kPllM = 16;
constexpr std::uint32_t kPllN = 336;
constexpr std::uint32_t kPllPBits = 0;  // P = 2
constexpr std::uint32_t kPllQ = 7;
static_assert(kHsiHz / kPllM * kPllN / 2 == kCoreClockHz, "PLL settings do not give kCoreClockHz");
// PLLCFGR bits that are reserved and must keep their reset value.
constexpr std::uint32_t kPllcfgrReserved = 0xF0BC8000u;

// The PLL locks within 200 us (datasheet); at 16 MHz this bound is > 5 ms.
// The same bound serves the clock switch, which takes a few cycles.
constexpr std::uint32_t kPllLockSpins = 100'000;

// Clock tree as configured now. Constant-initialised to the reset state
// (HSI, prescalers 1), which is also what a fallback leaves.
struct ClockState {
  std::uint32_t core_hz;
  std::uint32_t apb1_hz;
  ClockFallback fallback;
};
constinit ClockState g_clock{kHsiHz, kHsiHz, ClockFallback::kNone};

/// Poll until (register & mask) == value, at most kPllLockSpins times.
[[nodiscard]] bool wait_for(regs::Address address, std::uint32_t mask, std::uint32_t value) {
  for (std::uint32_t spins = 0; spins < kPllLockSpins; ++spins) {
    if ((regs::reg(address) & mask) == value) return true;
  }
  return false;
}

/// Stay on (or go back to) the HSI: system clock switch to HSI, PLL off,
/// AHB and APB prescalers 1 (16 MHz is within every bus limit). The flash
/// wait states are left as they are: 5 is correct at any HCLK up to
/// 168 MHz, only slower than the 0 the HSI would need. The switch to HSI is
/// not waited for: SW is what the clock logic follows, and the HSI (the
/// reset clock, never switched off here) is always ready.
ClockFallback fall_back_to_hsi(ClockFallback why) {
  using namespace regs;
  reg(kRccCfgr) = (reg(kRccCfgr) & ~(kRccCfgrSwMask | kRccCfgrHpreMask | kRccCfgrPpre1Mask | kRccCfgrPpre2Mask)) |
                  kRccCfgrSwHsi;
  reg(kRccCr) &= ~kRccCrPllOn;
  g_clock = ClockState{kHsiHz, kHsiHz, why};
  return why;
}

}  // namespace

ClockFallback configure_clocks() {
  using namespace regs;
  // Wait states before the clock goes up (RM0090 3.5.1). Voltage scale 1,
  // needed for 168 MHz, is the reset value of PWR_CR.VOS on the F407. A
  // FLASH_ACR that does not read back the latency (an emulator without the
  // flash interface) means 168 MHz would not be safe: stay on the HSI.
  reg(kFlashAcr) = kFlashAcrPrftEn | kFlashAcrIcEn | kFlashAcrDcEn | kFlashAcrLatency5;
  if ((reg(kFlashAcr) & kFlashAcrLatencyMask) != kFlashAcrLatency5) {
    return fall_back_to_hsi(ClockFallback::kFlashLatency);
  }

  reg(kRccPllcfgr) = (reg(kRccPllcfgr) & kPllcfgrReserved) | kPllM | (kPllN << 6) | (kPllPBits << 16) |
                     (kPllQ << 24);  // PLLSRC (bit 22) = 0: HSI
  reg(kRccCfgr) = kRccCfgrPpre1Div4 | kRccCfgrPpre2Div2;  // AHB /1; still running on HSI
  reg(kRccCr) |= kRccCrPllOn;
  if (!wait_for(kRccCr, kRccCrPllRdy, kRccCrPllRdy)) return fall_back_to_hsi(ClockFallback::kPllNoLock);
  reg(kRccCfgr) = (reg(kRccCfgr) & ~kRccCfgrSwMask) | kRccCfgrSwPll;
  if (!wait_for(kRccCfgr, kRccCfgrSwsMask, kRccCfgrSwsPll)) return fall_back_to_hsi(ClockFallback::kPllNotSelected);
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

}  // namespace kestrel::m4f

extern "C" [[noreturn]] void kestrel_assert_failed(const char* file, int line, const char* expr) {
  kestrel::m4f::AssertRecord& r = kestrel::m4f::g_last_assert;
  r.file = file;
  r.expr = expr;
  r.line = line;
  r.magic = kestrel::m4f::kAssertRecordMagic;
  kestrel::m4f::halt_and_reset();
}
