// SPDX-License-Identifier: Apache-2.0
#include "metrics/scoring.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kestrel::sim {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Truth sample at exactly t_us (truth rows are sorted by time), if any.
const TruthSample* truth_at(const std::vector<TruthSample>& truth, std::int64_t t_us) {
  const auto it = std::lower_bound(truth.begin(), truth.end(), t_us, [](const TruthSample& s, std::int64_t t) {
    return std::llround(s.t_s * 1e6) < t;
  });
  if (it == truth.end() || std::llround(it->t_s * 1e6) != t_us) return nullptr;
  return &*it;
}
}  // namespace

double position_nees(double ex, double ey, double p_xx, double p_xy, double p_yy) {
  const double det = p_xx * p_yy - p_xy * p_xy;
  if (!(p_xx > 0.0) || !(det > 0.0)) return kNaN;
  // [ex ey] inv(P) [ex ey]^T with the 2x2 inverse written out.
  return (p_yy * ex * ex - 2.0 * p_xy * ex * ey + p_xx * ey * ey) / det;
}

std::vector<ScoredStep> score_run(const StreamRunResult& run, const std::vector<TruthSample>& truth,
                                  const ScoringParams& config) {
  std::vector<ScoredStep> steps;
  for (std::size_t k = 0; k < run.frames.size(); ++k) {
    const FrameOutcome& f = run.frames[k];
    // A frame the tracker refused has no reports by design (docs/tracking.md):
    // it is counted in the status table, not scored.
    const bool tracked = f.status == Status::kOk || f.status == Status::kTooManyCandidates;
    if (k < config.first_scored_step || !f.stepped || !tracked) continue;
    const TruthSample* t = truth_at(truth, f.t_us);
    if (t == nullptr) continue;

    ScoredStep s;
    s.k = k;
    s.t_s = static_cast<double>(f.t_us) * 1e-6;
    s.truth = *t;
    s.nees = kNaN;
    s.nis = kNaN;
    double best = std::numeric_limits<double>::infinity();
    for (const host::TrackRow& row : f.tracks) {
      if (!row.confirmed) continue;
      ++s.confirmed_tracks;
      const double e = std::hypot(row.x_m - t->x_m, row.y_m - t->y_m);
      if (e < best) {
        best = e;
        s.estimate = row;
      }
    }
    if (s.estimate.has_value()) {
      const host::TrackRow& est = *s.estimate;
      s.error_m = best;
      s.nees = position_nees(est.x_m - t->x_m, est.y_m - t->y_m, est.p_xx, est.p_xy, est.p_yy);
      s.nis = est.associated ? est.nis : kNaN;
    }
    steps.push_back(s);
  }
  return steps;
}

}  // namespace kestrel::sim
