// SPDX-License-Identifier: Apache-2.0
#include "metrics/pcl_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace kestrel::sim {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool on_target(const PclTrackRow& r, const PclTruth& t, const PclTolerance& tol) {
  return std::abs(r.rb_m - t.rb_m) <= tol.rb_m && std::abs(r.drb_mps - t.drb_mps) <= tol.drb_mps;
}

double ratio(std::size_t num, std::size_t den) {
  return den == 0 ? kNaN : static_cast<double>(num) / static_cast<double>(den);
}
}  // namespace

PclRunMetrics score_pcl_run(const PclScenarioRun& run, const PclRunOutput& out, const PclTolerance& tol) {
  PclRunMetrics m;
  const std::size_t n = std::min(run.frames.size(), out.frames.size());

  // Pass 1: each confirmed track's life and time on the target.
  struct Life {
    std::size_t frames = 0, on = 0;
  };
  std::map<std::uint32_t, Life> lives;
  for (std::size_t k = 0; k < n; ++k) {
    for (const PclTrackRow& r : out.frames[k].tracks) {
      Life& l = lives[r.id];
      ++l.frames;
      if (on_target(r, run.truth[k], tol)) ++l.on;
    }
  }
  std::map<std::uint32_t, bool> is_target;
  for (const auto& [id, l] : lives) {
    const bool target = 2 * l.on > l.frames;
    is_target[id] = target;
    ++m.confirmed_tracks;
    if (target) ++m.target_tracks;
    else ++m.false_tracks;
  }

  // Pass 2: frame by frame.
  std::size_t first_confirmed = n;
  double se_rb = 0.0, se_drb = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const PclFrameOutcome& f = out.frames[k];
    const PclFrameRecord& rec = run.frames[k];
    const PclTruth& truth = run.truth[k];
    if (f.stepped) m.step_ns.push_back(f.step_ns);
    if (f.status == Status::kTooManyCandidates) ++m.frames_over_capacity;
    if (!f.stepped || (f.status != Status::kOk && f.status != Status::kTooManyCandidates)) ++m.frames_refused;
    if (rec.target_index >= 0) {
      ++m.detections;
      if (f.stepped && !f.target_in_scan) ++m.cut_by_adapter;
    } else if (rec.detected) {
      ++m.cut_by_sensor;
    }
    m.refused_starts += f.refused_starts;
    m.dropped_starts += f.dropped_starts;
    m.max_tracks_in_table = std::max(m.max_tracks_in_table, f.tracks_in_table);
    const PclTrackRow* primary = nullptr;
    bool took_detection = false;
    bool covered = false;
    for (const PclTrackRow& r : f.tracks) {
      if (on_target(r, truth, tol)) covered = true;
      if (!is_target[r.id]) continue;
      if (primary == nullptr || r.id < primary->id) primary = &r;
      if (rec.target_index >= 0 && r.frame_index == rec.target_index) took_detection = true;
    }
    if (primary != nullptr) {
      if (first_confirmed == n) first_confirmed = k;
      if (rec.target_index >= 0) {
        ++m.assoc_frames;
        if (took_detection) ++m.assoc_correct;
      }
      const double e_rb = primary->rb_m - truth.rb_m;
      const double e_drb = primary->drb_mps - truth.drb_mps;
      se_rb += e_rb * e_rb;
      se_drb += e_drb * e_drb;
      ++m.rmse_frames;
    }
    if (first_confirmed < k) {
      ++m.coverage_frames;
      if (covered) ++m.covered_frames;
    }
  }
  m.association_accuracy = ratio(m.assoc_correct, m.assoc_frames);
  m.coverage = first_confirmed < n ? ratio(m.covered_frames, m.coverage_frames) : kNaN;
  m.rb_rmse_m = m.rmse_frames > 0 ? std::sqrt(se_rb / static_cast<double>(m.rmse_frames)) : kNaN;
  m.drb_rmse_mps = m.rmse_frames > 0 ? std::sqrt(se_drb / static_cast<double>(m.rmse_frames)) : kNaN;
  m.time_to_confirm_s = first_confirmed < n ? run.truth[first_confirmed].t_s : kNaN;
  return m;
}

PclSummary summarise_pcl(const std::vector<PclRunMetrics>& runs, std::uint64_t budget_ns) {
  PclSummary s;
  s.runs = runs.size();
  std::vector<std::uint64_t> steps;
  std::size_t acc_num = 0, acc_den = 0, cov_num = 0, cov_den = 0;
  for (const PclRunMetrics& r : runs) {
    acc_num += r.assoc_correct;
    acc_den += r.assoc_frames;
    cov_num += r.covered_frames;
    cov_den += r.coverage_frames;
    if (r.target_tracks == 0) ++s.runs_never_confirmed;
    if (r.false_tracks > 0) ++s.runs_with_false_track;
    s.total_false_tracks += r.false_tracks;
    s.detections += r.detections;
    s.cut_by_adapter += r.cut_by_adapter;
    s.cut_by_sensor += r.cut_by_sensor;
    s.refused_starts += r.refused_starts;
    s.dropped_starts += r.dropped_starts;
    s.max_tracks_in_table = std::max(s.max_tracks_in_table, r.max_tracks_in_table);
    s.frames_over_capacity += r.frames_over_capacity;
    s.frames_refused += r.frames_refused;
    steps.insert(steps.end(), r.step_ns.begin(), r.step_ns.end());
  }
  s.association_accuracy = mean_ci95_of(runs, &PclRunMetrics::association_accuracy);
  s.coverage = mean_ci95_of(runs, &PclRunMetrics::coverage);
  s.false_tracks = mean_ci95_of(runs, &PclRunMetrics::false_tracks);
  s.rb_rmse_m = mean_ci95_of(runs, &PclRunMetrics::rb_rmse_m);
  s.drb_rmse_mps = mean_ci95_of(runs, &PclRunMetrics::drb_rmse_mps);
  s.time_to_confirm_s = mean_ci95_of(runs, &PclRunMetrics::time_to_confirm_s);
  s.pooled_accuracy = ratio(acc_num, acc_den);
  s.pooled_coverage = ratio(cov_num, cov_den);
  s.timing = summarise_step_times(steps, budget_ns);
  return s;
}

}  // namespace kestrel::sim
