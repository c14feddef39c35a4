// SPDX-License-Identifier: Apache-2.0
// Tracker and filter parameters by name: the keys of `--set KEY=VALUE` and of
// a `--config FILE` JSON object (docs/parameters.md lists every key, its
// default and where the default comes from). One table maps each key to its
// field, its range and its meaning, so the parser, the range check, the echo
// into summary.json and `kestrel-sim list --settings` cannot drift apart.
#pragma once

#include <map>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "filters/filter_registry.hpp"
#include "kestrel/tracking/radar_tracker.hpp"

namespace kestrel::sim {

/// One KEY=VALUE, with where it was given (for the error message).
struct Setting {
  std::string key;
  double value = 0.0;
  std::string origin;  ///< "--set" or the config file's path.
};

/// "KEY=VALUE" given as `origin`. Throws std::invalid_argument when there is
/// no '=', no key, or the value is not a finite number (true/false are 1/0).
Setting parse_setting(const std::string& text, const std::string& origin);

/// The settings of a JSON config file: one object whose values are numbers or
/// booleans; a nested object's keys are joined with '.', so
/// {"imm": {"p_stay": 0.9}} gives imm.p_stay. Throws std::runtime_error when
/// the file cannot be read or parsed, and std::invalid_argument for a value
/// of another type.
std::vector<Setting> read_config_file(const std::string& path);

/// Applies the settings to `options` in order (a later one wins). Throws
/// std::invalid_argument naming the key and its origin when the key is
/// unknown or the value outside the key's range; `options` is then unchanged.
void apply_settings(std::span<const Setting> settings, FilterOptions& options);

/// The radar tracker's parameters: the defaults of RadarTrackerParams (the
/// S1/S2 sensor and paper 000's EKF-CA), then `options.qj` and the radar
/// keys of `options.radar`.
RadarTrackerParams radar_tracker_params(const FilterOptions& options);

/// Gives `tracker` the adaptive measurement noise keys of p
/// (robust_noise_gain, robust_noise_max_scale) through
/// Tracker::configure_measurement_noise(). Throws std::invalid_argument
/// naming the keys when the tracker refuses them: a gain but 0 for a
/// filter whose kestrel-sim tracker is built without the adaptive noise
/// (all but ekf-ca, ekf-ca-f32, imm and imm-f32: AdaptiveMeasurementNoise
/// needs a filter with a scaled update), or values out of range.
template <class Tracker>
void apply_measurement_noise(Tracker& tracker, const RadarTrackerParams& p) {
  const Status s = tracker.configure_measurement_noise(radar_measurement_noise<typename Tracker::Scalar>(p));
  if (s == Status::kOk) return;
  std::string what = "robust_noise_gain " + std::to_string(p.robust_noise_gain) + ", robust_noise_max_scale " +
                     std::to_string(p.robust_noise_max_scale) + ": refused (" + to_string(s) + "): ";
  if constexpr (Tracker::MeasurementNoiseT::kAdapts) {
    what += "the gain must be in [0, 1] and the max scale at least 1, and a gain acts only under the robust gate "
            "(robust_gate_factor > 1, --robust-gate)";
  } else {
    what += "this filter's tracker is built without the adaptive measurement noise (ekf-ca, ekf-ca-f32, imm and "
            "imm-f32 have it; docs/robustness.md, \"Adaptive measurement noise\")";
  }
  throw std::invalid_argument(what);
}

/// The two-point initiator of `Tracker` (its InitiatorT) on `radar`, with
/// p's seed rules (seed_extra_frames, seed_from_pairs) when it is a
/// TwoPointHypothesesInitiator. Throws std::invalid_argument naming the keys
/// when p sets a rule a TwoPointInitiator does not have (all but ekf-ca,
/// ekf-ca-f32, imm, imm-f32 and the multi-target tracker).
template <class Tracker, class Radar>
typename Tracker::InitiatorT radar_initiator(const Radar& radar, typename Tracker::Scalar max_speed_mps,
                                             typename Tracker::Scalar init_accel_sigma_mps2,
                                             const RadarTrackerParams& p) {
  using Initiator = typename Tracker::InitiatorT;
  Initiator init{};
  init.measurement = radar;
  init.max_speed_mps = max_speed_mps;
  init.accel_sigma_mps2 = init_accel_sigma_mps2;
  if constexpr (requires { Initiator::kKeepsHypotheses; }) {
    init.seed_extra_frames = p.seed_extra_frames;
    init.seed_from_pairs = p.seed_from_pairs;
  } else if (p.seed_extra_frames != 0 || p.seed_from_pairs) {
    throw std::invalid_argument("seed_extra_frames " + std::to_string(p.seed_extra_frames) + ", seed_from_pairs " +
                                std::to_string(p.seed_from_pairs ? 1 : 0) +
                                ": refused: this filter's tracker keeps one hypothesis per start (ekf-ca, ekf-ca-f32, "
                                "imm, imm-f32 and the multi-target tracker keep more; docs/robustness.md, \"A second hypothesis at the "
                                "start\")");
  }
  return init;
}

/// kestrel-sim's radar tracker of type TrackerT around `prototype` (a
/// filter with its models set), off the stack (the track table is large):
/// p's two-point initiator on the prototype's measurement model, p's
/// tracker configuration with the options' confirmed-track gate, and p's
/// adaptive-noise keys (apply_measurement_noise). Every single-target radar
/// filter of the registry but EKF-CA-RR (a third channel) is built here.
template <class TrackerT, class Filter>
std::unique_ptr<TrackerT> make_sim_radar_tracker(const Filter& prototype, const FilterOptions& options,
                                                 const RadarTrackerParams& p) {
  using Scalar = typename TrackerT::Scalar;
  const RadarTrackerConfig<Scalar> s = radar_tracker_config<Scalar>(p);
  const auto init = radar_initiator<TrackerT>(prototype.measurement(), s.max_speed_mps, s.init_accel_sigma_mps2, p);
  typename TrackerT::Config config = tracker_config_of<Scalar>(p, s);
  apply_gate_options<Scalar>(options, config);
  auto tracker = std::make_unique<TrackerT>(prototype, init, config);
  apply_measurement_noise(*tracker, p);
  return tracker;
}

/// Every radar tracker key with its value in p, for summary.json.
void add_radar_parameters(const RadarTrackerParams& p, std::map<std::string, double>& parameters);

/// One key of the table, for `list --settings` and the docs.
struct SettingInfo {
  std::string key;
  std::string default_text;  ///< The default as a user would write it ("ungated", "1.6", ...).
  std::string range;         ///< e.g. "> 0", "1..8, <= confirm_n".
  std::string meaning;
};

/// Every key apply_settings() knows, in the order docs/parameters.md gives them.
std::vector<SettingInfo> setting_table();

}  // namespace kestrel::sim
