// SPDX-License-Identifier: Apache-2.0
#include "scenarios/multi_target.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "kestrel/hal/frame.hpp"
#include "scenarios/radar_scenario.hpp"
#include "scenarios/rng.hpp"

namespace kestrel::sim {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kIntegrationStepS = 1e-3;

/// The S1/S2 sensor's sigmas (docs/scenarios.md), so the radar tracker's
/// defaults fit every radar scenario.
MultiTargetSensor paper000_sensor() {
  MultiTargetSensor s;
  s.sigma_range_m = 3.0;
  s.sigma_bearing_rad = 0.30 * kDeg;
  return s;
}

TargetMotion straight(double x0, double y0, double speed, double heading_deg) {
  return TargetMotion{x0, y0, speed, heading_deg * kDeg, {}};
}

}  // namespace

std::vector<TruthSample> sample_motion(const TargetMotion& m, double period_s, std::size_t steps) {
  std::vector<TruthSample> out;
  out.reserve(steps);
  double x = m.x0_m;
  double y = m.y0_m;
  double psi = m.heading_rad;
  double t = 0.0;
  const auto turn_rate = [&m](double at) {
    double w = 0.0;
    for (const TurnLeg& l : m.turns) {
      if (at >= l.t_begin_s && at < l.t_end_s) w += l.turn_rate_radps;
    }
    return w;
  };
  for (std::size_t k = 0; k < steps; ++k) {
    const double tk = static_cast<double>(k) * period_s;
    // Integer step counts, so the sample times are exact whatever the period.
    const long n = std::lround((tk - t) / kIntegrationStepS);
    for (long i = 0; i < n; ++i) {
      x += m.speed_mps * std::cos(psi) * kIntegrationStepS;
      y += m.speed_mps * std::sin(psi) * kIntegrationStepS;
      psi += turn_rate(t) * kIntegrationStepS;
      t += kIntegrationStepS;
    }
    t = tk;
    out.push_back(TruthSample{tk, x, y, m.speed_mps * std::cos(psi), m.speed_mps * std::sin(psi)});
  }
  return out;
}

MultiTargetScenario::MultiTargetScenario(ScenarioInfo info, const std::vector<TargetMotion>& motions,
                                         MultiTargetSensor sensor)
    : info_(std::move(info)), sensor_(sensor) {
  info_.targets = motions.size();
  for (const TargetMotion& m : motions) targets_.push_back(sample_motion(m, info_.frame_period_s, info_.steps));
}

