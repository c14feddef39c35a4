#include "filters/ekf_ca.hpp"

#include <cstdio>
#include <memory>
#include <utility>

#include "kestrel/host/board.hpp"
#include "pipeline/stream_run.hpp"

namespace kestrel::sim {

namespace {

template <class Scalar>
StreamRunResult run_typed(std::vector<std::uint8_t> stream, const FilterOptions& options, std::uint64_t budget_ns) {
  using Tracker = host::BoardRadarTracker<EkfCa<Scalar>>;
  // The tracker holds the whole track table: keep it off the stack.
  auto tracker = std::make_unique<Tracker>(
      make_radar_tracker<Scalar, host::kMaxTracks, host::kMaxPlots>(ekf_ca_params(options)));
  return run_stream(*tracker, std::move(stream), budget_ns);
}

FilterSetup setup_with(const FilterOptions& options, const char* scalar) {
  const RadarTrackerParams p = ekf_ca_params(options);
  char label[96];
  std::snprintf(label, sizeof label, "EKF-CA (%s), qj %g", scalar, p.qj);
  return FilterSetup{label,
                     {{"qj", p.qj},
                      {"sigma_range_m", p.sigma_range_m},
                      {"sigma_bearing_rad", p.sigma_bearing_rad},
                      {"init_accel_sigma_mps2", p.init_accel_sigma_mps2},
                      {"confirm_m", p.confirm_m},
                      {"confirm_n", p.confirm_n},
                      {"max_coast_misses", p.max_coast_misses}}};
}

}  // namespace

RadarTrackerParams ekf_ca_params(const FilterOptions& options) {
  RadarTrackerParams p;  // SPEC section 9 sensor, paper 000's qj = 1.6
  if (options.qj.has_value()) p.qj = *options.qj;
  return p;
}

FilterSetup ekf_ca_setup(const FilterOptions& options) { return setup_with(options, "double"); }
FilterSetup ekf_ca_f32_setup(const FilterOptions& options) { return setup_with(options, "float"); }

StreamRunResult run_ekf_ca(std::vector<std::uint8_t> stream, const FilterOptions& options, std::uint64_t budget_ns) {
  return run_typed<double>(std::move(stream), options, budget_ns);
}

StreamRunResult run_ekf_ca_f32(std::vector<std::uint8_t> stream, const FilterOptions& options,
                               std::uint64_t budget_ns) {
  return run_typed<float>(std::move(stream), options, budget_ns);
}

}  // namespace kestrel::sim
