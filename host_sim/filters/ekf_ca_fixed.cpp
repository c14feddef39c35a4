// SPDX-License-Identifier: Apache-2.0
#include "filters/ekf_ca_fixed.hpp"

#include <cstdio>
#include <limits>
#include <memory>
#include <utility>

#include "filters/ekf_ca.hpp"
#include "kestrel/host/board.hpp"
#include "kestrel/scalar/fixed_point_eigen.hpp"
#include "kestrel/tracking/radar_tracker.hpp"
#include "pipeline/stream_run.hpp"

namespace kestrel::sim {

namespace {

/// The EKF-CA tracker of make_ekf_ca_tracker() on Q, as a board builds it
/// (without the adaptive noise: it refuses a gain).
template <class Q>
StreamRunResult run_typed(StreamInput stream, const FilterOptions& options, std::uint64_t budget_ns) {
  const RadarTrackerParams p = radar_tracker_params(options);
  const auto tracker =
      make_sim_radar_tracker<host::BoardRadarTracker<EkfCa<Q>>>(ca_polar_filter<EkfCa<Q>>(p), options, p);
  return run_stream(*tracker, std::move(stream), budget_ns);
}

FilterSetup setup_with(const FilterOptions& options, const char* scalar) {
  return radar_filter_setup(options, "EKF-CA", scalar);
}

}  // namespace

FilterSetup ekf_ca_q31_32_setup(const FilterOptions& options) { return setup_with(options, "Q31.32"); }
FilterSetup ekf_ca_q23_40_setup(const FilterOptions& options) { return setup_with(options, "Q23.40"); }

StreamRunResult run_ekf_ca_q31_32(StreamInput stream, const FilterOptions& options,
                                  std::uint64_t budget_ns) {
  return run_typed<Q31_32>(std::move(stream), options, budget_ns);
}

StreamRunResult run_ekf_ca_q23_40(StreamInput stream, const FilterOptions& options,
                                  std::uint64_t budget_ns) {
  return run_typed<Q23_40>(std::move(stream), options, budget_ns);
}

}  // namespace kestrel::sim
