// SPDX-License-Identifier: Apache-2.0
// Compile-time configuration of the riscv64-linux board (an embedded-Linux
// RISC-V SoC: StarFive JH7110, Allwinner D1, SpacemiT K1, ...): tracker
// capacities, buffer sizes and the step budget. The cycle clock is chosen
// when configuring (KESTREL_RV64_CYCLE_CLOCK, cycle_clock.hpp).
#pragma once

#include <cstddef>
#include <cstdint>

#include "kestrel/hal/frame.hpp"
#include "kestrel/hal/frame_format.hpp"

namespace kestrel::rv64 {

/// Tracker capacities: the host board's (targets/host board.hpp), so a
/// stream replayed here and by kestrel-host-replay runs the same tracker.
inline constexpr std::size_t kMaxTracks = 16;
inline constexpr std::size_t kMaxPlots = hal::kMaxRadarPlots;

/// Bytes read from the input per read(2) call.
inline constexpr std::size_t kReadChunkBytes = 512;
/// Frame assembler's linear buffer: the largest frame the decoder accepts.
inline constexpr std::size_t kAssemblerBytes = hal::wire::kMaxFrameBytes;
/// KTRK records buffered before a write(2): a full table of reports.
inline constexpr std::size_t kSinkRecords = kMaxTracks;

/// A convert+step longer than this counts as an overrun: 10 ms (as on the
/// microcontroller boards), 2 % of the 0.5 s frame interval of
/// docs/scenarios.md's radar scenarios. Converted to clock ticks at start-up.
inline constexpr std::uint64_t kStepBudgetNs = 10'000'000;

}  // namespace kestrel::rv64
