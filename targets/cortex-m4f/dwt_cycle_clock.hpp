// CycleClock on the Cortex-M4 Data Watchpoint and Trace unit: CYCCNT counts
// core clock cycles in 32 bits (it wraps every 2^32 / 168 MHz = 25.6 s), and
// now_cycles() extends it to 64 bits by counting the wraps it observes (SPEC
// section 8: the board's cycle counter feeds the runner's step statistics).
//
// A wrap is seen only if now_cycles() runs at least once per 25.6 s. The
// runner reads the clock twice per frame around step(), so a quiet link may
// let the 64-bit value lag behind real time by whole wraps; it stays
// monotonic, and the difference across one step (what the statistics use)
// is exact for any step shorter than 25.6 s. Main-loop use only: the wrap
// bookkeeping is not interrupt-safe.
#pragma once

#include <cstdint>

#include "board_config.hpp"
#include "registers.hpp"

namespace kestrel::m4f {

class DwtCycleClock {
 public:
  /// Enable the trace block (DEMCR.TRCENA), reset CYCCNT and start it.
  /// Call once at start-up, before the first now_cycles().
  void start() {
    regs::reg(regs::kDemcr) |= regs::kDemcrTrcEna;
    regs::reg(regs::kDwtLar) = regs::kDwtLarUnlock;
    regs::reg(regs::kDwtCyccnt) = 0;
    regs::reg(regs::kDwtCtrl) |= regs::kDwtCtrlCycCntEna;
    last_low_ = 0;
    wraps_ = 0;
  }

  /// Cycles since start(), 64 bits (see the header note on wraps).
  [[nodiscard]] std::uint64_t now_cycles() {
    const std::uint32_t low = regs::reg(regs::kDwtCyccnt);
    if (low < last_low_) ++wraps_;
    last_low_ = low;
    return (static_cast<std::uint64_t>(wraps_) << 32) | low;
  }

  /// The core clock the board configures (board_config.hpp).
  [[nodiscard]] std::uint64_t cycles_per_second() const { return kCoreClockHz; }

 private:
  std::uint32_t last_low_ = 0;
  std::uint32_t wraps_ = 0;
};

}  // namespace kestrel::m4f
