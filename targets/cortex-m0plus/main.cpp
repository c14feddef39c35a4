// SPDX-License-Identifier: Apache-2.0
// The Cortex-M0+ firmware's main (firmware_main, called by Reset_Handler in
// startup.cpp): clocks to 125 MHz, SysTick cycle clock and UART0, then the
// hal Runner forever (docs/tracking.md). All large objects are statics, as on
// the other boards; g_runner.stats() holds the same RunnerStats.
#include "board.hpp"

namespace {

using namespace kestrel::m0plus;

// The real-valued parameters become Q31.32 constants at compile time: the
// image converts nothing from double at run time.
constexpr kestrel::RadarTrackerParams kParams{};
constexpr kestrel::RadarTrackerConfig<Scalar> kConfig = kestrel::radar_tracker_config<Scalar>(kParams);
Tracker g_tracker = kestrel::make_radar_tracker<Scalar, kMaxTracks, kMaxPlots>(kParams, kConfig);
Feed g_feed{uart0_rx_ring()};
Clock g_clock{};
Sink g_sink{uart0_tx_ring()};
Runner g_runner{g_feed, g_clock, g_tracker, Adapter{}, g_sink, kStepBudgetCycles};

}  // namespace

namespace kestrel::m0plus {

[[noreturn]] void firmware_main() {
  // A clock step that does not complete leaves clk_sys on the crystal or
  // the ring oscillator (clock_fallback() says why); clock and UART take
  // the rate actually configured.
  (void)configure_clocks();
  g_clock.start(core_clock_hz());
  // Without UART0 there is neither feed nor sink: nothing to run.
  if (!uart0_start(core_clock_hz())) kestrel_assert_failed(__FILE__, __LINE__, "UART0 stuck in reset");
  for (;;) {
    (void)g_runner.poll_once();
  }
}

}  // namespace kestrel::m0plus
