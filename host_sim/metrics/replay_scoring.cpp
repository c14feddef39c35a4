// SPDX-License-Identifier: Apache-2.0
#include "metrics/replay_scoring.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <optional>

#include "stream/quantise.hpp"

namespace kestrel::sim {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Truth row index by wire microsecond.
template <class Row>
std::map<std::int64_t, std::size_t> index_by_time(const std::vector<Row>& rows) {
  std::map<std::int64_t, std::size_t> by_time;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (const auto us = try_wire_time_us(rows[i].truth.t_s)) by_time.emplace(*us, i);
  }
  return by_time;
}

/// The truth row at a frame's time, if any (NaN: the frame has no time).
template <class Row>
const Row* row_at(const std::map<std::int64_t, std::size_t>& by_time, const std::vector<Row>& rows, double t_s) {
  if (!std::isfinite(t_s)) return nullptr;
  const auto us = try_wire_time_us(t_s);
  if (!us) return nullptr;
  const auto it = by_time.find(*us);
  return it == by_time.end() ? nullptr : &rows[it->second];
}

}  // namespace

std::size_t count_truth_times(const std::vector<double>& frame_times_s, const std::vector<double>& truth_times_s) {
  std::map<std::int64_t, bool> truth;
  for (const double t : truth_times_s) {
    if (const auto us = try_wire_time_us(t)) truth.emplace(*us, true);
  }
  std::size_t n = 0;
  for (const double t : frame_times_s) {
    if (!std::isfinite(t)) continue;
    const auto us = try_wire_time_us(t);
    if (us && truth.count(*us) != 0) ++n;
  }
  return n;
}

PclTargetLocator pcl_target_locator(const std::vector<PclTruthRow>& truth) {
  // Shared so that copies of the std::function stay cheap.
  auto by_time = std::make_shared<std::map<std::int64_t, hal::PclCandidate>>();
  for (const PclTruthRow& r : truth) {
    if (!r.detection) continue;
    if (const auto us = try_wire_time_us(r.truth.t_s)) by_time->emplace(*us, *r.detection);
  }
  return [by_time](const hal::Frame& frame) {
    const auto it = by_time->find(frame.t_us);
    if (it == by_time->end()) return -1;
    const hal::PclCandidate& want = it->second;
    for (std::size_t i = 0; i < frame.count && i < hal::kMaxPclCandidates; ++i) {
      const hal::PclCandidate& c = frame.pcl[i];
      if (c.bistatic_range_mm == want.bistatic_range_mm && c.doppler_mhz == want.doppler_mhz &&
          c.snr_cdb == want.snr_cdb) {
        return static_cast<int>(i);
      }
    }
    return -1;
  };
}

PclReplayScore score_pcl_replay(const PclRunOutput& out, const std::vector<PclTruthRow>& truth,
                                const PclTolerance& tolerance) {
  const auto by_time = index_by_time(truth);
  PclReplayScore score;
  PclScenarioRun run;
  PclRunOutput scored;
  scored.stats = out.stats;
  PclTruth none;
  none.t_s = none.rb_m = none.drb_mps = none.fd_hz = kNaN;
  for (const PclFrameOutcome& f : out.frames) {
    const PclTruthRow* row = f.stepped ? row_at(by_time, truth, f.t_s) : nullptr;
    score.truth_per_frame.push_back(row != nullptr ? row->truth : none);
    if (!f.stepped) {
      ++score.match.without_time;
      continue;
    }
    if (row == nullptr) {
      ++score.match.without_truth;
      continue;
    }
    ++score.match.matched;
    run.truth.push_back(row->truth);
    PclFrameRecord rec;
    rec.target_index = f.target_index;  // found in this frame by the locator
    rec.detected = row->detected;
    run.frames.push_back(rec);
    scored.frames.push_back(f);
  }
  score.metrics = score_pcl_run(run, scored, tolerance);
  return score;
}

SonarReplayScore score_sonar_replay(const SonarRunOutput& out, const std::vector<SonarTruthRow>& truth) {
  const auto by_time = index_by_time(truth);
  SonarReplayScore score;
  SonarScenarioRun run;
  SonarRunOutput scored;
  scored.stats = out.stats;
  for (const SonarFrameOutcome& f : out.frames) {
    if (!f.stepped) {
      ++score.match.without_time;
      continue;
    }
    const SonarTruthRow* row = row_at(by_time, truth, f.t_s);
    if (row == nullptr) {
      ++score.match.without_truth;
      continue;
    }
    ++score.match.matched;
    run.truth.push_back(row->truth);
    SonarFrameRecord rec;
    // The scorer reads each arrival's channel and outlier flag only.
    for (std::uint32_t bit = 0; bit < 32; ++bit) {
      if ((row->channels & (1u << bit)) == 0) continue;
      SonarArrivalRecord a;
      a.beacon = static_cast<std::uint8_t>(bit / 2);
      a.path = static_cast<hal::ToaPath>(bit % 2);
      a.outlier = (row->outlier_channels & (1u << bit)) != 0;
      rec.arrivals.push_back(a);
    }
    run.frames.push_back(rec);
    scored.frames.push_back(f);
  }
  score.metrics = score_sonar_run(run, scored);
  return score;
}

}  // namespace kestrel::sim
