// SPDX-License-Identifier: Apache-2.0
// CycleClock of the Cortex-M4F board: the DWT cycle counter at the core
// clock (targets/common/include/kestrel/board/dwt_cycle_clock.hpp, shared
// with the Cortex-M7 board), started with core_clock_hz() (168 MHz, or
// 16 MHz on the HSI fallback). CYCCNT wraps every 2^32 / 168 MHz = 25.6 s;
// now_cycles() extends it to 64 bits (see the shared header for when a wrap
// is seen).
#pragma once

#include "board_config.hpp"
#include "kestrel/board/dwt_cycle_clock.hpp"

namespace kestrel::m4f {

using DwtCycleClock = board::DwtCycleClock;

}  // namespace kestrel::m4f
