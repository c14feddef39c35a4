// SPDX-License-Identifier: Apache-2.0
// Paper 001's filters (UKF, CDKF, SR-UKF, SR-CDKF, CRPF) as radar trackers:
// the same CA-2D model, polar radar, two-point initiator and track
// management as EKF-CA, with only the filter changed.
#pragma once

#include <cstdint>

#include "filters/filter_registry.hpp"

namespace kestrel::sim {

FilterSetup ukf_setup(const FilterOptions& options);
FilterSetup ukf_f32_setup(const FilterOptions& options);
FilterSetup cdkf_setup(const FilterOptions& options);
FilterSetup cdkf_f32_setup(const FilterOptions& options);
FilterSetup sr_ukf_setup(const FilterOptions& options);
FilterSetup sr_ukf_f32_setup(const FilterOptions& options);
FilterSetup sr_cdkf_setup(const FilterOptions& options);
FilterSetup sr_cdkf_f32_setup(const FilterOptions& options);
FilterSetup crpf100_setup(const FilterOptions& options);
FilterSetup crpf100_f32_setup(const FilterOptions& options);

StreamRunResult run_ukf(StreamInput stream, const FilterOptions& options, std::uint64_t budget_ns);
StreamRunResult run_ukf_f32(StreamInput stream, const FilterOptions& options, std::uint64_t budget_ns);
StreamRunResult run_cdkf(StreamInput stream, const FilterOptions& options, std::uint64_t budget_ns);
StreamRunResult run_cdkf_f32(StreamInput stream, const FilterOptions& options, std::uint64_t budget_ns);
StreamRunResult run_sr_ukf(StreamInput stream, const FilterOptions& options, std::uint64_t budget_ns);
StreamRunResult run_sr_ukf_f32(StreamInput stream, const FilterOptions& options, std::uint64_t budget_ns);
StreamRunResult run_sr_cdkf(StreamInput stream, const FilterOptions& options, std::uint64_t budget_ns);
StreamRunResult run_sr_cdkf_f32(StreamInput stream, const FilterOptions& options, std::uint64_t budget_ns);
StreamRunResult run_crpf100(StreamInput stream, const FilterOptions& options, std::uint64_t budget_ns);
StreamRunResult run_crpf100_f32(StreamInput stream, const FilterOptions& options, std::uint64_t budget_ns);

}  // namespace kestrel::sim
