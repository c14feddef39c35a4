// SPDX-License-Identifier: Apache-2.0
// EKF-CA with range rate on the host board
// (kestrel/tracking/radar_range_rate_tracker.hpp): double ("ekf-ca-rr") and
// float ("ekf-ca-rr-f32"). It takes radar frames whose plots all carry a
// range rate (scenarios s1rr, s2rr); hal::RadarAdapter refuses any other
// radar frame with kWrongKind. Defaults: EKF-CA's (the S1/S2 sensor of docs/scenarios.md,
// qj 1.6) plus srr 0.5 m/s, the rr scenarios' value (docs/range_rate.md);
// confirmed tracks ungated unless --gate-d2 is given, as for EKF-CA.
#pragma once

#include "filters/filter_registry.hpp"
#include "kestrel/host/board.hpp"
#include "kestrel/tracking/radar_range_rate_tracker.hpp"

namespace kestrel::sim {

/// The core parameters the options resolve to.
RadarRangeRateTrackerParams ekf_ca_rr_params(const FilterOptions& options);

/// The host board's EKF-CA range-rate tracker for these options (double and
/// float are instantiated).
template <class Scalar>
host::BoardRadarTracker<EkfCaRr<Scalar>> make_ekf_ca_rr_tracker(const FilterOptions& options);

FilterSetup ekf_ca_rr_setup(const FilterOptions& options);
FilterSetup ekf_ca_rr_f32_setup(const FilterOptions& options);
StreamRunResult run_ekf_ca_rr(StreamInput stream, const FilterOptions& options, std::uint64_t budget_ns);
StreamRunResult run_ekf_ca_rr_f32(StreamInput stream, const FilterOptions& options,
                                  std::uint64_t budget_ns);

}  // namespace kestrel::sim
