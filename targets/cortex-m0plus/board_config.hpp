// SPDX-License-Identifier: Apache-2.0
// Compile-time configuration of the Cortex-M0+ board (RP2040, e.g. the
// Raspberry Pi Pico): clocks, the UART link, buffer sizes, tracker
// capacities and the step budget.
//
// This is the float soft-float build, kept for comparison with the
// fixed-point scalar (docs/fixed-point.md): the same float EKF-CA
// tracker as the Cortex-M4F, every float operation a libgcc routine.
#pragma once

#include <cstddef>
#include <cstdint>

#include "kestrel/hal/frame_format.hpp"

namespace kestrel::m0plus {

/// Crystal of the Pico (XOSC) and the system clock configure_clocks() sets:
/// 12 MHz * 125 / (6 * 2) = 125 MHz through PLL_SYS (the Pico SDK default).
inline constexpr std::uint32_t kXoscHz = 12'000'000;
inline constexpr std::uint32_t kCoreClockHz = 125'000'000;
/// clk_peri (UART0's clock) = clk_sys; core_clock_hz() at run time.
inline constexpr std::uint32_t kPeriHz = kCoreClockHz;
/// Ring oscillator, the reset clock and the last fallback: nominal only,
/// it varies with process, voltage and temperature (datasheet 2.17).
inline constexpr std::uint32_t kRoscNominalHz = 6'500'000;

/// UART link to the sensor front end and the track consumer: UART0 on GPIO0
/// (TX) / GPIO1 (RX), 8N1, no flow control.
inline constexpr std::uint32_t kUartBaud = 115'200;

/// Receive and transmit rings and the frame assembler, as on the M4F board.
inline constexpr std::size_t kRxRingBytes = 1024;
inline constexpr std::size_t kTxRingBytes = 1024;
inline constexpr std::size_t kAssemblerBytes = hal::wire::kMaxFrameBytes;

/// Tracker capacities: the M4F board's, so the images differ only in the core.
inline constexpr std::size_t kMaxTracks = 8;
inline constexpr std::size_t kMaxPlots = 32;

/// A convert+step longer than this counts as an overrun: 50 ms (10 % of
/// the 0.5 s frame interval of docs/scenarios.md's radar scenarios; soft float
/// on a 125 MHz M0+ is an order of magnitude slower than the M4F's FPU).
inline constexpr std::uint64_t kStepBudgetCycles = kCoreClockHz / 20;

}  // namespace kestrel::m0plus
