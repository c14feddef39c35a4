// SPDX-License-Identifier: Apache-2.0
// Per-step CSV of one run (written by `run` for run 0 and by `replay`): one
// row per scored frame with truth, the plot the scored track used, the
// estimate and its error statistics:
//   time_s,k,truth_x_m,truth_y_m,meas_x_m,meas_y_m,est_x_m,est_y_m,
//   track_id,error_m,nees,nis,lost,confirmed_tracks
// meas_* is empty when the scored track coasted; est_*, track_id, error_m
// and nees are empty when no confirmed track existed (a lost frame).
#pragma once

#include <filesystem>
#include <vector>

#include "metrics/scoring.hpp"
#include "scenarios/scenario.hpp"

namespace kestrel::sim {

/// @param frames the frames of the run in stream order (indexed by ScoredStep::k).
void write_step_csv(const std::filesystem::path& path, const std::vector<ScoredStep>& steps,
                    const std::vector<MeasurementFrame>& frames, double loss_threshold_m);

}  // namespace kestrel::sim
