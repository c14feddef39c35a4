// SPDX-License-Identifier: Apache-2.0
// S2, S-curve with slow-and-go and jerk bursts (docs/scenarios.md, paper 000),
// S2n, the same with time-varying noise, and S2rr, with range rate. Truth is integrated at 1 ms in
// position, heading and speed:
//  - start (-8000, 12000) m, heading +x, 180 m/s;
//  - turns of radius 1500 m (rate = speed / 1500): a left turn of 90 deg
//    from t = 20 s immediately followed by a right turn of 90 deg, and the
//    same pair from t = 95 s; a turn ends when its heading change reaches
//    90 deg exactly (the last 1 ms step is shortened);
//  - along-track -0.2 m/s^2 for 60 <= t < 90 s, +0.2 m/s^2 for 90 <= t < 110 s;
//  - jerk bursts 10 sin(pi (t - t0) / 3) m/s^2 for t0 <= t < t0 + 3 s,
//    t0 = 40, 75, 125 s.
#pragma once

#include <memory>
#include <vector>

#include "scenarios/scenario.hpp"

namespace kestrel::sim {

/// S2 truth sampled every `period_s` for `steps` samples (t = k * period_s).
std::vector<TruthSample> s2_trajectory(double period_s, std::size_t steps);

/// Along-track acceleration of S2 at time t (slow-and-go plus bursts), m/s^2.
double s2_along_track_accel(double t_s);

std::unique_ptr<Scenario> make_s2();
std::unique_ptr<Scenario> make_s2n();
/// S2 with a range rate on every plot (sigma kRangeRateSigmaMps); range and
/// bearing noise equal to S2 seed for seed.
std::unique_ptr<Scenario> make_s2rr();
/// S2 with gross range outliers (kOutliers); other noise equal to S2 seed
/// for seed.
std::unique_ptr<Scenario> make_s2_outliers();
/// S2 with a noise burst (range and bearing sigma x kNoiseBurstScale on
/// [kNoiseBurstBeginS, kNoiseBurstEndS)); unit variates equal to S2 seed for seed.
std::unique_ptr<Scenario> make_s2_burst();

}  // namespace kestrel::sim
