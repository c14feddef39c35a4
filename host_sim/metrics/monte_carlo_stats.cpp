// SPDX-License-Identifier: Apache-2.0
#include "metrics/monte_carlo_stats.hpp"

#include <cmath>
#include <limits>

namespace kestrel::sim {

MeanCi mean_ci95(std::span<const double> values) {
  MeanCi out;
  double sum = 0.0;
  for (const double v : values) {
    if (!std::isfinite(v)) continue;
    sum += v;
    ++out.n;
  }
  if (out.n == 0) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return MeanCi{nan, nan, nan, 0};
  }
  out.mean = sum / static_cast<double>(out.n);
  double ss = 0.0;
  for (const double v : values) {
    if (std::isfinite(v)) ss += (v - out.mean) * (v - out.mean);
  }
  const double sd = out.n > 1 ? std::sqrt(ss / static_cast<double>(out.n - 1)) : 0.0;
  const double half = 1.96 * sd / std::sqrt(static_cast<double>(out.n));
  out.ci95_low = out.mean - half;
  out.ci95_high = out.mean + half;
  return out;
}

}  // namespace kestrel::sim
