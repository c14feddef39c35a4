// SPDX-License-Identifier: Apache-2.0
// Scoring a replayed PCL or sonar stream against its truth CSV
// (csv/sensor_truth_csv.hpp) with the kind's own scorer, the one `run` of a
// PCL or sonar scenario uses (metrics/pcl_metrics.hpp, metrics/sonar_metrics.hpp). A frame is
// matched to the truth row at its wire time, to the microsecond, as a radar
// replay matches its truth; frames that did not reach the tracker (no time)
// or have no truth row are left out of the scored sequence and counted. On
// an unchanged stream with the truth `generate` wrote beside it, every
// figure equals the generating run's, bit for bit.
#pragma once

#include <cstddef>
#include <vector>

#include "csv/sensor_truth_csv.hpp"
#include "metrics/pcl_metrics.hpp"
#include "metrics/sonar_metrics.hpp"
#include "montecarlo/pcl_run.hpp"
#include "montecarlo/sonar_run.hpp"

namespace kestrel::sim {

/// How a replay's frames met its truth.
struct TruthMatch {
  std::size_t matched = 0;       ///< Frames scored: they reached the tracker and have a truth row.
  std::size_t without_time = 0;  ///< Frames that did not reach the tracker.
  std::size_t without_truth = 0; ///< Frames that did, at a time no truth row has.
};

/// The number of `frame_times_s` (NaN ones skipped) that fall on a truth
/// time to the wire microsecond; replay refuses a truth that meets none.
std::size_t count_truth_times(const std::vector<double>& frame_times_s, const std::vector<double>& truth_times_s);

/// Finds the target's detection in a frame: the candidate equal, on the
/// wire, to the one the truth row at the frame's time names.
PclTargetLocator pcl_target_locator(const std::vector<PclTruthRow>& truth);

struct PclReplayScore {
  PclRunMetrics metrics;
  TruthMatch match;
  std::vector<PclTruth> truth_per_frame;  ///< One per outcome frame; NaN where not matched.
};
PclReplayScore score_pcl_replay(const PclRunOutput& out, const std::vector<PclTruthRow>& truth,
                                const PclTolerance& tolerance);

struct SonarReplayScore {
  SonarRunMetrics metrics;
  TruthMatch match;
};
SonarReplayScore score_sonar_replay(const SonarRunOutput& out, const std::vector<SonarTruthRow>& truth);

}  // namespace kestrel::sim
