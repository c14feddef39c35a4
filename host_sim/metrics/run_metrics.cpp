// SPDX-License-Identifier: Apache-2.0
#include "metrics/run_metrics.hpp"

#include <cmath>
#include <limits>

namespace kestrel::sim {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool is_lost(const StepError& s, double loss_threshold_m) {
  return !s.error_m.has_value() || *s.error_m > loss_threshold_m;
}
}  // namespace

RunMetrics compute_run_metrics(std::span<const StepError> steps, double period_s, double loss_threshold_m) {
  RunMetrics m;
  m.scored_steps = steps.size();
  double sum_e2 = 0.0;
  double peak = 0.0;
  std::size_t n_error = 0;
  double sum_nees = 0.0;
  std::size_t n_nees = 0;
  double sum_nis = 0.0;
  std::size_t n_nis = 0;

  for (std::size_t k = 0; k < steps.size(); ++k) {
    const StepError& s = steps[k];
    if (s.error_m.has_value()) {
      sum_e2 += *s.error_m * *s.error_m;
      peak = std::fmax(peak, *s.error_m);
      ++n_error;
    } else {
      ++m.missing_steps;
    }
    if (std::isfinite(s.nees)) {
      sum_nees += s.nees;
      ++n_nees;
    }
    if (std::isfinite(s.nis)) {
      sum_nis += s.nis;
      ++n_nis;
    }

    const bool lost = is_lost(s, loss_threshold_m);
    if (lost) ++m.lost_steps;
    const bool was_lost = k > 0 && is_lost(steps[k - 1], loss_threshold_m);
    if (lost && !was_lost) m.episodes.push_back(LossEpisode{k, steps.size(), true});
    if (!lost && was_lost) {
      m.episodes.back().end_step = k;
      m.episodes.back().open_at_end = false;
    }
  }

  m.rmse_m = n_error > 0 ? std::sqrt(sum_e2 / static_cast<double>(n_error)) : kNaN;
  m.peak_m = n_error > 0 ? peak : kNaN;
  m.nees_pos = n_nees > 0 ? sum_nees / static_cast<double>(n_nees) : kNaN;
  m.nis = n_nis > 0 ? sum_nis / static_cast<double>(n_nis) : kNaN;
  m.track_loss_s = period_s * static_cast<double>(m.lost_steps);
  if (m.episodes.empty()) {
    m.recovery_s = kNaN;
  } else {
    double total = 0.0;
    for (const LossEpisode& e : m.episodes) total += period_s * static_cast<double>(e.end_step - e.first_step);
    m.recovery_s = total / static_cast<double>(m.episodes.size());
  }
  return m;
}

}  // namespace kestrel::sim
