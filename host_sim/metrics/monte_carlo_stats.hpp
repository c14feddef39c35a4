// SPDX-License-Identifier: Apache-2.0
// Monte Carlo figures (docs/metrics.md): the mean over runs of a per-run
// figure with the 95 % confidence interval of that mean,
// mean +- 1.96 sd / sqrt(n), sd the sample standard deviation (n - 1).
// One run gives a zero-width interval (there is no spread to estimate).
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <vector>

namespace kestrel::sim {

struct MeanCi {
  double mean = 0.0;
  double ci95_low = 0.0;
  double ci95_high = 0.0;
  std::size_t n = 0;  ///< Values that entered (NaN values are skipped).
};

/// Mean and 95 % interval of the finite values; all NaN if there are none.
MeanCi mean_ci95(std::span<const double> values);

/// mean_ci95 of a per-run figure over the runs: `figure` is a field of Run
/// (&Run::rmse_m) or a function of a run.
template <class Run, class Figure>
MeanCi mean_ci95_of(const std::vector<Run>& runs, Figure figure) {
  std::vector<double> values;
  values.reserve(runs.size());
  for (const Run& r : runs) values.push_back(static_cast<double>(std::invoke(figure, r)));
  return mean_ci95(values);
}

}  // namespace kestrel::sim
