// SPDX-License-Identifier: Apache-2.0
// The radar IMM (kestrel/filters/imm_radar.hpp: CV-2D, CA-2D and CT-2D
// EKFs, seen as CA-2D) on the host board, for kestrel-sim: "imm" (double)
// and "imm-f32" (float, the Cortex-M4F scalar). Same sensor, two-point
// initiation and management as "ekf-ca" (filters/ekf_ca.hpp); confirmed
// tracks ungated unless --gate-d2 is given. --qj sets the CA mode's qj;
// --imm KEY=VALUE overrides any parameter:
//   cv_sa, ca_qj, ct_sa, ct_sw          mode noise (RadarImmParams)
//   p_stay                              every p_ii, the rest spread evenly
//   pIJ (I, J in 0..2: 0 CV, 1 CA, 2 CT) one entry of the switching matrix
//   switch_period                       the period the matrix is for, s (0: per predict)
//   mu_cv, mu_ca, mu_ct                 initial mode probabilities
//   min_prob, pad_a, pad_w              floor and padding sigmas
#pragma once

#include <cstdint>

#include "filters/ekf_ca.hpp"
#include "filters/filter_registry.hpp"
#include "kestrel/filters/imm_radar.hpp"
#include "kestrel/host/board.hpp"

namespace kestrel::sim {

/// The defaults of kestrel-sim's IMM (docs/imm.md) with the options applied.
/// Throws std::invalid_argument for an unknown key, a malformed value or a
/// parameter set that is not valid.
RadarImmParams imm_params(const FilterOptions& options);

/// The host board's IMM tracker (double and float are instantiated).
template <class Scalar>
SimRadarTracker<RadarImm<Scalar>> make_imm_tracker(const FilterOptions& options);

FilterSetup imm_setup(const FilterOptions& options);
FilterSetup imm_f32_setup(const FilterOptions& options);
StreamRunResult run_imm(StreamInput stream, const FilterOptions& options, std::uint64_t budget_ns);
StreamRunResult run_imm_f32(StreamInput stream, const FilterOptions& options, std::uint64_t budget_ns);

}  // namespace kestrel::sim
