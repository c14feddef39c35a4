// SPDX-License-Identifier: Apache-2.0
// The PCL and sonar trackers' parameters by name: the keys `--set
// KEY=VALUE` and `--config FILE` take on `run -s pcl002|uw003...`,
// `sonar-study` and `replay` (docs/parameters.md, "PCL tracker" and "Sonar tracker").
// As for the radar keys (filters/settings.hpp), one table per tracker maps
// each key to its field, range and meaning, so the parser, the range check,
// the echo into the summary and `list --settings` cannot drift apart.
#pragma once

#include <map>
#include <span>
#include <string>
#include <vector>

#include "filters/settings.hpp"
#include "kestrel/hal/frame.hpp"
#include "kestrel/tracking/pcl_tracker.hpp"
#include "kestrel/tracking/sonar_tracker.hpp"

namespace kestrel::sim {

/// Applies the settings to `params` in order (a later one wins). Throws
/// std::invalid_argument naming the key and its origin for an unknown key,
/// a value outside its range or confirm_m > confirm_n; `params` is then
/// unchanged.
void apply_pcl_settings(std::span<const Setting> settings, PclTrackerParams& params);
void apply_sonar_settings(std::span<const Setting> settings, SonarTrackerParams& params);

/// Every key with its value in `params`, for the summary's "parameters".
std::map<std::string, double> pcl_parameters(const PclTrackerParams& params);
std::map<std::string, double> sonar_parameters(const SonarTrackerParams& params);

/// The trackers that take `key` ("radar tracker", "PCL and sonar
/// trackers"), or "" when none does: what an unknown-key error names.
std::string trackers_taking(const std::string& key);

/// The gate of a command-line probability; throws std::invalid_argument
/// naming `option` unless it is 0.9, 0.95, 0.99, 0.995 or 0.999.
GateProbability gate_option(double p, const char* option);

/// Throws std::invalid_argument unless every setting is a key of the
/// tracker of `kind`'s frames (the radar keys of setting_table(), the PCL
/// or the sonar tracker's), naming the key, where it was given, the
/// tracker it belongs to if any, `what` (e.g. "FILE holds PCL frames") and
/// `list --settings`. For `replay`, which learns the kind from its input:
/// a key of another tracker is refused as such, never applied or ignored.
void check_settings_kind(std::span<const Setting> settings, hal::FrameKind kind, const std::string& what);

/// Every key, its default (for the keys a scenario sets, "the scenario's"
/// with pcl002's / uw003's value), range and meaning, in docs order.
std::vector<SettingInfo> pcl_setting_table();
std::vector<SettingInfo> sonar_setting_table();

}  // namespace kestrel::sim
