// SPDX-License-Identifier: Apache-2.0
#include "filters/radar_filter_family.hpp"

#include <memory>
#include <utility>

#include "filters/ekf_ca.hpp"
#include "kestrel/filters/crpf.hpp"
#include "kestrel/filters/sigma_point_filter.hpp"
#include "kestrel/filters/sr_sigma_point_filter.hpp"
#include "kestrel/host/board.hpp"
#include "pipeline/stream_run.hpp"

namespace kestrel::sim {

namespace {

template <class M, class H>
using Crpf100 = Crpf<M, H, 100>;

// EKF-CA's tracker (make_ekf_ca_tracker) with another filter of the same
// models: the filter is the only difference between the registry's radar
// entries. The CRPF keeps its default PRNG seed, so a stream replays to
// the same tracks; Monte Carlo runs differ by their measurement noise.
template <template <class, class> class FilterT, class Scalar>
StreamRunResult run_family(StreamInput stream, const FilterOptions& options, std::uint64_t budget_ns) {
  using Filter = FilterT<CaMotion<Scalar>, CaPolarRadar<Scalar>>;
  const RadarTrackerParams p = radar_tracker_params(options);
  // Built without the adaptive noise: refuses a gain.
  const auto tracker = make_sim_radar_tracker<host::BoardRadarTracker<Filter>>(ca_polar_filter<Filter>(p), options, p);
  return run_stream(*tracker, std::move(stream), budget_ns);
}

}  // namespace

FilterSetup ukf_setup(const FilterOptions& o) { return radar_filter_setup(o, "UKF", "double"); }
FilterSetup ukf_f32_setup(const FilterOptions& o) { return radar_filter_setup(o, "UKF", "float"); }
FilterSetup cdkf_setup(const FilterOptions& o) { return radar_filter_setup(o, "CDKF", "double"); }
FilterSetup cdkf_f32_setup(const FilterOptions& o) { return radar_filter_setup(o, "CDKF", "float"); }
FilterSetup sr_ukf_setup(const FilterOptions& o) { return radar_filter_setup(o, "SR-UKF", "double"); }
FilterSetup sr_ukf_f32_setup(const FilterOptions& o) { return radar_filter_setup(o, "SR-UKF", "float"); }
FilterSetup sr_cdkf_setup(const FilterOptions& o) { return radar_filter_setup(o, "SR-CDKF", "double"); }
FilterSetup sr_cdkf_f32_setup(const FilterOptions& o) { return radar_filter_setup(o, "SR-CDKF", "float"); }
FilterSetup crpf100_setup(const FilterOptions& o) { return radar_filter_setup(o, "CRPF-100", "double"); }
FilterSetup crpf100_f32_setup(const FilterOptions& o) { return radar_filter_setup(o, "CRPF-100", "float"); }

StreamRunResult run_ukf(StreamInput s, const FilterOptions& o, std::uint64_t b) {
  return run_family<Ukf, double>(std::move(s), o, b);
}
StreamRunResult run_ukf_f32(StreamInput s, const FilterOptions& o, std::uint64_t b) {
  return run_family<Ukf, float>(std::move(s), o, b);
}
StreamRunResult run_cdkf(StreamInput s, const FilterOptions& o, std::uint64_t b) {
  return run_family<Cdkf, double>(std::move(s), o, b);
}
StreamRunResult run_cdkf_f32(StreamInput s, const FilterOptions& o, std::uint64_t b) {
  return run_family<Cdkf, float>(std::move(s), o, b);
}
StreamRunResult run_sr_ukf(StreamInput s, const FilterOptions& o, std::uint64_t b) {
  return run_family<SrUkf, double>(std::move(s), o, b);
}
StreamRunResult run_sr_ukf_f32(StreamInput s, const FilterOptions& o, std::uint64_t b) {
  return run_family<SrUkf, float>(std::move(s), o, b);
}
StreamRunResult run_sr_cdkf(StreamInput s, const FilterOptions& o, std::uint64_t b) {
  return run_family<SrCdkf, double>(std::move(s), o, b);
}
StreamRunResult run_sr_cdkf_f32(StreamInput s, const FilterOptions& o, std::uint64_t b) {
  return run_family<SrCdkf, float>(std::move(s), o, b);
}
StreamRunResult run_crpf100(StreamInput s, const FilterOptions& o, std::uint64_t b) {
  return run_family<Crpf100, double>(std::move(s), o, b);
}
StreamRunResult run_crpf100_f32(StreamInput s, const FilterOptions& o, std::uint64_t b) {
  return run_family<Crpf100, float>(std::move(s), o, b);
}

}  // namespace kestrel::sim
