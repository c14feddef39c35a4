// SPDX-License-Identifier: Apache-2.0
// S1, zig-zag with an axial burst (docs/scenarios.md, paper 000), and S1n, the
// same with time-varying noise. Truth is analytic:
//   x(t) = -15000 + s(t),  y(t) = 8000 + 300 sin(2 pi t / 15)  [m]
// with s(t) the along-track distance at 200 m/s plus +5 m/s^2 for
// 80 <= t < 85 s (200 -> 225 m/s).
#pragma once

#include <memory>

#include "scenarios/scenario.hpp"

namespace kestrel::sim {

/// S1 truth at time t (position and velocity, exact).
TruthSample s1_truth(double t_s);

std::unique_ptr<Scenario> make_s1();
std::unique_ptr<Scenario> make_s1n();
/// S1 with a range rate on every plot (sigma kRangeRateSigmaMps); range and
/// bearing noise equal to S1 seed for seed.
std::unique_ptr<Scenario> make_s1rr();
/// S1 with gross range outliers (kOutliers); other noise equal to S1 seed
/// for seed.
std::unique_ptr<Scenario> make_s1_outliers();
/// S1 with a noise burst (range and bearing sigma x kNoiseBurstScale on
/// [kNoiseBurstBeginS, kNoiseBurstEndS)); unit variates equal to S1 seed for seed.
std::unique_ptr<Scenario> make_s1_burst();

}  // namespace kestrel::sim
