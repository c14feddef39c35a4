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
static_assert(16'000'000 / kPllM * kPllN / 2 == kCoreClockHz, "PLL settings do not give kCoreClockHz");
// PLLCFGR bits that are reserved and must keep their reset value.
constexpr std::uint32_t kPllcfgrReserved = 0xF0BC8000u;

// The PLL locks within 200 us (datasheet); at 16 MHz this bound is > 5 ms.
constexpr std::uint32_t kPllLockSpins = 100'000;

}  // namespace

void configure_clocks() {
  using namespace regs;
  // Wait states before the clock goes up (RM0090 3.5.1). Voltage scale 1,
  // needed for 168 MHz, is the reset value of PWR_CR.VOS on the F407.
  reg(kFlashAcr) = kFlashAcrPrftEn | kFlashAcrIcEn | kFlashAcrDcEn | kFlashAcrLatency5;
  if ((reg(kFlashAcr) & kFlashAcrLatencyMask) != kFlashAcrLatency5) {
    kestrel_assert_failed(__FILE__, __LINE__, "flash latency not accepted");
  }

  reg(kRccPllcfgr) = (reg(kRccPllcfgr) & kPllcfgrReserved) | kPllM | (kPllN << 6) | (kPllPBits << 16) |
                     (kPllQ << 24);  // PLLSRC (bit 22) = 0: HSI
  reg(kRccCfgr) = kRccCfgrPpre1Div4 | kRccCfgrPpre2Div2;  // AHB /1; still running on HSI
  reg(kRccCr) |= kRccCrPllOn;
  std::uint32_t spins = 0;
  while ((reg(kRccCr) & kRccCrPllRdy) == 0) {
    if (++spins == kPllLockSpins) kestrel_assert_failed(__FILE__, __LINE__, "PLL did not lock");
  }
  reg(kRccCfgr) = (reg(kRccCfgr) & ~kRccCfgrSwMask) | kRccCfgrSwPll;
  spins = 0;
  while ((reg(kRccCfgr) & kRccCfgrSwsMask) != kRccCfgrSwsPll) {
    if (++spins == kPllLockSpins) kestrel_assert_failed(__FILE__, __LINE__, "PLL not selected");
  }
}

void halt_and_reset() {
  using namespace regs;
  if ((reg(kDhcsr) & kDhcsrCDebugEn) != 0) {
    __asm volatile("bkpt #0");  // without a debugger BKPT would escalate to HardFault
  }
  __asm volatile("dsb" ::: "memory");
  reg(kScbAircr) = kAircrVectKey | (reg(kScbAircr) & (0x7u << 8)) | kAircrSysResetReq;  // keep PRIGROUP
  __asm volatile("dsb" ::: "memory");
  for (;;) {
    __asm volatile("nop");  // until the reset takes effect
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
