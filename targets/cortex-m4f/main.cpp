// SPDX-License-Identifier: Apache-2.0
// The Cortex-M4F firmware's main (firmware_main, called by Reset_Handler in
// startup.cpp): bring up clocks, cycle counter and UART, then run the hal
// Runner forever, one poll_once() per iteration (SPEC section 8). All large objects (tracker, feed with its frame assembler,
// runner with its frame and scan) are namespace-scope statics, so the stack
// holds only the call chain of one step; their constructors run from
// .init_array in Reset_Handler. The runner's statistics (min/max/last
// cycles, overruns against kStepBudgetCycles, per-status counts) are in
// g_runner.stats(), readable with a debugger.
#include "board.hpp"

namespace {

using namespace kestrel::m4f;

Tracker g_tracker = kestrel::make_radar_tracker<float, kMaxTracks, kMaxPlots>(kestrel::RadarTrackerParams{});
Feed g_feed{usart2_rx_ring()};
Clock g_clock{};
Sink g_sink{usart2_tx_ring()};
Runner g_runner{g_feed, g_clock, g_tracker, Adapter{}, g_sink, kStepBudgetCycles};

}  // namespace

namespace kestrel::m4f {

[[noreturn]] void firmware_main() {
  configure_clocks();
  g_clock.start();
  usart2_start();
  for (;;) {
    // Every outcome is already counted in g_runner.stats().by_status.
    (void)g_runner.poll_once();
  }
}

}  // namespace kestrel::m4f
