// Paper 000's EKF-CA on the host board (kestrel/tracking/radar_tracker.hpp):
// double ("ekf-ca") and float ("ekf-ca-f32", the Cortex-M4F build's scalar).
// Defaults are SPEC section 9: sr 3 m, sb 0.30 deg, qj 1.6 m^2/s^5.
#pragma once

#include "filters/filter_registry.hpp"
#include "kestrel/tracking/radar_tracker.hpp"

namespace kestrel::sim {

/// The core parameters the options resolve to.
RadarTrackerParams ekf_ca_params(const FilterOptions& options);

FilterSetup ekf_ca_setup(const FilterOptions& options);
FilterSetup ekf_ca_f32_setup(const FilterOptions& options);
StreamRunResult run_ekf_ca(std::vector<std::uint8_t> stream, const FilterOptions& options, std::uint64_t budget_ns);
StreamRunResult run_ekf_ca_f32(std::vector<std::uint8_t> stream, const FilterOptions& options,
                               std::uint64_t budget_ns);

}  // namespace kestrel::sim
