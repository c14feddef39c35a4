// SPDX-License-Identifier: Apache-2.0
#include "scenarios/radar_scenario.hpp"

#include <cmath>
#include <numbers>
#include <utility>

#include "scenarios/rng.hpp"

namespace kestrel::sim {

double wrap_pi(double a) {
  const double r = std::remainder(a, 2.0 * std::numbers::pi);
  return r <= -std::numbers::pi ? r + 2.0 * std::numbers::pi : r;
}

double RadarNoise::range_sigma_at(double t_s) const {
  double sigma = sigma_range_m;
  for (const NoiseWindow& w : windows) {
    if (t_s >= w.t_begin_s && t_s < w.t_end_s) sigma *= w.range_scale;
  }
  return sigma;
}

double RadarNoise::bearing_sigma_at(double t_s) const {
  double sigma = sigma_bearing_rad;
  for (const NoiseWindow& w : windows) {
    if (t_s >= w.t_begin_s && t_s < w.t_end_s) sigma *= w.bearing_scale;
  }
  return sigma;
}

RadarNoise paper000_radar_noise() {
  RadarNoise n;
  n.sigma_range_m = 3.0;
  n.sigma_bearing_rad = 0.30 * std::numbers::pi / 180.0;
  return n;
}

RadarNoise paper000_varying_radar_noise() {
  RadarNoise n = paper000_radar_noise();
  n.windows = {NoiseWindow{60.0, 75.0, 3.0, 1.0}, NoiseWindow{110.0, 120.0, 1.0, 3.0}};
  return n;
}

RadarNoise paper000_range_rate_radar_noise() {
  RadarNoise n = paper000_radar_noise();
  n.sigma_range_rate_mps = kRangeRateSigmaMps;
  return n;
}

RadarNoise paper000_outlier_radar_noise() {
  RadarNoise n = paper000_radar_noise();
  n.range_outliers = kOutliers;
  return n;
}

RadarNoise paper000_burst_radar_noise() {
  RadarNoise n = paper000_radar_noise();
  n.windows = {NoiseWindow{kNoiseBurstBeginS, kNoiseBurstEndS, kNoiseBurstScale, kNoiseBurstScale}};
  return n;
}

RadarScenario::RadarScenario(ScenarioInfo info, std::vector<TruthSample> truth, RadarNoise noise)
    : info_(std::move(info)), truth_(std::move(truth)), noise_(std::move(noise)) {}

ScenarioRun RadarScenario::generate(std::uint64_t seed) const {
  Rng rng(seed);
  // Range-rate noise from a stream of its own, so that range and bearing
  // noise are the same bits as in the variant without range rate (s1 and
  // s1rr with one seed differ only by the range rate: paired comparisons).
  Rng rate_rng(seed ^ 0x5261'6E67'6552'6174ULL);  // "RangeRat"
  // Outliers likewise: s1 and s1-outliers with one seed differ only in the
  // outlier plots.
  Rng outlier_rng(seed ^ 0x4F75'746C'6965'7273ULL);  // "Outliers"
  ScenarioRun run;
  run.truth = truth_;
  run.frames.reserve(truth_.size());
  for (const TruthSample& s : truth_) {
    // Always draw range then bearing, whatever the sigma: the same seed
    // gives the same unit variates in S1 and S1n, so the variants differ
    // only inside their noise windows.
    const double n_range = rng.normal();
    const double n_bearing = rng.normal();
    RadarPlotSi plot;
    plot.range_m = std::hypot(s.x_m, s.y_m) + noise_.range_sigma_at(s.t_s) * n_range;
    plot.bearing_rad = wrap_pi(std::atan2(s.y_m, s.x_m) + noise_.bearing_sigma_at(s.t_s) * n_bearing);
    if (noise_.range_outliers.has_value()) {
      // Three draws per plot whether or not it is an outlier, so which plots
      // are outliers depends only on the seed and the frame index.
      const RangeOutliers& o = *noise_.range_outliers;
      const bool outlier = outlier_rng.uniform() < o.probability;
      const double magnitude = outlier_rng.uniform(o.offset_min_m, o.offset_max_m);
      const double sign = outlier_rng.uniform() < 0.5 ? -1.0 : 1.0;
      if (outlier) plot.range_m += sign * magnitude;
    }
    if (noise_.sigma_range_rate_mps.has_value()) {
      const double r = std::hypot(s.x_m, s.y_m);
      plot.range_rate_mps = (s.x_m * s.vx_mps + s.y_m * s.vy_mps) / r + *noise_.sigma_range_rate_mps * rate_rng.normal();
    }
    MeasurementFrame frame;
    frame.t_s = s.t_s;
    frame.kind = hal::FrameKind::kRadar;
    frame.radar.push_back(plot);
    run.frames.push_back(std::move(frame));
  }
  return run;
}

}  // namespace kestrel::sim
