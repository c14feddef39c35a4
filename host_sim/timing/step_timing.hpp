// SPDX-License-Identifier: Apache-2.0
// Per-step latency of the real-time loop (docs/tracking.md): the Runner times
// adapter conversion + Tracker::step of every frame with the board's cycle
// clock (SteadyClock on the host: 1 cycle = 1 ns). Percentiles use the
// nearest-rank definition (the value at rank ceil(p n) of the sorted
// sample), so every figure is a latency that actually occurred.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

namespace kestrel::sim {

struct StepTiming {
  std::size_t steps = 0;      ///< Timed steps.
  std::uint64_t min_ns = 0;
  std::uint64_t median_ns = 0;
  std::uint64_t p99_ns = 0;
  std::uint64_t max_ns = 0;
  double mean_ns = 0.0;
  std::uint64_t budget_ns = 0;  ///< Overrun threshold.
  std::size_t overruns = 0;     ///< Steps over budget_ns.
};

/// Summarise step times (any order). All zero for an empty sample.
StepTiming summarise_step_times(std::span<const std::uint64_t> step_ns, std::uint64_t budget_ns);

}  // namespace kestrel::sim
