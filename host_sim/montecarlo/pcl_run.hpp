// SPDX-License-Identifier: Apache-2.0
// One PCL run through the board loop (docs/tracking.md): the scenario's wire
// frames are encoded into a byte stream and driven exactly as a board drives
// them, host::StreamFileFeed -> hal::PclAdapter (Doppler to range rate, the
// over-capacity rule) -> Tracker::step (the ready-made PCL tracker of
// core/include/kestrel/tracking/pcl_tracker.hpp) -> host::MemorySink, inside
// hal::Runner and timed by host::SteadyClock. Per frame it keeps the reports
// with each chosen candidate mapped back to its index in the wire frame, so
// the metrics can tell whether the target's own detection was used.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "kestrel/hal/runner.hpp"
#include "kestrel/status.hpp"
#include "kestrel/tracking/pcl_tracker.hpp"
#include "pipeline/tracker_policies.hpp"
#include "scenarios/pcl002.hpp"

namespace kestrel::sim {

/// One confirmed track's report in one frame, in SI units.
struct PclTrackRow {
  std::uint32_t id = 0;          ///< Stable track id.
  bool associated = false;       ///< Updated by a candidate in this frame.
  int frame_index = -1;          ///< That candidate's index in the wire frame, -1 if none.
  double rb_m = 0.0;             ///< Estimated bistatic range, m.
  double drb_mps = 0.0;          ///< Estimated range rate, m/s.
  double p_rr = 0.0, p_rd = 0.0, p_dd = 0.0;  ///< Covariance (m^2, m^2/s, m^2/s^2).
  double nis = 0.0;              ///< NIS of this frame's association (NaN if none).
  double test_ratio = 0.0;       ///< nis / gate threshold of the latest association.
  std::uint16_t age = 0, hits = 0, misses = 0;
  bool has_prediction = false;   ///< It was reported in the previous frame too.
  double pred_rb_m = 0.0;        ///< F(dt) x of its previous report: the predicted Rb, m.
  double pred_drb_mps = 0.0;     ///< ... and range rate, m/s.
};

struct PclFrameOutcome {
  Status status = Status::kOk;   ///< Runner::poll_once() result.
  bool stepped = false;          ///< Reached Tracker::step.
  std::uint64_t step_ns = 0;     ///< Adapter + step time, ns.
  double t_s = 0.0;              ///< The frame's wire time, s (NaN if it did not reach the tracker).
  std::size_t scan_count = 0;    ///< Candidates the tracker saw.
  int target_index = -1;         ///< The target's detection in the wire frame, -1 if none or unknown.
  bool target_in_scan = false;   ///< The target's detection survived the adapter's cut.
  std::uint16_t refused_starts = 0;  ///< Candidates the initiator refused (zero-Doppler veto).
  std::uint16_t dropped_starts = 0;  ///< Candidates with no free table slot to start a track.
  std::size_t tracks_in_table = 0;   ///< Tentative + confirmed tracks after the step.
  std::vector<PclTrackRow> tracks;  ///< Confirmed tracks reported.
};

struct PclRunOutput {
  std::vector<PclFrameOutcome> frames;  ///< One per wire frame, in order.
  hal::RunnerStats stats;
};

/// The tracker parameters that match a scenario's sensor: carrier,
/// sigma_Rb, sigma_fD, and for the policies that read them P_D and the
/// clutter density (the false-alarm rate a sensor's CFAR is set for); the
/// track-management defaults are PclTrackerParams'.
PclTrackerParams pcl_params_for(const PclScenarioParams& scenario);

/// Run the PCL tracker composed of `policies` with `params` over the run's
/// frames. The scan capacity is the scenario's (32 or 64; others throw
/// std::invalid_argument).
PclRunOutput run_pcl(const PclScenarioRun& run, const PclScenarioParams& scenario, const PclTrackerParams& params,
                     const TrackerPolicies& policies, std::uint64_t budget_ns);

/// The same over a PCL byte stream (any bytes: one outcome per Runner
/// frame, malformed or refused ones included, until the stream is used
/// up). `reference` names the target's candidate in each frame it holds,
/// found by the frame's content, so frames dropped, repeated or re-timed
/// keep it.
PclRunOutput run_pcl_stream(std::vector<std::uint8_t> stream, const std::vector<PclFrameRecord>& reference,
                            const PclScenarioParams& scenario, const PclTrackerParams& params,
                            const TrackerPolicies& policies, std::uint64_t budget_ns);

/// Names the target's candidate in a frame as it reached the tracker: its
/// index in frame.pcl, or -1 when the frame holds none or it is unknown.
using PclTargetLocator = std::function<int(const hal::Frame&)>;

/// The same with the target's candidate named by `locate` (a replay finds
/// it from its truth CSV, see metrics/replay_scoring.hpp).
PclRunOutput run_pcl_stream(std::vector<std::uint8_t> stream, const PclTargetLocator& locate,
                            const PclScenarioParams& scenario, const PclTrackerParams& params,
                            const TrackerPolicies& policies, std::uint64_t budget_ns);

/// The run's frames as the wire byte stream the sensor sends.
std::vector<std::uint8_t> encode_pcl_stream(const PclScenarioRun& run);

/// Track-table capacity used with each scan capacity.
std::size_t pcl_track_capacity(std::size_t scan_capacity);

}  // namespace kestrel::sim
