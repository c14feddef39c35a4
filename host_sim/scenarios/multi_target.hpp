// SPDX-License-Identifier: Apache-2.0
// Multi-target radar scenarios (docs/scenarios.md, docs/multitarget.md):
// several targets seen by the polar radar at the origin, each detected with
// probability Pd per frame, plus Poisson false alarms uniform over the
// surveillance region's range-bearing cells. Plots carry no label on the
// wire; ScenarioRun::origins keeps each plot's true origin for scoring and
// for the oracle associator. Truth is seed-independent; the seed drives
// detections, noise and clutter.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "scenarios/scenario.hpp"

namespace kestrel::sim {

/// A manoeuvre of one target: from t_begin_s on, turn at turn_rate_radps
/// (positive counter-clockwise) until t_end_s.
struct TurnLeg {
  double t_begin_s = 0.0;
  double t_end_s = 0.0;
  double turn_rate_radps = 0.0;
};

/// One target's motion: constant speed, straight except in its turns.
struct TargetMotion {
  double x0_m = 0.0;
  double y0_m = 0.0;
  double speed_mps = 0.0;
  double heading_rad = 0.0;  ///< Counter-clockwise from +x.
  std::vector<TurnLeg> turns;
};

/// The sensor and the region of a multi-target scenario.
struct MultiTargetSensor {
  double sigma_range_m = 3.0;        ///< sr, m.
  double sigma_bearing_rad = 0.0;    ///< sb, rad.
  double detection_probability = 1.0;  ///< Pd per target and frame.
  double clutter_mean = 0.0;         ///< Mean false alarms per frame (Poisson).
  double range_min_m = 0.0;          ///< Surveillance region: ranges ...
  double range_max_m = 0.0;
  double bearing_min_rad = 0.0;      ///< ... and bearings of the false alarms.
  double bearing_max_rad = 0.0;
};

class MultiTargetScenario final : public Scenario {
 public:
  /// @param info its targets field is set to motions.size().
  MultiTargetScenario(ScenarioInfo info, const std::vector<TargetMotion>& motions, MultiTargetSensor sensor);

  const ScenarioInfo& info() const override { return info_; }
  /// Frames with the plots in bearing order (as a rotating antenna reports
  /// them, so the order says nothing of the origin), at most
  /// hal::kMaxRadarPlots: the plots beyond it in that order are dropped.
  ScenarioRun generate(std::uint64_t seed) const override;
  const std::vector<std::vector<TruthSample>>& targets() const { return targets_; }
  const MultiTargetSensor& sensor() const { return sensor_; }

 private:
  ScenarioInfo info_;
  std::vector<std::vector<TruthSample>> targets_;  ///< [target][frame]
  MultiTargetSensor sensor_;
};

/// Sample a TargetMotion at t = k * period_s, k = 0..steps-1 (integrated at 1 ms).
std::vector<TruthSample> sample_motion(const TargetMotion& m, double period_s, std::size_t steps);

/// Two targets crossing at close range.
std::unique_ptr<Scenario> make_crossing();
/// A raid of twelve targets, Pd 0.9, Poisson clutter.
std::unique_ptr<Scenario> make_raid();
/// A formation of three that splits.
std::unique_ptr<Scenario> make_formation_split();

}  // namespace kestrel::sim
