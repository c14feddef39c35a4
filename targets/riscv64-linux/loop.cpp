// SPDX-License-Identifier: Apache-2.0
// The board objects of the riscv64-linux board and one loop iteration (see
// loop.hpp). All large objects are namespace-scope statics, as on the
// microcontroller boards: the step runs on a stack that holds only its call
// chain, and nothing is allocated after start-up (nor before: the objects
// are constructed in place from .init_array).
#include "loop.hpp"

#include "board.hpp"

namespace kestrel::rv64 {
namespace {

Tracker g_tracker = make_radar_tracker<double, kMaxTracks, kMaxPlots>(RadarTrackerParams{});
Feed g_feed{};
Clock g_clock{};
Sink g_sink{};
std::uint64_t g_budget_cycles = 0;  // kStepBudgetNs in ticks of g_clock, set by loop_init

/// The runner, built on the first call (from loop_init, once the clock rate
/// and so the budget in ticks are known). A function-local static: with
/// -fno-threadsafe-statics its guard is one flag, no library call.
Runner& runner() {
  static Runner r{g_feed, g_clock, g_tracker, Adapter{}, g_sink, g_budget_cycles};
  return r;
}

}  // namespace

void loop_init(int in_fd, int out_fd, std::uint64_t clock_hz) {
  g_feed.attach(in_fd);
  g_sink.attach(out_fd);
  g_clock.set_rate(clock_hz);
  const std::uint64_t hz = g_clock.cycles_per_second();
  g_budget_cycles = hz / 1'000'000'000u * kStepBudgetNs + hz % 1'000'000'000u * kStepBudgetNs / 1'000'000'000u;
  (void)runner();
}

Status loop_poll_once() {
  const Status s = runner().poll_once();
  g_sink.flush();
  return s;
}

bool loop_input_ended() { return g_feed.ended(); }
const hal::RunnerStats& loop_stats() { return runner().stats(); }
std::uint64_t loop_clock_hz() { return g_clock.cycles_per_second(); }
const char* loop_clock_name() { return Clock::kName; }
std::uint64_t loop_budget_cycles() { return g_budget_cycles; }
std::uint32_t loop_read_errors() { return g_feed.read_errors(); }
std::uint32_t loop_write_errors() { return g_sink.write_errors(); }
std::uint32_t loop_dropped_reports() { return g_sink.dropped(); }

}  // namespace kestrel::rv64
