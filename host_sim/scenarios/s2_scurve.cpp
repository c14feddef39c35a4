// SPDX-License-Identifier: Apache-2.0
#include "scenarios/s2_scurve.hpp"

#include <cmath>
#include <cstdint>
#include <numbers>

#include "scenarios/radar_scenario.hpp"

namespace kestrel::sim {

namespace {

constexpr double kPeriodS = 0.5;
constexpr std::size_t kSteps = 300;
constexpr double kLossThresholdM = 300.0;

constexpr std::int64_t kTicksPerSecond = 1000;  // integration step 1 ms
constexpr double kDtS = 1.0 / static_cast<double>(kTicksPerSecond);
constexpr double kTurnRadiusM = 1500.0;
constexpr double kQuarterTurnRad = std::numbers::pi / 2.0;
constexpr double kTurnPairStartsS[] = {20.0, 95.0};
constexpr double kBurstStartsS[] = {40.0, 75.0, 125.0};
constexpr double kBurstLengthS = 3.0;
constexpr double kBurstPeakMps2 = 10.0;

// The turn sequence: straight, then for each pair a left and a right
// quarter turn back to back.
enum class Phase { kStraight, kLeft, kRight };

struct State {
  double x_m = -8000.0;
  double y_m = 12000.0;
  double heading_rad = 0.0;  // counter-clockwise from +x
  double speed_mps = 180.0;
  Phase phase = Phase::kStraight;
  double turned_rad = 0.0;   // heading change so far in the current turn
  int pairs_started = 0;
};

TruthSample sample(const State& s, double t_s) {
  return TruthSample{t_s, s.x_m, s.y_m, s.speed_mps * std::cos(s.heading_rad),
                     s.speed_mps * std::sin(s.heading_rad)};
}

// Advance by one 1 ms step starting at time t.
void advance(State& s, double t) {
  constexpr int kPairs = static_cast<int>(std::size(kTurnPairStartsS));
  if (s.phase == Phase::kStraight && s.pairs_started < kPairs && t >= kTurnPairStartsS[s.pairs_started]) {
    s.phase = Phase::kLeft;
    s.turned_rad = 0.0;
    ++s.pairs_started;
  }
  const double accel = s2_along_track_accel(t);
  const double v_mid = s.speed_mps + 0.5 * accel * kDtS;

  // Heading change this step: rate = speed / R, clipped so a turn ends at
  // exactly 90 deg.
  double dpsi = 0.0;
  if (s.phase != Phase::kStraight) {
    dpsi = std::fmin(v_mid / kTurnRadiusM * kDtS, kQuarterTurnRad - s.turned_rad);
    s.turned_rad += dpsi;
    if (s.phase == Phase::kRight) dpsi = -dpsi;
  }
  // Midpoint rule for position: second order in the 1 ms step.
  const double psi_mid = s.heading_rad + 0.5 * dpsi;
  s.x_m += v_mid * std::cos(psi_mid) * kDtS;
  s.y_m += v_mid * std::sin(psi_mid) * kDtS;
  s.heading_rad += dpsi;
  s.speed_mps += accel * kDtS;

  if (s.phase != Phase::kStraight && s.turned_rad >= kQuarterTurnRad) {
    s.phase = s.phase == Phase::kLeft ? Phase::kRight : Phase::kStraight;
    s.turned_rad = 0.0;
  }
}

ScenarioInfo s2_info(const char* name, const char* description) {
  return ScenarioInfo{name, description, hal::FrameKind::kRadar, kPeriodS, kSteps, kLossThresholdM};
}

}  // namespace

double s2_along_track_accel(double t_s) {
  double a = 0.0;
  if (t_s >= 60.0 && t_s < 90.0) a -= 0.2;   // slow ...
  if (t_s >= 90.0 && t_s < 110.0) a += 0.2;  // ... and go
  for (const double t0 : kBurstStartsS) {
    if (t_s >= t0 && t_s < t0 + kBurstLengthS) a += kBurstPeakMps2 * std::sin(std::numbers::pi * (t_s - t0) / kBurstLengthS);
  }
  return a;
}

std::vector<TruthSample> s2_trajectory(double period_s, std::size_t steps) {
  // Integer tick counting: time never drifts and samples land exactly on kT.
  const auto ticks_per_sample = static_cast<std::int64_t>(std::llround(period_s * kTicksPerSecond));
  std::vector<TruthSample> truth;
  truth.reserve(steps);
  State s;
  std::int64_t tick = 0;
  for (std::size_t k = 0; k < steps; ++k) {
    const std::int64_t sample_tick = static_cast<std::int64_t>(k) * ticks_per_sample;
    for (; tick < sample_tick; ++tick) advance(s, static_cast<double>(tick) / kTicksPerSecond);
    truth.push_back(sample(s, static_cast<double>(sample_tick) / kTicksPerSecond));
  }
  return truth;
}

std::unique_ptr<Scenario> make_s2() {
  return std::make_unique<RadarScenario>(
      s2_info("s2", "S2 S-curve (R 1500 m turns), slow-and-go, 3 s jerk bursts; paper 000; T 0.5 s x 300"),
      s2_trajectory(kPeriodS, kSteps), paper000_radar_noise());
}

std::unique_ptr<Scenario> make_s2n() {
  return std::make_unique<RadarScenario>(
      s2_info("s2n", "S2 with range sigma x3 in [60,75) s and bearing sigma x3 in [110,120) s"),
      s2_trajectory(kPeriodS, kSteps), paper000_varying_radar_noise());
}

}  // namespace kestrel::sim

namespace kestrel::sim {

std::unique_ptr<Scenario> make_s2rr() {
  return std::make_unique<RadarScenario>(
      s2_info("s2rr", "S2 with a range rate on every plot (sigma 0.5 m/s); range/bearing noise as S2"),
      s2_trajectory(kPeriodS, kSteps), paper000_range_rate_radar_noise());
}

}  // namespace kestrel::sim

namespace kestrel::sim {

std::unique_ptr<Scenario> make_s2_outliers() {
  return std::make_unique<RadarScenario>(
      s2_info("s2-outliers", "S2 with 3 % of plots off in range by 300-800 m (either sign)"),
      s2_trajectory(kPeriodS, kSteps), paper000_outlier_radar_noise());
}

std::unique_ptr<Scenario> make_s2_burst() {
  return std::make_unique<RadarScenario>(
      s2_info("s2-burst", "S2 with range and bearing sigma x3 in [50,80) s"),
      s2_trajectory(kPeriodS, kSteps), paper000_burst_radar_noise());
}

}  // namespace kestrel::sim
