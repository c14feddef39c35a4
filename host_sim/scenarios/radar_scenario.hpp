// SPDX-License-Identifier: Apache-2.0
// A single target seen by the polar radar at the origin (docs/models.md,
// scenarios S1, S2, S1n, S2n): a truth trajectory sampled at the frame
// times, plus range and bearing noise whose sigma may change over time
// (the "n" and "burst" variants), optionally a range rate (x vx + y vy)/r
// with its own noise (the "rr" variants, docs/range_rate.md), and
// optionally gross range outliers (the "outliers" variants,
// docs/robustness.md). Each frame holds exactly one plot (Pd = 1, no
// clutter).
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

/// Gross range errors: with probability `probability` a plot's range is
/// off by an offset of magnitude uniform on [offset_min_m, offset_max_m)
/// and random sign, on top of its Gaussian noise (a multipath or
/// range-gate error of the plot extractor).
struct RangeOutliers {
  double probability = 0.0;   ///< Chance per plot, in [0, 1].
  double offset_min_m = 0.0;  ///< Smallest offset magnitude, m.
  double offset_max_m = 0.0;  ///< Largest offset magnitude (exclusive), m.
};

/// Radar noise as a function of time.
struct RadarNoise {
  double sigma_range_m = 3.0;                   ///< sr outside any window, m.
  double sigma_bearing_rad = 0.0;               ///< sb outside any window, rad.
  std::vector<NoiseWindow> windows;             ///< Where the sigmas are scaled.
  /// Range-rate noise sigma, m/s (not scaled by the windows). Unset: the
  /// plots carry no range rate.
  std::optional<double> sigma_range_rate_mps;
  /// Gross range outliers. Unset: none.
  std::optional<RangeOutliers> range_outliers;

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
/// The "outliers" sensor: the S1/S2 sensor plus kOutliers (docs/robustness.md).
RadarNoise paper000_outlier_radar_noise();
/// 3 % of plots with a range offset of 300-800 m, either sign: each one
/// lands beyond the track-loss threshold L = 300 m of S1/S2.
inline constexpr RangeOutliers kOutliers{0.03, 300.0, 800.0};
/// The "burst" sensor: the S1/S2 sensor with range and bearing sigma
/// x kNoiseBurstScale for kNoiseBurstBeginS <= t < kNoiseBurstEndS (the filters are not
/// told; docs/robustness.md).
RadarNoise paper000_burst_radar_noise();
inline constexpr double kNoiseBurstBeginS = 50.0;
inline constexpr double kNoiseBurstEndS = 80.0;
inline constexpr double kNoiseBurstScale = 3.0;

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

/// An angle in (-pi, pi], the convention of the core's residual() and of
/// docs/host_sim.md: every simulated bearing is wrapped by it.
double wrap_pi(double a);

}  // namespace kestrel::sim
