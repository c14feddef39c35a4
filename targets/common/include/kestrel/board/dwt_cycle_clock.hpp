// SPDX-License-Identifier: Apache-2.0
// CycleClock on the ARMv7-M Data Watchpoint and Trace unit (Cortex-M3/M4/M7):
// CYCCNT counts core clock cycles in 32 bits and now_cycles() extends it to
// 64 bits by counting the wraps it observes, so it must run at least once
// per 2^32 cycles (25.6 s at 168 MHz) to see every wrap. Across a quiet link
// the 64-bit value may lag real time by whole wraps but stays monotonic, and
// the difference across one step (what the runner's statistics use) is exact
// for any step shorter than 2^32 cycles. Main-loop use only: the wrap
// bookkeeping is not interrupt-safe. Cortex-M0/M0+ have no CYCCNT.
// Registers: ARMv7-M Architecture Reference Manual (DDI 0403E) C1.6.5 DEMCR,
// C1.8.7 DWT_CTRL / DWT_CYCCNT; the CoreSight lock (DWT_LAR) must be
// unlocked on some Cortex-M7 parts (STM32F7/H7) and is harmless elsewhere.
#pragma once

#include <cstdint>

namespace kestrel::board {

class DwtCycleClock {
 public:
  /// Enable the trace block (DEMCR.TRCENA), reset CYCCNT and start it.
  /// Call once at start-up, after the clock tree is configured and before
  /// the first now_cycles().
  /// @param core_clock_hz the core clock the board actually runs at (which
  ///        may be a fallback clock rather than the one it aimed for).
  void start(std::uint32_t core_clock_hz) {
    core_clock_hz_ = core_clock_hz;
    reg(kDemcr) |= kDemcrTrcEna;
    reg(kDwtLar) = kDwtLarUnlock;
    reg(kDwtCyccnt) = 0;
    reg(kDwtCtrl) |= kDwtCtrlCycCntEna;
    last_low_ = 0;
    wraps_ = 0;
  }

  /// Cycles since start(), 64 bits (see the header note on wraps).
  [[nodiscard]] std::uint64_t now_cycles() {
    const std::uint32_t low = reg(kDwtCyccnt);
    if (low < last_low_) ++wraps_;
    last_low_ = low;
    return (static_cast<std::uint64_t>(wraps_) << 32) | low;
  }

  /// The core clock given to start().
  [[nodiscard]] std::uint64_t cycles_per_second() const { return core_clock_hz_; }

 private:
  static constexpr std::uintptr_t kDemcr = 0xE000EDFC;      ///< Debug exception and monitor control.
  static constexpr std::uint32_t kDemcrTrcEna = 1u << 24;   ///< Enable DWT and ITM.
  static constexpr std::uintptr_t kDwtCtrl = 0xE0001000;    ///< DWT control.
  static constexpr std::uint32_t kDwtCtrlCycCntEna = 1u << 0;
  static constexpr std::uintptr_t kDwtCyccnt = 0xE0001004;  ///< Cycle counter, 32 bits, wraps.
  static constexpr std::uintptr_t kDwtLar = 0xE0001FB0;     ///< CoreSight lock access.
  static constexpr std::uint32_t kDwtLarUnlock = 0xC5ACCE55u;

  static volatile std::uint32_t& reg(std::uintptr_t address) {
    return *reinterpret_cast<volatile std::uint32_t*>(address);
  }

  std::uint32_t core_clock_hz_ = 0;
  std::uint32_t last_low_ = 0;
  std::uint32_t wraps_ = 0;
};

}  // namespace kestrel::board
