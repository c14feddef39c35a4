// SPDX-License-Identifier: Apache-2.0
// Which sensor kind (radar, PCL, sonar) a scenario name or a decoded stream
// belongs to, and which trackers fit each kind: `run` and `replay` choose
// the pipeline from it and refuse a mismatch by name (docs/host_sim.md).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "kestrel/hal/frame.hpp"
#include "scenarios/scenario.hpp"

namespace kestrel::sim {

/// The `-f` names of the one tracker each non-radar kind has (radar has
/// the filter registry).
inline constexpr std::string_view kPclFilterName = "pcl-kf";
inline constexpr std::string_view kSonarFilterName = "sonar-ekf";

/// "radar", "PCL" or "sonar".
const char* sensor_kind_name(hal::FrameKind kind);

/// The kind of the scenario called `name` (case-insensitive): the radar
/// registry, the PCL scenarios or the sonar ones; nullopt for no scenario.
std::optional<hal::FrameKind> scenario_kind(std::string_view name);

/// The scenario names of a kind, in listing order.
std::vector<std::string> scenario_names_of_kind(hal::FrameKind kind);

/// The `-f` names that run frames of `kind`.
std::vector<std::string> filters_for_kind(hal::FrameKind kind);

/// The kind a filter name consumes (case-insensitive); nullopt for none.
std::optional<hal::FrameKind> filter_kind(std::string_view name);

/// "a, b, c".
std::string join_names(const std::vector<std::string>& names);

/// Decoded frames of each kind. Placeholders of frames that did not decode
/// (t_s NaN, see decode_stream) are counted apart, never as radar.
struct FrameKindCounts {
  std::size_t radar = 0;
  std::size_t pcl = 0;
  std::size_t sonar = 0;
  std::size_t undecoded = 0;
  /// Kinds with at least one frame.
  [[nodiscard]] std::size_t kinds() const;
  /// "120 radar, 60 PCL" (kinds with frames only).
  [[nodiscard]] std::string describe() const;
};
FrameKindCounts count_frame_kinds(const std::vector<MeasurementFrame>& frames);

}  // namespace kestrel::sim
