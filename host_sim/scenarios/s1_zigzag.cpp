// SPDX-License-Identifier: Apache-2.0
#include "scenarios/s1_zigzag.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "scenarios/radar_scenario.hpp"

namespace kestrel::sim {

namespace {

constexpr double kPeriodS = 0.5;        // T
constexpr std::size_t kSteps = 300;     // k = 0..299
constexpr double kLossThresholdM = 300.0;

constexpr double kSpeed0Mps = 200.0;    // nominal speed along +x
constexpr double kBurstStartS = 80.0;   // axial burst +5 m/s^2 ...
constexpr double kBurstEndS = 85.0;     // ... until here (200 -> 225 m/s)
constexpr double kBurstAccelMps2 = 5.0;
constexpr double kWeaveAmplitudeM = 300.0;
constexpr double kWeavePeriodS = 15.0;

// Along-track distance s(t) and speed s'(t) of the nominal heading (+x).
void along_track(double t, double& s, double& v) {
  if (t < kBurstStartS) {
    s = kSpeed0Mps * t;
    v = kSpeed0Mps;
    return;
  }
  const double tb = (t < kBurstEndS ? t : kBurstEndS) - kBurstStartS;  // time spent accelerating
  const double s_burst = kSpeed0Mps * (kBurstStartS + tb) + 0.5 * kBurstAccelMps2 * tb * tb;
  const double v_burst = kSpeed0Mps + kBurstAccelMps2 * tb;
  const double coast = t < kBurstEndS ? 0.0 : t - kBurstEndS;
  s = s_burst + v_burst * coast;
  v = v_burst;
}

std::vector<TruthSample> s1_trajectory() {
  std::vector<TruthSample> truth;
  truth.reserve(kSteps);
  for (std::size_t k = 0; k < kSteps; ++k) truth.push_back(s1_truth(static_cast<double>(k) * kPeriodS));
  return truth;
}

ScenarioInfo s1_info(const char* name, const char* description) {
  return ScenarioInfo{name, description, hal::FrameKind::kRadar, kPeriodS, kSteps, kLossThresholdM};
}

}  // namespace

TruthSample s1_truth(double t_s) {
  constexpr double w = 2.0 * std::numbers::pi / kWeavePeriodS;  // weave angular rate, rad/s
  double s = 0.0;
  double v = 0.0;
  along_track(t_s, s, v);
  TruthSample out;
  out.t_s = t_s;
  out.x_m = -15000.0 + s;
  out.y_m = 8000.0 + kWeaveAmplitudeM * std::sin(w * t_s);
  out.vx_mps = v;
  out.vy_mps = kWeaveAmplitudeM * w * std::cos(w * t_s);
  return out;
}

std::unique_ptr<Scenario> make_s1() {
  return std::make_unique<RadarScenario>(
      s1_info("s1", "S1 zig-zag (5.4 g weave) with axial burst; paper 000; T 0.5 s x 300"),
      s1_trajectory(), paper000_radar_noise());
}

std::unique_ptr<Scenario> make_s1n() {
  return std::make_unique<RadarScenario>(
      s1_info("s1n", "S1 with range sigma x3 in [60,75) s and bearing sigma x3 in [110,120) s"),
      s1_trajectory(), paper000_varying_radar_noise());
}

}  // namespace kestrel::sim

namespace kestrel::sim {

std::unique_ptr<Scenario> make_s1rr() {
  return std::make_unique<RadarScenario>(
      s1_info("s1rr", "S1 with a range rate on every plot (sigma 0.5 m/s); range/bearing noise as S1"),
      s1_trajectory(), paper000_range_rate_radar_noise());
}

}  // namespace kestrel::sim

namespace kestrel::sim {

std::unique_ptr<Scenario> make_s1_outliers() {
  return std::make_unique<RadarScenario>(
      s1_info("s1-outliers", "S1 with 3 % of plots off in range by 300-800 m (either sign)"),
      s1_trajectory(), paper000_outlier_radar_noise());
}

std::unique_ptr<Scenario> make_s1_burst() {
  return std::make_unique<RadarScenario>(
      s1_info("s1-burst", "S1 with range and bearing sigma x3 in [50,80) s"),
      s1_trajectory(), paper000_burst_radar_noise());
}

}  // namespace kestrel::sim
