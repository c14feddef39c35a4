// SPDX-License-Identifier: Apache-2.0
// A single target seen by the polar radar at the origin (docs/models.md,
// scenarios S1, S2, S1n, S2n): a truth trajectory sampled at the frame
// times, plus range and bearing noise whose sigma may change over time
// (the "n" variants), and optionally a range rate (x vx + y vy)/r with its
// own noise (the "rr" variants, docs/range_rate.md). Each frame holds
// exactly one plot (Pd = 1, no clutter).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "scenarios/scenario.hpp"

namespace kestrel::sim {

/// A time window in which the sensor noise is scaled.
struct NoiseWindow {
  double t_begin_s = 0.0;     ///< Start, inclusive, s.
  double t_end_s = 0.0;       ///< End, exclusive, s.
  double range_scale = 1.0;   ///< Multiplier of sigma_range_m inside the window.
  double bearing_scale = 1.0; ///< Multiplier of sigma_bearing_rad inside the window.
};

/// Radar noise as a function of time.
struct RadarNoise {
  double sigma_range_m = 3.0;                   ///< sr outside any window, m.
  double sigma_bearing_rad = 0.0;               ///< sb outside any window, rad.
  std::vector<NoiseWindow> windows;             ///< Where the sigmas are scaled.
  /// Range-rate noise sigma, m/s (not scaled by the windows). Unset: the
  /// plots carry no range rate.
  std::optional<double> sigma_range_rate_mps;

  /// Range sigma at time t, m.
  double range_sigma_at(double t_s) const;
  /// Bearing sigma at time t, rad.
  double bearing_sigma_at(double t_s) const;
};

/// The S1/S2 sensor: sr = 3 m, sb = 0.30 deg (docs/scenarios.md).
RadarNoise paper000_radar_noise();
/// The S1n/S2n sensor: range sigma x3 for 60 <= t < 75 s, bearing sigma x3
/// for 110 <= t < 120 s (the filters are not told).
RadarNoise paper000_varying_radar_noise();
/// The S1rr/S2rr sensor: the S1/S2 sensor plus a range rate with sigma
/// kRangeRateSigmaMps (no source paper fixes one; docs/range_rate.md).
RadarNoise paper000_range_rate_radar_noise();
/// srr of the rr variants, m/s: a pulse-Doppler radar's typical radial
/// velocity accuracy (docs/range_rate.md).
inline constexpr double kRangeRateSigmaMps = 0.5;

class RadarScenario final : public Scenario {
 public:
  /// @param truth the trajectory at every frame time (seed-independent).
  RadarScenario(ScenarioInfo info, std::vector<TruthSample> truth, RadarNoise noise);

  const ScenarioInfo& info() const override { return info_; }
  ScenarioRun generate(std::uint64_t seed) const override;
  const RadarNoise& noise() const { return noise_; }

 private:
  ScenarioInfo info_;
  std::vector<TruthSample> truth_;
  RadarNoise noise_;
};

}  // namespace kestrel::sim
