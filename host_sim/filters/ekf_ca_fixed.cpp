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

/// What make_ekf_ca_tracker() builds for double and float, on Q.
template <class Q>
host::BoardRadarTracker<EkfCa<Q>> make_fixed_tracker(const FilterOptions& options) {
  const RadarTrackerParams p = radar_tracker_params(options);
  const RadarTrackerConfig<Q> s = radar_tracker_config<Q>(p);
  CaMotion<Q> motion;
  motion.qj = s.qj;
  CaPolarRadar<Q> radar;
  radar.sigma_range_m = s.sigma_range_m;
  radar.sigma_bearing_rad = s.sigma_bearing_rad;
  const auto init =
      radar_initiator<host::BoardRadarTracker<EkfCa<Q>>>(radar, s.max_speed_mps, s.init_accel_sigma_mps2, p);
  TrackerConfig<Q, 2> config = tracker_config_of<Q>(p, s);
  apply_gate_options<Q>(options, config);
  host::BoardRadarTracker<EkfCa<Q>> tracker(EkfCa<Q>(motion, radar), init, config);
  apply_measurement_noise(tracker, p);  // built without the adaptive noise: refuses a gain
  return tracker;
}

template <class Q>
StreamRunResult run_typed(StreamInput stream, const FilterOptions& options, std::uint64_t budget_ns) {
  using Tracker = host::BoardRadarTracker<EkfCa<Q>>;
  auto tracker = std::make_unique<Tracker>(make_fixed_tracker<Q>(options));
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
