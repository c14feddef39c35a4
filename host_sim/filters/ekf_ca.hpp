// SPDX-License-Identifier: Apache-2.0
// Paper 000's EKF-CA on the host board (kestrel/tracking/radar_tracker.hpp):
// double ("ekf-ca") and float ("ekf-ca-f32", the Cortex-M4F build's scalar).
// Defaults are the S1/S2 sensor of docs/scenarios.md: sr 3 m, sb 0.30 deg, qj 1.6 m^2/s^5; confirmed
// tracks ungated unless a gate is given (see FilterOptions); every parameter
// by key in filters/settings.hpp.
#pragma once

#include "filters/filter_registry.hpp"
#include "filters/settings.hpp"
#include "kestrel/host/board.hpp"
#include "kestrel/tracking/radar_tracker.hpp"

namespace kestrel::sim {

/// Label and parameters of a radar filter on the CA-2D model and the
/// polar radar ("UKF (float), qj 160"); every such filter shares them.
FilterSetup radar_filter_setup(const FilterOptions& options, const char* name, const char* scalar);

/// kestrel-sim's radar tracker for a filter with a scaled update (EKF-CA,
/// the IMM): the host board's capacities with the adaptive measurement
/// noise (AdaptiveMeasurementNoise) and the initiation's second hypotheses
/// (TwoPointHypothesesInitiator) compiled in, so that the robust_noise_gain
/// and seed_* keys act; with their defaults it gives what the board's
/// tracker (host::BoardRadarTracker) gives, bit for bit (golden tests).
/// Boards build the nominal one.
template <class Filter>
using SimRadarTracker =
    Tracker<Filter, TwoPointHypothesesInitiator<typename Filter::MotionModel, typename Filter::MeasurementModel>,
            host::kMaxTracks, host::kMaxPlots, NearestNeighbour, MOfN, AdaptiveMeasurementNoise>;

/// A filter of the CA-2D model and the polar radar (EkfCa, Ukf, Crpf,
/// R2AekfCa with its config as `extra`, ...) with p's qj and sensor
/// sigmas, in the filter's scalar.
template <class Filter, class... Extra>
Filter ca_polar_filter(const RadarTrackerParams& p, const Extra&... extra) {
  using Scalar = typename Filter::Scalar;
  const RadarTrackerConfig<Scalar> s = radar_tracker_config<Scalar>(p);
  CaMotion<Scalar> motion;
  motion.qj = s.qj;
  CaPolarRadar<Scalar> radar;
  radar.sigma_range_m = s.sigma_range_m;
  radar.sigma_bearing_rad = s.sigma_bearing_rad;
  return Filter(motion, radar, extra...);
}

/// kestrel-sim's EKF-CA tracker for these options (double and float are
/// instantiated). Unless options.confirmed_gate_d2 is set, confirmed tracks
/// are ungated (FilterOptions). Throws std::invalid_argument when the
/// adaptive noise keys are out of range (apply_measurement_noise).
template <class Scalar>
SimRadarTracker<EkfCa<Scalar>> make_ekf_ca_tracker(const FilterOptions& options);

FilterSetup ekf_ca_setup(const FilterOptions& options);
FilterSetup ekf_ca_f32_setup(const FilterOptions& options);
StreamRunResult run_ekf_ca(StreamInput stream, const FilterOptions& options, std::uint64_t budget_ns);
StreamRunResult run_ekf_ca_f32(StreamInput stream, const FilterOptions& options,
                               std::uint64_t budget_ns);

}  // namespace kestrel::sim
