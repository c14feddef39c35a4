// SPDX-License-Identifier: Apache-2.0
// The Cortex-M4F firmware's main (firmware_main, called by Reset_Handler in
// startup.cpp): bring up clocks (or stay on the HSI, see system.hpp), cycle counter and UART, then run the hal
// Runner forever, one poll_once() per iteration (docs/tracking.md). All large objects (tracker, feed with its frame assembler,
// runner with its frame and scan) are namespace-scope statics, so the stack
// holds only the call chain of one step; their constructors run from
// .init_array in Reset_Handler. The runner's statistics (min/max/last
// cycles, overruns against kStepBudgetCycles, per-status counts) are in
// g_runner.stats(), readable with a debugger.
#include "board.hpp"

namespace {

using namespace kestrel::m4f;

Tracker g_tracker = kestrel::make_radar_tracker<float, kMaxTracks, kMaxPlots, TrackFilter>(kestrel::RadarTrackerParams{});
Feed g_feed{usart2_rx_ring()};
Clock g_clock{};
Sink g_sink{usart2_tx_ring()};
Runner g_runner{g_feed, g_clock, g_tracker, Adapter{}, g_sink, kStepBudgetCycles};

}  // namespace

namespace kestrel::m4f {

[[noreturn]] void firmware_main() {
  // A clock tree that cannot reach 168 MHz leaves the board on the 16 MHz
  // HSI (clock_fallback() says why); the cycle clock and the UART divisor
  // take the clock actually configured, so the link keeps its baud rate.
  (void)configure_clocks();
  g_clock.start(core_clock_hz());
  usart2_start(apb1_clock_hz());
  for (;;) {
    // Every outcome is already counted in g_runner.stats().by_status.
    (void)g_runner.poll_once();
    usart2_poll_tx();
  }
}

}  // namespace kestrel::m4f
