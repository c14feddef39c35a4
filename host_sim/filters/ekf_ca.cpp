// SPDX-License-Identifier: Apache-2.0
#include "filters/ekf_ca.hpp"

#include <cstdio>
#include <limits>
#include <memory>
#include <utility>

#include "kestrel/host/board.hpp"
#include "pipeline/stream_run.hpp"

namespace kestrel::sim {

namespace {

template <class Scalar>
StreamRunResult run_typed(StreamInput stream, const FilterOptions& options, std::uint64_t budget_ns) {
  using Tracker = SimRadarTracker<EkfCa<Scalar>>;
  // The tracker holds the whole track table: keep it off the stack.
  auto tracker = std::make_unique<Tracker>(make_ekf_ca_tracker<Scalar>(options));
  return run_stream(*tracker, std::move(stream), budget_ns);
}

}  // namespace

template <class Scalar>
SimRadarTracker<EkfCa<Scalar>> make_ekf_ca_tracker(const FilterOptions& options) {
  using T = ScalarTraits<Scalar>;
  const RadarTrackerParams p = radar_tracker_params(options);
  // What make_radar_tracker() builds, plus the confirmed-track gate, which
  // RadarTrackerParams does not carry.
  CaMotion<Scalar> motion;
  motion.qj = T::from_double(p.qj);
  CaPolarRadar<Scalar> radar;
  radar.sigma_range_m = T::from_double(p.sigma_range_m);
  radar.sigma_bearing_rad = T::from_double(p.sigma_bearing_rad);
  const auto init = radar_initiator<SimRadarTracker<EkfCa<Scalar>>>(radar, T::from_double(p.max_speed_mps),
                                                                     T::from_double(p.init_accel_sigma_mps2), p);
  TrackerConfig<Scalar, 2> config = tracker_config_of<Scalar>(p);
  apply_gate_options<Scalar>(options, config);
  SimRadarTracker<EkfCa<Scalar>> tracker(EkfCa<Scalar>(motion, radar), init, config);
  apply_measurement_noise(tracker, p);
  return tracker;
}

template SimRadarTracker<EkfCa<double>> make_ekf_ca_tracker<double>(const FilterOptions&);
template SimRadarTracker<EkfCa<float>> make_ekf_ca_tracker<float>(const FilterOptions&);

FilterSetup radar_filter_setup(const FilterOptions& options, const char* name, const char* scalar) {
  const RadarTrackerParams p = radar_tracker_params(options);
  char label[96];
  std::snprintf(label, sizeof label, "%s (%s), qj %g%s", name, scalar, p.qj, gate_label(options).c_str());
  FilterSetup setup{label,
                    {}};
  add_radar_parameters(p, setup.parameters);
  // An ungated run has no threshold: JSON null.
  add_gate_parameters(options, setup.parameters);
  return setup;
}

FilterSetup ekf_ca_setup(const FilterOptions& options) { return radar_filter_setup(options, "EKF-CA", "double"); }
FilterSetup ekf_ca_f32_setup(const FilterOptions& options) { return radar_filter_setup(options, "EKF-CA", "float"); }

StreamRunResult run_ekf_ca(StreamInput stream, const FilterOptions& options, std::uint64_t budget_ns) {
  return run_typed<double>(std::move(stream), options, budget_ns);
}

StreamRunResult run_ekf_ca_f32(StreamInput stream, const FilterOptions& options,
                               std::uint64_t budget_ns) {
  return run_typed<float>(std::move(stream), options, budget_ns);
}

}  // namespace kestrel::sim
