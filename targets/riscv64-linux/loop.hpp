// SPDX-License-Identifier: Apache-2.0
// The tracker's code path on the riscv64-linux board: the board objects
// (tracker, feed, sink, clock, runner) and one iteration of the board loop.
// loop.cpp is compiled once, under the firmware rules, and the same object
// is linked into both the process image (kestrel-rv64, with main.cpp's
// Linux shell) and the heap-guard image (kestrel-rv64-guard.elf, with no
// start-up files and every allocator wrapped to an undefined symbol), so the
// guard's verdict is about the very code the process runs (docs/porting.md,
// "riscv64-linux: what the no-heap proof covers").
#pragma once

#include <cstdint>

#include "kestrel/hal/runner.hpp"
#include "kestrel/status.hpp"

namespace kestrel::rv64 {

/// Attach the input and output descriptors and the clock rate (ticks per
/// second; ignored by the monotonic clock), and start the statistics.
/// Call once before the first loop_poll_once().
void loop_init(int in_fd, int out_fd, std::uint64_t clock_hz);

/// One iteration of the board loop: Runner::poll_once() (feed, adapter,
/// step, publish), then the sink's flush.
/// @return Runner::poll_once()'s status (kNoData: no frame was ready).
[[nodiscard]] Status loop_poll_once();

/// The input ended (end of file) and every byte of it was decoded.
[[nodiscard]] bool loop_input_ended();

/// The runner's cycle and status accounting (the same RunnerStats as on the
/// microcontroller boards), the clock's rate and name, the step budget in
/// clock ticks, and the I/O error counters.
const hal::RunnerStats& loop_stats();
std::uint64_t loop_clock_hz();
const char* loop_clock_name();
std::uint64_t loop_budget_cycles();
std::uint32_t loop_read_errors();
std::uint32_t loop_write_errors();
std::uint32_t loop_dropped_reports();

}  // namespace kestrel::rv64