ScenarioRun MultiTargetScenario::generate(std::uint64_t seed) const {
  // Detections and noise from one stream, clutter from another: a run with
  // and without clutter differ only in the false alarms.
  Rng rng(seed);
  Rng clutter_rng(seed ^ 0x436C'7574'7465'7221ULL);  // "Clutter!"
  ScenarioRun run;
  run.targets = targets_;
  run.truth = targets_.empty() ? std::vector<TruthSample>{} : targets_.front();
  run.frames.reserve(info_.steps);
  run.origins.reserve(info_.steps);
  for (std::size_t k = 0; k < info_.steps; ++k) {
    std::vector<std::pair<RadarPlotSi, int>> plots;
    for (std::size_t i = 0; i < targets_.size(); ++i) {
      const TruthSample& s = targets_[i][k];
      // Three draws per target and frame whether or not it is detected, so
      // the noise of one target does not depend on another's detections.
      const bool detected = rng.uniform() < sensor_.detection_probability;
      const double n_range = rng.normal();
      const double n_bearing = rng.normal();
      if (!detected) continue;
      RadarPlotSi p;
      p.range_m = std::hypot(s.x_m, s.y_m) + sensor_.sigma_range_m * n_range;
      p.bearing_rad = wrap_pi(std::atan2(s.y_m, s.x_m) + sensor_.sigma_bearing_rad * n_bearing);
      plots.emplace_back(p, static_cast<int>(i));
    }
    const std::size_t n_clutter = sensor_.clutter_mean > 0.0 ? clutter_rng.poisson(sensor_.clutter_mean) : 0;
    for (std::size_t c = 0; c < n_clutter; ++c) {
      RadarPlotSi p;
      // Uniform over range and bearing cells: a constant false-alarm rate per resolution cell.
      p.range_m = clutter_rng.uniform(sensor_.range_min_m, sensor_.range_max_m);
      p.bearing_rad = wrap_pi(clutter_rng.uniform(sensor_.bearing_min_rad, sensor_.bearing_max_rad));
      plots.emplace_back(p, -1);
    }
    std::stable_sort(plots.begin(), plots.end(),
                     [](const auto& a, const auto& b) { return a.first.bearing_rad < b.first.bearing_rad; });
    if (plots.size() > hal::kMaxRadarPlots) plots.resize(hal::kMaxRadarPlots);
    MeasurementFrame frame;
    frame.t_s = targets_.empty() ? static_cast<double>(k) * info_.frame_period_s : targets_.front()[k].t_s;
    frame.kind = hal::FrameKind::kRadar;
    std::vector<int> origin;
    for (const auto& [p, o] : plots) {
      frame.radar.push_back(p);
      origin.push_back(o);
    }
    run.frames.push_back(std::move(frame));
    run.origins.push_back(std::move(origin));
  }
  return run;
}

/// The raid's and the formation's sensor: the S1/S2 sigmas, Pd 0.9, and
/// Poisson clutter of the given mean per frame over the sector 5-40 km,
/// 45-135 deg that both scenarios fly in.
MultiTargetSensor surveillance_sector(double clutter_mean) {
  MultiTargetSensor sensor = paper000_sensor();
  sensor.detection_probability = 0.9;
  sensor.clutter_mean = clutter_mean;
  sensor.range_min_m = 5000.0;
  sensor.range_max_m = 40000.0;
  sensor.bearing_min_rad = 45.0 * kDeg;
  sensor.bearing_max_rad = 135.0 * kDeg;
  return sensor;
}

std::unique_ptr<Scenario> make_crossing() {
  // Both inbound at 200 m/s, headings -80 and -100 deg, mirror images
  // about the y axis: their ranges are equal all along, so only bearing
  // tells them apart, and they cross at (0, 10 km) at t = 30 s with a
  // cross-range closing speed of 69 m/s; within one cross-range sigma of
  // each other (52 m at 10 km) for about 1.5 s.
  constexpr double kSpeed = 200.0;
  constexpr double kHalfAngleDeg = 10.0;
  constexpr double kCrossS = 30.0;
  const double dx = kSpeed * std::sin(kHalfAngleDeg * kDeg) * kCrossS;
  const double dy = kSpeed * std::cos(kHalfAngleDeg * kDeg) * kCrossS;
  ScenarioInfo info{"crossing", "Two inbound targets crossing at 20 deg at 10 km, equal ranges, T 1 s, Pd 1, no clutter",
                    hal::FrameKind::kRadar, 1.0, 61, 300.0};
  MultiTargetSensor sensor = paper000_sensor();
  sensor.detection_probability = 1.0;
  return std::make_unique<MultiTargetScenario>(
      info, std::vector<TargetMotion>{straight(-dx, 10000.0 + dy, kSpeed, -90.0 + kHalfAngleDeg),
                                      straight(dx, 10000.0 + dy, kSpeed, -90.0 - kHalfAngleDeg)},
      sensor);
}

std::unique_ptr<Scenario> make_raid() {
  // Three rows of four, 1 km abreast and 1.5 km in trail, inbound (-y) at
  // 250 m/s from 32 km to 12 km; 1 km is 6 cross-range sigmas at 32 km.
  ScenarioInfo info{"raid", "Raid of 12 inbound targets, T 1 s, Pd 0.9, Poisson(10) clutter per frame",
                    hal::FrameKind::kRadar, 1.0, 80, 300.0};
  const MultiTargetSensor sensor = surveillance_sector(10.0);
  std::vector<TargetMotion> m;
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 4; ++col) {
      m.push_back(straight(-1500.0 + 1000.0 * col, 32000.0 + 1500.0 * row, 250.0, -90.0));
    }
  }
  return std::make_unique<MultiTargetScenario>(info, m, sensor);
}

std::unique_ptr<Scenario> make_formation_split() {
  // Three abreast across the line of sight, 400 m apart (2.7 cross-range
  // sigmas at 28 km; along the line of sight range would separate them),
  // inbound at 220 m/s from (x, 28 km) to about 8 km; at t = 40 s the
  // outer two turn away at 3 deg/s for 10 s.
  ScenarioInfo info{"formation-split",
                    "Formation of 3 (400 m abreast, inbound) splitting at t = 40 s, T 1 s, Pd 0.9, Poisson(5) clutter",
                    hal::FrameKind::kRadar, 1.0, 90, 300.0};
  const MultiTargetSensor sensor = surveillance_sector(5.0);
  // Heading -90 deg: turning right (clockwise, negative rate) heads west (-x).
  TargetMotion west = straight(-400.0, 28000.0, 220.0, -90.0);
  west.turns.push_back(TurnLeg{40.0, 50.0, -3.0 * kDeg});
  TargetMotion east = straight(400.0, 28000.0, 220.0, -90.0);
  east.turns.push_back(TurnLeg{40.0, 50.0, 3.0 * kDeg});
  return std::make_unique<MultiTargetScenario>(
      info, std::vector<TargetMotion>{west, straight(0.0, 28000.0, 220.0, -90.0), east}, sensor);
}

}  // namespace kestrel::sim
