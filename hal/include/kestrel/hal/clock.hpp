// SPDX-License-Identifier: Apache-2.0
// CycleClock: a free-running cycle (or tick) counter for per-step timing.
// DWT CYCCNT on Cortex-M3/4/7, SysTick on M0+, rdcycle on RISC-V,
// std::chrono::steady_clock (in ns) on the host. Only differences of
// now_cycles() are meaningful; 64 bits so a difference never wraps in a run.
#pragma once

#include <concepts>
#include <cstdint>

namespace kestrel::hal {

template <class C>
concept CycleClock = requires(C& clock) {
  { clock.now_cycles() } -> std::same_as<std::uint64_t>;
  { clock.cycles_per_second() } -> std::same_as<std::uint64_t>;
};

}  // namespace kestrel::hal
