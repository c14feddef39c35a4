// SPDX-License-Identifier: Apache-2.0
// What a scenario is: a named, seeded generator of truth and sensor frames
// (docs/scenarios.md). Measurements are in SI units here; stream/ quantises
// them to the wire units a real sensor front end would send.
//
// Truth is deterministic per scenario; the seed only drives sensor noise
// (and, in later scenarios, detection and clutter). The same seed always
// gives the same bits (Rng is fully specified, see rng.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "kestrel/hal/frame.hpp"

namespace kestrel::sim {

/// True target state at one frame time.
struct TruthSample {
  double t_s = 0.0;     ///< Time, s.
  double x_m = 0.0;     ///< Position east of the radar, m.
  double y_m = 0.0;     ///< Position north of the radar, m.
  double vx_mps = 0.0;  ///< Velocity, m/s.
  double vy_mps = 0.0;  ///< Velocity, m/s.
};

/// One radar plot in SI units (radar at the origin).
struct RadarPlotSi {
  double range_m = 0.0;                   ///< Slant range, m.
  double bearing_rad = 0.0;               ///< atan2(y, x), counter-clockwise from +x, (-pi, pi].
  std::optional<double> range_rate_mps;   ///< Radial velocity if measured, m/s, + opening.
  std::uint8_t sensor_id = 0;             ///< Producing sensor (0 for a single radar).
};

/// One sensor look: a time and its detections.
struct MeasurementFrame {
  double t_s = 0.0;                              ///< Measurement time, s.
  hal::FrameKind kind = hal::FrameKind::kRadar;  ///< Which item list is used.
  std::vector<RadarPlotSi> radar;                ///< Plots (kind == kRadar).
};

/// One generated run: truth[k] is the target at frames[k].t_s.
struct ScenarioRun {
  std::vector<TruthSample> truth;
  std::vector<MeasurementFrame> frames;
  /// Scenarios with more than one target (ScenarioInfo::targets > 1):
  /// targets[i][k] is target i at frames[k].t_s (truth is targets[0]), and
  /// origins[k][p] the target index of plot p of frames[k], or -1 for a
  /// false alarm. Empty for single-target scenarios.
  std::vector<std::vector<TruthSample>> targets;
  std::vector<std::vector<int>> origins;
};

/// Constants of a scenario that scoring and the CLI need.
struct ScenarioInfo {
  std::string name;            ///< Registry key, lower case ("s1").
  std::string description;     ///< One line for `kestrel-sim list`.
  hal::FrameKind kind = hal::FrameKind::kRadar;
  double frame_period_s = 0.0; ///< T, s.
  std::size_t steps = 0;       ///< Frames per run.
  double loss_threshold_m = 0.0;  ///< L of the track-loss metric (docs/metrics.md), m.
  std::size_t targets = 1;        ///< Targets per run (multi-target scenarios: docs/multitarget.md).
};

class Scenario {
 public:
  virtual ~Scenario() = default;
  virtual const ScenarioInfo& info() const = 0;
  /// Truth and frames of the run with this seed.
  virtual ScenarioRun generate(std::uint64_t seed) const = 0;
};

}  // namespace kestrel::sim
