// SPDX-License-Identifier: Apache-2.0
// Paper 000's EKF-CA on the fixed-point scalars (docs/fixed-point.md):
// "ekf-ca-q31_32" (the Cortex-M0+ board's tracker) and "ekf-ca-q23_40", with
// the same sensor, initiation, management and options as "ekf-ca"
// (filters/ekf_ca.hpp). The command line's doubles (--qj, --gate-d2) are
// converted once when the tracker is built, exactly (FixedPoint::from_double
// works on the bits of the double); a board takes constexpr constants.
#pragma once

#include <cstdint>
#include <vector>

#include "filters/filter_registry.hpp"

namespace kestrel::sim {

FilterSetup ekf_ca_q31_32_setup(const FilterOptions& options);
FilterSetup ekf_ca_q23_40_setup(const FilterOptions& options);
StreamRunResult run_ekf_ca_q31_32(StreamInput stream, const FilterOptions& options,
                                  std::uint64_t budget_ns);
StreamRunResult run_ekf_ca_q23_40(StreamInput stream, const FilterOptions& options,
                                  std::uint64_t budget_ns);

}  // namespace kestrel::sim
