// SPDX-License-Identifier: Apache-2.0
#include "timing/step_timing.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace kestrel::sim {

namespace {
// Nearest rank: the smallest value with at least p * n values at or below it.
std::uint64_t percentile(const std::vector<std::uint64_t>& sorted, double p) {
  const auto rank = static_cast<std::size_t>(std::ceil(p * static_cast<double>(sorted.size())));
  return sorted[rank == 0 ? 0 : rank - 1];
}
}  // namespace

StepTiming summarise_step_times(std::span<const std::uint64_t> step_ns, std::uint64_t budget_ns) {
  StepTiming t;
  t.budget_ns = budget_ns;
  t.steps = step_ns.size();
  if (step_ns.empty()) return t;
  std::vector<std::uint64_t> sorted(step_ns.begin(), step_ns.end());
  std::sort(sorted.begin(), sorted.end());
  t.min_ns = sorted.front();
  t.max_ns = sorted.back();
  t.median_ns = percentile(sorted, 0.50);
  t.p99_ns = percentile(sorted, 0.99);
  double sum = 0.0;
  for (const std::uint64_t v : sorted) {
    sum += static_cast<double>(v);
    if (v > budget_ns) ++t.overruns;
  }
  t.mean_ns = sum / static_cast<double>(sorted.size());
  return t;
}

}  // namespace kestrel::sim
