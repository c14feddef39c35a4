// SPDX-License-Identifier: Apache-2.0
// Compile-time configuration of the Cortex-M4F board (STM32F407): clocks,
// the UART link, buffer sizes, tracker capacities and the step budget. Every
// number a reader might want to change for another F4 board is here; the
// drivers only read these constants.
#pragma once

#include <cstddef>
#include <cstdint>

#include "kestrel/hal/frame_format.hpp"

namespace kestrel::m4f {

/// Internal RC oscillator: the reset clock, and the clock the board stays on
/// when configure_clocks() cannot bring the PLL up (system.hpp).
inline constexpr std::uint32_t kHsiHz = 16'000'000;
/// Core clock (HCLK) configure_clocks() aims for: HSI 16 MHz / 16 * 336 / 2.
/// What the board actually runs at is core_clock_hz() (system.hpp).
inline constexpr std::uint32_t kCoreClockHz = 168'000'000;
/// APB1 (USART2's bus) = HCLK / 4 on the PLL; apb1_clock_hz() at run time.
inline constexpr std::uint32_t kApb1Hz = kCoreClockHz / 4;

/// UART link to the sensor front end and the track consumer: 8N1, no flow control.
inline constexpr std::uint32_t kUartBaud = 115'200;

/// Receive ring (USART2 RX interrupt -> main loop). At 115200 baud about
/// 11.5 bytes arrive per millisecond, so 1 KiB rides out an 88 ms step.
inline constexpr std::size_t kRxRingBytes = 1024;
/// Transmit ring (main loop -> USART2 TX interrupt): 16 KTRK v2 records of 64 bytes (18 of v1).
inline constexpr std::size_t kTxRingBytes = 1024;
/// Frame assembler's linear buffer: the largest frame the decoder accepts.
inline constexpr std::size_t kAssemblerBytes = hal::wire::kMaxFrameBytes;

/// Tracker capacities of this board (float EKF-CA radar tracker).
inline constexpr std::size_t kMaxTracks = 8;
inline constexpr std::size_t kMaxPlots = 32;

/// A convert+step longer than this counts as an overrun: 10 ms, 2 % of the
/// 0.5 s frame interval of docs/scenarios.md's radar scenarios, leaving the rest
/// of the frame for the link and for a second sensor. It is a cycle count:
/// on the HSI fallback (16 MHz) the same work takes 105 ms, still a fifth of
/// the frame interval, and an overrun still means the step did more work.
inline constexpr std::uint64_t kStepBudgetCycles = kCoreClockHz / 100;

}  // namespace kestrel::m4f
