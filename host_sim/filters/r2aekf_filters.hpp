// SPDX-License-Identifier: Apache-2.0
// Paper 000's R2-AEKF (kestrel/filters/r2aekf.hpp) on the host board, for
// kestrel-sim: "r2aekf" (default mode, the corrections of docs/r2aekf.md), "r2aekf-paper"
// (the printed equations) and "r2aekf-f32" (default mode in float, the
// Cortex-M4F scalar). Same sensor, initiation and management as "ekf-ca"
// (filters/ekf_ca.hpp): the S1/S2 sensor of docs/scenarios.md, qj 1.6 (--qj overrides it, as the
// paper uses one qj for both filters), confirmed tracks ungated unless
// --gate-d2 is given.
//
// Beyond the registry entries this file offers what the R2-AEKF study
// (cli/cmd_r2aekf.cpp) needs: a run with any config, and a run that also
// records the filter's scales and indicators after every update (the
// per-step scale CSV, paper fig. 4).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "filters/filter_registry.hpp"
#include "kestrel/filters/r2aekf.hpp"
#include "kestrel/host/board.hpp"
#include "kestrel/tracking/radar_tracker.hpp"

namespace kestrel::sim {

/// The host board's R2-AEKF tracker (sensor, initiation and gate as
/// make_ekf_ca_tracker) with the given adaptation config.
template <class Scalar>
host::BoardRadarTracker<R2AekfCa<Scalar>> make_r2aekf_tracker(const FilterOptions& options,
                                                              const R2AekfConfig<Scalar>& config);

FilterSetup r2aekf_setup(const FilterOptions& options);
FilterSetup r2aekf_paper_setup(const FilterOptions& options);
FilterSetup r2aekf_f32_setup(const FilterOptions& options);
FilterSetup r2aekf_q31_32_setup(const FilterOptions& options);
StreamRunResult run_r2aekf(StreamInput stream, const FilterOptions& options, std::uint64_t budget_ns);
StreamRunResult run_r2aekf_paper(StreamInput stream, const FilterOptions& options,
                                 std::uint64_t budget_ns);
StreamRunResult run_r2aekf_f32(StreamInput stream, const FilterOptions& options,
                               std::uint64_t budget_ns);
StreamRunResult run_r2aekf_q31_32(StreamInput stream, const FilterOptions& options,
                                  std::uint64_t budget_ns);

/// Parameters of a config, by name (summary.json, study tables).
FilterSetup r2aekf_setup_for(const FilterOptions& options, const R2AekfConfig<double>& config, const char* label);

/// A FilterEntry (kind radar) that runs the R2-AEKF in double with `config`.
/// Function pointers cannot carry a config, so the entry reads one
/// process-wide study config: call this before a Monte Carlo and do not call
/// it again while one runs (the runs only read it). Not in the registry.
const FilterEntry& r2aekf_study_entry(const R2AekfConfig<double>& config);

/// What the filter said about one update (docs/r2aekf.md steps 2-7), as recorded
/// by the logging run.
struct ScaleSample {
  double time_s = 0.0;         ///< Frame time, s (filled by the join with the reports).
  std::uint32_t track_id = 0;  ///< Track it belongs to (filled by the join).
  double x_m = 0.0;            ///< Updated x position, m (the join key).
  double y_m = 0.0;            ///< Updated y position, m (the join key).
  double s_r_range = 1.0;      ///< sRr (eq. 11).
  double s_r_bearing = 1.0;    ///< sRb (eq. 11).
  double s_q_axial = 1.0;      ///< sQax (eq. 16).
  double s_q_lateral = 1.0;    ///< sQlat (eq. 16).
  double s_q_x = 1.0;          ///< M(0,0): x-axis Q factor (eq. 17).
  double s_q_y = 1.0;          ///< M(1,1): y-axis Q factor (eq. 17).
  double e_range = 0.0;        ///< Normalised range innovation (eq. 8).
  double e_bearing = 0.0;      ///< Normalised bearing innovation (eq. 8).
  double spread_range = 0.0;   ///< What eq. 10 used for range.
  double spread_bearing = 0.0; ///< What eq. 10 used for bearing.
  double d2 = 0.0;             ///< Total NIS with R_k.
  bool robust_gated = false;   ///< rho applied.
  double phi_axial = 0.0;      ///< Axial manoeuvre indicator.
  double phi_lateral = 0.0;    ///< Lateral manoeuvre indicator.
};

/// A run that also records every update's scales. `scales` holds the
/// samples matched to the published reports (time and track id filled in),
/// in frame order; samples of updates that were never reported (tentative
/// tracks) are dropped.
struct LoggedR2AekfRun {
  StreamRunResult stream;
  std::vector<ScaleSample> scales;
};

LoggedR2AekfRun run_r2aekf_logged(std::vector<std::uint8_t> stream, const FilterOptions& options,
                                  const R2AekfConfig<double>& config, std::uint64_t budget_ns);

/// Per-step scale CSV: time_s,track_id,s_r_range,s_r_bearing,s_q_axial,
/// s_q_lateral,s_q_x,s_q_y,e_range,e_bearing,spread_range,spread_bearing,d2,
/// robust_gated,phi_axial,phi_lateral.
void write_scale_csv(const std::filesystem::path& path, const std::vector<ScaleSample>& scales);

}  // namespace kestrel::sim
