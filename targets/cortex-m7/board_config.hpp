// SPDX-License-Identifier: Apache-2.0
// Compile-time configuration of the Cortex-M7 board (STM32H743, e.g. the
// NUCLEO-H743ZI): clocks, the UART link, buffer sizes, tracker capacities
// and the step budget. Every number a reader might want to change for
// another H7 board is here; the drivers only read these constants.
#pragma once

#include <cstddef>
#include <cstdint>

#include "kestrel/hal/frame_format.hpp"

namespace kestrel::m7 {

/// Internal RC oscillator (HSI, HSIDIV 1): the reset clock, and the clock
/// the board stays on when configure_clocks() cannot finish (system.hpp).
inline constexpr std::uint32_t kHsiHz = 64'000'000;
/// Core clock (sys_ck) configure_clocks() aims for: HSI 64 MHz / 4 * 50 / 2
/// through PLL1, at voltage scale 1 (400 MHz is the VOS1 maximum of every
/// H743 revision; 480 MHz needs VOS0 and revision V).
inline constexpr std::uint32_t kCoreClockHz = 400'000'000;
/// AXI/AHB (hclk) = sys_ck / 2; APB1 (USART3's bus and kernel clock) = hclk / 2.
/// At run time: core_clock_hz() and apb1_clock_hz() (system.hpp).
inline constexpr std::uint32_t kAhbHz = kCoreClockHz / 2;
inline constexpr std::uint32_t kApb1Hz = kAhbHz / 2;

/// UART link to the sensor front end and the track consumer: 8N1, no flow
/// control, on USART3 (PD8 TX / PD9 RX: the ST-LINK virtual COM port of the
/// NUCLEO-H743ZI).
inline constexpr std::uint32_t kUartBaud = 115'200;

/// Receive ring (USART3 RX interrupt -> main loop). At 115200 baud about
/// 11.5 bytes arrive per millisecond, so 1 KiB rides out an 88 ms step.
inline constexpr std::size_t kRxRingBytes = 1024;
/// Transmit ring (main loop -> USART3 TX interrupt): 16 KTRK records of 64
/// bytes, two frames of the radar image's 8 tracks. The PCL image's ring
/// holds one full frame of its track table (kPclMaxTracks records); at
/// 115200 baud about 90 records leave per 0.5 s frame, so a frame with more
/// (mostly tentative) tracks than that drops the excess, counted in
/// publish_failures.
#if defined(KESTREL_BOARD_SENSOR_PCL)
inline constexpr std::size_t kTxRingBytes = 8192;
#else
inline constexpr std::size_t kTxRingBytes = 1024;
#endif
/// I062/010 data source of the CAT062 image (kestrel-m7-cat062.elf): the
/// SAC and SIC a surveillance network assigns to this tracker.
inline constexpr std::uint8_t kAsterixSac = 0;
inline constexpr std::uint8_t kAsterixSic = 1;

/// Frame assembler's linear buffer: the largest frame the decoder accepts.
inline constexpr std::size_t kAssemblerBytes = hal::wire::kMaxFrameBytes;

/// Tracker capacities of this board (double EKF-CA radar tracker): the same
/// as the Cortex-M4F board, so the two images differ only in the scalar.
inline constexpr std::size_t kMaxTracks = 8;
inline constexpr std::size_t kMaxPlots = 32;

/// Tracker capacities of the PCL image (kestrel-m7-pcl.elf: double KF on
/// [Rb, dRb]): core's PCL-002 defaults, 32 candidates a frame and room for
/// the tentative tracks about 22 clutter candidates a frame start.
inline constexpr std::size_t kPclMaxTracks = 128;
inline constexpr std::size_t kPclMaxCandidates = 32;

/// A convert+step longer than this counts as an overrun: 10 ms (as on the
/// M4F board), 2 % of the 0.5 s frame interval of docs/scenarios.md's radar
/// scenarios.
inline constexpr std::uint64_t kStepBudgetCycles = kCoreClockHz / 100;

}  // namespace kestrel::m7
