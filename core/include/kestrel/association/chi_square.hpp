// Chi-square quantiles for ellipsoidal gates (SPEC section 6), as a
// compile-time table: dimension 1..8 by gate probability. Values are the
// standard inverse CDF to 3 decimals (e.g. scipy.stats.chi2.ppf(0.99, 2) =
// 9.210); tests/core/association/gate_test.cpp checks a few against an
// independent series evaluation.
#pragma once

#include <cstdint>

namespace kestrel {

/// Probability that a true measurement falls inside the gate.
enum class GateProbability : std::uint8_t { k90 = 0, k95, k99, k995, k999 };

inline constexpr int kChiSquareMaxDim = 8;

/// Inverse chi-square CDF for kDim degrees of freedom.
template <int kDim>
constexpr double chi_square_quantile(GateProbability p) {
  static_assert(kDim >= 1 && kDim <= kChiSquareMaxDim, "chi-square table covers 1..8 dimensions");
  constexpr double kTable[kChiSquareMaxDim][5] = {
      {2.706, 3.841, 6.635, 7.879, 10.828},
      {4.605, 5.991, 9.210, 10.597, 13.816},
      {6.251, 7.815, 11.345, 12.838, 16.266},
      {7.779, 9.488, 13.277, 14.860, 18.467},
      {9.236, 11.070, 15.086, 16.750, 20.515},
      {10.645, 12.592, 16.812, 18.548, 22.458},
      {12.017, 14.067, 18.475, 20.278, 24.322},
      {13.362, 15.507, 20.090, 21.955, 26.124},
  };
  return kTable[kDim - 1][static_cast<int>(p)];
}

}  // namespace kestrel
