// SPDX-License-Identifier: Apache-2.0
// The Cortex-M7 firmware's main (firmware_main, called by Reset_Handler in
// startup.cpp): caches on, clocks to 400 MHz, cycle counter and UART, then
// the hal Runner forever, one poll_once() per iteration (docs/tracking.md).
// All large objects (tracker, feed with its frame assembler, runner with its
// frame and scan) are namespace-scope statics in DTCM, so the stack holds
// only the call chain of one step; their constructors run from .init_array
// in Reset_Handler. The runner's statistics (min/max/last cycles, overruns
// against kStepBudgetCycles, per-status counts) are in g_runner.stats(),
// readable with a debugger: the same RunnerStats every board keeps.
#include "board.hpp"

namespace {

using namespace kestrel::m7;

// The sensor chain is board.hpp's (radar, or PCL in kestrel-m7-pcl.elf).
Tracker g_tracker = make_tracker();
Feed g_feed{usart3_rx_ring()};
Clock g_clock{};
Sink g_sink{usart3_tx_ring()};
Runner g_runner{g_feed, g_clock, g_tracker, make_adapter(g_tracker), g_sink, kStepBudgetCycles};

}  // namespace

namespace kestrel::m7 {

[[noreturn]] void firmware_main() {
  enable_caches();
  // A clock tree that cannot reach 400 MHz leaves the board on the 64 MHz
  // HSI (clock_fallback() says why); clock and UART take the actual rates.
  (void)configure_clocks();
  g_clock.start(core_clock_hz());
  usart3_start(apb1_clock_hz());
  for (;;) {
    // Every outcome is already counted in g_runner.stats().by_status.
    (void)g_runner.poll_once();
  }
}

}  // namespace kestrel::m7
