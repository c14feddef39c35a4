// SPDX-License-Identifier: Apache-2.0
// Chi-square quantiles for ellipsoidal gates (docs/tracking.md), as a
// compile-time table: dimension 1..16 by gate probability (16 = the most TOA
// channels a sonar frame carries, for gates over a variable subset). Values
// are the standard inverse CDF to 3 decimals (e.g. scipy.stats.chi2.ppf(0.99,
// 2) = 9.210); tests/core/association/gate_test.cpp and
// tests/core/filters/channel_gated_ekf_test.cpp check them against an
// independent series evaluation.
#pragma once

#include <cstdint>

namespace kestrel {

/// Probability that a true measurement falls inside the gate.
enum class GateProbability : std::uint8_t { k90 = 0, k95, k99, k995, k999 };

/// The probability itself (the track score's miss term needs P_G).
constexpr double gate_probability(GateProbability p) {
  constexpr double kProbability[] = {0.90, 0.95, 0.99, 0.995, 0.999};
  return kProbability[static_cast<int>(p)];
}

/// The GateProbability whose probability is `p` (0.90, 0.95, 0.99, 0.995
/// or 0.999) to within 1e-12, the rounding of those decimals and no more:
/// configuration read as a number. @return false, `g` unchanged, for any
/// other value (NaN included).
constexpr bool gate_probability_from(double p, GateProbability& g) {
  for (int i = 0; i < 5; ++i) {
    const auto candidate = static_cast<GateProbability>(i);
    const double d = gate_probability(candidate) - p;
    if (d < 1e-12 && d > -1e-12) {
      g = candidate;
      return true;
    }
  }
  return false;
}

inline constexpr int kChiSquareMaxDim = 16;

namespace detail {
inline constexpr double kChiSquareTable[kChiSquareMaxDim][5] = {
    {2.706, 3.841, 6.635, 7.879, 10.828},
    {4.605, 5.991, 9.210, 10.597, 13.816},
    {6.251, 7.815, 11.345, 12.838, 16.266},
    {7.779, 9.488, 13.277, 14.860, 18.467},
    {9.236, 11.070, 15.086, 16.750, 20.515},
    {10.645, 12.592, 16.812, 18.548, 22.458},
    {12.017, 14.067, 18.475, 20.278, 24.322},
    {13.362, 15.507, 20.090, 21.955, 26.124},
    {14.684, 16.919, 21.666, 23.589, 27.877},
    {15.987, 18.307, 23.209, 25.188, 29.588},
    {17.275, 19.675, 24.725, 26.757, 31.264},
    {18.549, 21.026, 26.217, 28.300, 32.909},
    {19.812, 22.362, 27.688, 29.819, 34.528},
    {21.064, 23.685, 29.141, 31.319, 36.123},
    {22.307, 24.996, 30.578, 32.801, 37.697},
    {23.542, 26.296, 32.000, 34.267, 39.252},
};
}  // namespace detail

/// Inverse chi-square CDF for kDim degrees of freedom.
template <int kDim>
constexpr double chi_square_quantile(GateProbability p) {
  static_assert(kDim >= 1 && kDim <= kChiSquareMaxDim, "chi-square table covers 1..16 dimensions");
  return detail::kChiSquareTable[kDim - 1][static_cast<int>(p)];
}

/// Inverse chi-square CDF for a dimension known only at run time (a gate
/// over a variable subset of channels). dim is clamped to 1..16: callers
/// bound it by a compile-time capacity checked against kChiSquareMaxDim.
constexpr double chi_square_quantile(int dim, GateProbability p) {
  const int d = dim < 1 ? 1 : (dim > kChiSquareMaxDim ? kChiSquareMaxDim : dim);
  return detail::kChiSquareTable[d - 1][static_cast<int>(p)];
}

}  // namespace kestrel
