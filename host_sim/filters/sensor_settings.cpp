// SPDX-License-Identifier: Apache-2.0
#include "filters/sensor_settings.hpp"

#include <stdexcept>

#include "filters/parameter_key.hpp"
#include "kestrel/association/chi_square.hpp"
#include "montecarlo/pcl_run.hpp"
#include "montecarlo/sonar_run.hpp"

namespace kestrel::sim {

namespace {

using PclKey = ParameterKey<PclTrackerParams>;
using SonarKey = ParameterKey<SonarTrackerParams>;
using Pcl = PclTrackerParams;
using Sonar = SonarTrackerParams;

constexpr KeyRange kPositive{0.0, true};
constexpr KeyRange kProbability{0.0, true, 1.0};  // (0, 1)
constexpr bool kFromScenario = true;

// clang-format off
const PclKey kPclKeys[] = {
  field_key<&Pcl::sigma_rb_m>("sigma_rb_m", kPositive, "bistatic range noise sigma the filter assumes, m", kFromScenario),
  field_key<&Pcl::sigma_doppler_hz>("sigma_doppler_hz", kPositive, "Doppler noise sigma the filter assumes, Hz", kFromScenario),
  field_key<&Pcl::accel_sigma_mps2>("accel_sigma_mps2", kPositive, "white-acceleration sigma on Rb, m/s^2"),
  field_key<&Pcl::gate_tentative>("gate_tentative", {}, "chi-square gate probability of tentative tracks"),
  field_key<&Pcl::gate_confirmed>("gate_confirmed", {}, "chi-square gate probability of confirmed tracks"),
  field_key<&Pcl::confirm_m>("confirm_m", {1.0, false, 8.0}, "M of M-of-N confirmation, <= confirm_n"),
  field_key<&Pcl::confirm_n>("confirm_n", {1.0, false, 8.0}, "N of M-of-N confirmation, frames"),
  field_key<&Pcl::min_start_doppler_hz>("min_start_doppler_hz", {0.0}, "no track starts from a candidate with |fD| below this, Hz"),
  field_key<&Pcl::max_coast_misses>("max_coast_misses", {0.0, false, 65535.0}, "misses in a row before a confirmed track is deleted"),
  field_key<&Pcl::max_rb_variance_m2>("max_rb_variance_m2", kPositive, "a track whose var(Rb) exceeds this is deleted, m^2"),
  field_key<&Pcl::detection_probability>("detection_probability", kProbability,
                                         "P_D for the pda associator and the score manager, < 1", kFromScenario),
  field_key<&Pcl::clutter_density>("clutter_density", kPositive,
                                   "false candidates per m x m/s and frame, for pda and score", kFromScenario),
  field_key<&Pcl::new_target_density>("new_target_density", kPositive, "new targets per m x m/s and frame, for score"),
  field_key<&Pcl::false_track_probability>("false_track_probability", kProbability, "alpha of score's confirmation test, < 1"),
  field_key<&Pcl::missed_track_probability>("missed_track_probability", kProbability, "beta of score's deletion test, < 1"),
};

const SonarKey kSonarKeys[] = {
  field_key<&Sonar::sigma_toa_s>("sigma_toa_s", kPositive, "TOA noise sigma the filter assumes, s", kFromScenario),
  field_key<&Sonar::seabed_depth_m>("seabed_depth_m", kPositive, "seabed depth D the reflected-path model assumes, m", kFromScenario),
  field_key<&Sonar::accel_sigma_mps2>("accel_sigma_mps2", kPositive, "white acceleration per axis, m/s^2"),
  field_key<&Sonar::sound_speed_sigma_mps_per_sqrt_s>("sound_speed_sigma_mps_per_sqrt_s", {0.0},
                                                      "sound-speed random walk, m/s per sqrt(s)"),
  field_key<&Sonar::initial_sound_speed_mps>("initial_sound_speed_mps", kPositive, "c of the first fix and of the filter start, m/s"),
  field_key<&Sonar::initial_sound_speed_sigma_mps>("initial_sound_speed_sigma_mps", kPositive, "initial sound-speed sigma, m/s"),
  field_key<&Sonar::initial_velocity_sigma_mps>("initial_velocity_sigma_mps", kPositive, "initial velocity sigma per axis, m/s"),
  field_key<&Sonar::initial_position_sigma_m>("initial_position_sigma_m", kPositive,
                                              "prior position sigma before the first update, m"),
  field_key<&Sonar::per_channel_gate>("per_channel_gate", {}, "per-channel gate on"),
  field_key<&Sonar::gate_k_sigma>("gate_k_sigma", kPositive, "per-channel gate multiplier k"),
  field_key<&Sonar::ellipsoidal_gate>("ellipsoidal_gate", {}, "ellipsoidal gate on, after the per-channel gate"),
  field_key<&Sonar::ellipsoid_probability>("ellipsoid_probability", {}, "the ellipsoidal gate's probability"),
  field_key<&Sonar::reject_sigma>("reject_sigma", kPositive,
                                  "multilateration fix: arrivals off by more than this many sigma are rejected"),
  field_key<&Sonar::reacquire_after_lost_frames>("reacquire_after_lost_frames", {0.0, false, 65535.0},
                                                 "re-run the fix after this many frames in a row fusing at most half "
                                                 "their arrivals, 0: never"),
  field_key<&Sonar::gate_truncation_covariance>("gate_truncation_covariance", {},
                                                "widen P for channels the per-channel gate dropped"),
  field_key<&Sonar::project_depth>("project_depth", {}, "keep the depth estimate within (0, D)"),
};
// clang-format on

template <class P, std::size_t N>
void apply(std::span<const Setting> settings, P& params, const ParameterKey<P> (&keys)[N], const char* tracker) {
  P p = params;
  for (const Setting& s : settings) {
    const ParameterKey<P>* found = nullptr;
    for (const ParameterKey<P>& k : keys) {
      if (s.key == k.key) found = &k;
    }
    if (found == nullptr) {
      std::string known;
      for (const ParameterKey<P>& k : keys) known += (known.empty() ? "" : ", ") + std::string(k.key);
      const std::string owners = trackers_taking(s.key);
      throw std::invalid_argument(s.origin + " " + s.key + "=" + shortest_text(s.value) + ": unknown key of the " + tracker +
                                  " tracker (known: " + known + ")" +
                                  (owners.empty() ? std::string() : "; it is a key of the " + owners) +
                                  ". The keys of each tracker: `kestrel-sim list --settings`");
    }
    if (!key_accepts(found->type, found->range, s.value)) {
      throw std::invalid_argument(s.origin + " " + s.key + "=" + shortest_text(s.value) + ": out of range (" +
                                  range_text(found->type, found->range) + ")");
    }
    found->set(p, s.value);
  }
  params = p;
}

template <class P, std::size_t N>
std::map<std::string, double> values(const P& p, const ParameterKey<P> (&keys)[N]) {
  std::map<std::string, double> m;
  for (const ParameterKey<P>& k : keys) m[k.key] = k.get(p);
  return m;
}

template <class P, std::size_t N>
std::vector<SettingInfo> table(const P& defaults, const ParameterKey<P> (&keys)[N], const std::string& scenario) {
  std::vector<SettingInfo> t;
  for (const ParameterKey<P>& k : keys) {
    std::string d = default_text(k, defaults);
    if (k.from_scenario) d = "the scenario's (" + scenario + ": " + d + ")";
    t.push_back({k.key, d, range_text(k.type, k.range), k.meaning});
  }
  return t;
}

}  // namespace

void apply_pcl_settings(std::span<const Setting> settings, PclTrackerParams& params) {
  PclTrackerParams p = params;
  apply(settings, p, kPclKeys, "PCL");
  if (p.confirm_m > p.confirm_n) {
    throw std::invalid_argument("confirm_m " + std::to_string(p.confirm_m) + " > confirm_n " +
                                std::to_string(p.confirm_n) + ": M-of-N needs M <= N");
  }
  params = p;
}

void apply_sonar_settings(std::span<const Setting> settings, SonarTrackerParams& params) {
  apply(settings, params, kSonarKeys, "sonar");
}

namespace {

const char* tracker_name(hal::FrameKind kind) {
  switch (kind) {
    case hal::FrameKind::kPcl: return "PCL";
    case hal::FrameKind::kSonar: return "sonar";
    default: return "radar";
  }
}

bool tracker_takes(hal::FrameKind kind, const std::string& key) {
  switch (kind) {
    case hal::FrameKind::kPcl:
      for (const auto& k : kPclKeys) {
        if (key == k.key) return true;
      }
      return false;
    case hal::FrameKind::kSonar:
      for (const auto& k : kSonarKeys) {
        if (key == k.key) return true;
      }
      return false;
    default:
      // imm.KEY stands for every IMM parameter (apply_settings passes them on).
      if (key.rfind("imm.", 0) == 0) return key.size() > 4;
      for (const SettingInfo& i : setting_table()) {
        if (key == i.key) return true;
      }
      return false;
  }
}

}  // namespace

GateProbability gate_option(double p, const char* option) {
  GateProbability g{};
  if (!gate_probability_from(p, g)) {
    throw std::invalid_argument(std::string(option) + " must be 0.9, 0.95, 0.99, 0.995 or 0.999");
  }
  return g;
}

std::string trackers_taking(const std::string& key) {
  constexpr hal::FrameKind kKinds[] = {hal::FrameKind::kRadar, hal::FrameKind::kPcl, hal::FrameKind::kSonar};
  std::string owners;
  int owner_count = 0;
  for (const hal::FrameKind k : kKinds) {
    if (!tracker_takes(k, key)) continue;
    owners += std::string(owners.empty() ? "" : " and ") + tracker_name(k);
    ++owner_count;
  }
  if (owner_count == 0) return owners;
  return owners + (owner_count > 1 ? " trackers" : " tracker");
}

void check_settings_kind(std::span<const Setting> settings, hal::FrameKind kind, const std::string& what) {
  for (const Setting& s : settings) {
    if (tracker_takes(kind, s.key)) continue;
    const std::string owners = trackers_taking(s.key);
    const std::string whose = owners.empty() ? std::string("no tracker has it") : "it is a key of the " + owners;
    throw std::invalid_argument(s.origin + " " + s.key + "=" + shortest_text(s.value) + ": '" + s.key +
                                "' is not a key of the " + tracker_name(kind) + " tracker (" + what + "); " + whose +
                                ". The keys of each tracker: `kestrel-sim list --settings`");
  }
}

std::map<std::string, double> pcl_parameters(const PclTrackerParams& params) { return values(params, kPclKeys); }
std::map<std::string, double> sonar_parameters(const SonarTrackerParams& params) { return values(params, kSonarKeys); }

std::vector<SettingInfo> pcl_setting_table() {
  return table(pcl_params_for(pcl002_config()), kPclKeys, "pcl002");
}

std::vector<SettingInfo> sonar_setting_table() {
  return table(sonar_params_for(uw003_config()), kSonarKeys, "uw003");
}

}  // namespace kestrel::sim
