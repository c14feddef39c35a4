// SPDX-License-Identifier: Apache-2.0
#include "filters/ekf_ca_rr.hpp"

#include <cstdio>
#include <limits>
#include <memory>
#include <utility>

#include "filters/ekf_ca.hpp"
#include "pipeline/stream_run.hpp"

namespace kestrel::sim {

namespace {

template <class Scalar>
StreamRunResult run_typed(StreamInput stream, const FilterOptions& options, std::uint64_t budget_ns) {
  using Tracker = host::BoardRadarTracker<EkfCaRr<Scalar>>;
  // The tracker holds the whole track table: keep it off the stack.
  auto tracker = std::make_unique<Tracker>(make_ekf_ca_rr_tracker<Scalar>(options));
  return run_stream(*tracker, std::move(stream), budget_ns);
}

FilterSetup setup_with(const FilterOptions& options, const char* scalar) {
  const RadarRangeRateTrackerParams p = ekf_ca_rr_params(options);
  // EKF-CA's parameters, plus the range-rate channel.
  FilterSetup s = ekf_ca_setup(options);
  char label[112];
  std::snprintf(label, sizeof label, "EKF-CA-RR (%s), qj %g, srr %g%s", scalar, p.radar.qj, p.sigma_range_rate_mps,
                gate_label(options).c_str());
  s.label = label;
  s.parameters["sigma_range_rate_mps"] = p.sigma_range_rate_mps;
  s.parameters["max_range_rate_mps"] = p.max_range_rate_mps;
  return s;
}

}  // namespace

template <class Scalar>
host::BoardRadarTracker<EkfCaRr<Scalar>> make_ekf_ca_rr_tracker(const FilterOptions& options) {
  const RadarRangeRateTrackerParams p = ekf_ca_rr_params(options);
  const RadarRangeRateTrackerConfig<Scalar> s = radar_range_rate_tracker_config<Scalar>(p);
  // What make_radar_range_rate_tracker() builds, plus the confirmed-track
  // gate, as make_ekf_ca_tracker() does.
  CaMotion<Scalar> motion;
  motion.qj = s.radar.qj;
  CaPolarRadarRangeRate<Scalar> radar;
  radar.sigma_range_m = s.radar.sigma_range_m;
  radar.sigma_bearing_rad = s.radar.sigma_bearing_rad;
  radar.sigma_range_rate_mps = s.sigma_range_rate_mps;
  const auto init = radar_initiator<host::BoardRadarTracker<EkfCaRr<Scalar>>>(radar, s.radar.max_speed_mps,
                                                                               s.radar.init_accel_sigma_mps2, p.radar);
  TrackerConfig<Scalar, 3> config = tracker_config_of<Scalar>(p, s);
  apply_gate_options<Scalar>(options, config);
  host::BoardRadarTracker<EkfCaRr<Scalar>> tracker(EkfCaRr<Scalar>(motion, radar), init, config);
  apply_measurement_noise(tracker, p.radar);  // built without the adaptive noise: refuses a gain
  return tracker;
}

template host::BoardRadarTracker<EkfCaRr<double>> make_ekf_ca_rr_tracker<double>(const FilterOptions&);
template host::BoardRadarTracker<EkfCaRr<float>> make_ekf_ca_rr_tracker<float>(const FilterOptions&);

RadarRangeRateTrackerParams ekf_ca_rr_params(const FilterOptions& options) {
  RadarRangeRateTrackerParams p;
  p.radar = radar_tracker_params(options);
  return p;
}

FilterSetup ekf_ca_rr_setup(const FilterOptions& options) { return setup_with(options, "double"); }
FilterSetup ekf_ca_rr_f32_setup(const FilterOptions& options) { return setup_with(options, "float"); }

StreamRunResult run_ekf_ca_rr(StreamInput stream, const FilterOptions& options,
                              std::uint64_t budget_ns) {
  return run_typed<double>(std::move(stream), options, budget_ns);
}

StreamRunResult run_ekf_ca_rr_f32(StreamInput stream, const FilterOptions& options,
                                  std::uint64_t budget_ns) {
  return run_typed<float>(std::move(stream), options, budget_ns);
}

}  // namespace kestrel::sim
