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

/// make_ekf_ca_tracker's tracker, off the stack.
template <class Scalar>
std::unique_ptr<SimRadarTracker<EkfCa<Scalar>>> ekf_ca_tracker_on_heap(const FilterOptions& options) {
  const RadarTrackerParams p = radar_tracker_params(options);
  return make_sim_radar_tracker<SimRadarTracker<EkfCa<Scalar>>>(ca_polar_filter<EkfCa<Scalar>>(p), options, p);
}

template <class Scalar>
StreamRunResult run_typed(StreamInput stream, const FilterOptions& options, std::uint64_t budget_ns) {
  return run_stream(*ekf_ca_tracker_on_heap<Scalar>(options), std::move(stream), budget_ns);
}

}  // namespace

template <class Scalar>
SimRadarTracker<EkfCa<Scalar>> make_ekf_ca_tracker(const FilterOptions& options) {
  return *ekf_ca_tracker_on_heap<Scalar>(options);
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
