// SPDX-License-Identifier: Apache-2.0
#include "filters/sensor_settings.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#include "kestrel/association/chi_square.hpp"
#include "montecarlo/pcl_run.hpp"
#include "montecarlo/sonar_run.hpp"

namespace kestrel::sim {

namespace {

enum class Type { kReal, kWhole, kBool, kGate };

/// One key of a tracker's parameter struct P.
template <class P>
struct Key {
  const char* key;
  Type type;
  double lo;     ///< Smallest value (exclusive when lo_open); kReal and kWhole.
  bool lo_open;
  double hi;     ///< Largest value (inclusive).
  bool from_scenario;  ///< The scenario sets its default (the sensor's figure).
  double (*get)(const P&);
  void (*set)(P&, double);
  const char* meaning;
};

constexpr double kInf = std::numeric_limits<double>::infinity();
GateProbability gate_of(double v) {
  GateProbability g = GateProbability::k99;
  (void)gate_probability_from(v, g);  // check() refused any other value
  return g;
}

// clang-format off
const Key<PclTrackerParams> kPclKeys[] = {
  {"sigma_rb_m", Type::kReal, 0.0, true, kInf, true,
   [](const PclTrackerParams& p) { return p.sigma_rb_m; }, [](PclTrackerParams& p, double v) { p.sigma_rb_m = v; },
   "bistatic range noise sigma the filter assumes, m"},
  {"sigma_doppler_hz", Type::kReal, 0.0, true, kInf, true,
   [](const PclTrackerParams& p) { return p.sigma_doppler_hz; },
   [](PclTrackerParams& p, double v) { p.sigma_doppler_hz = v; },
   "Doppler noise sigma the filter assumes, Hz"},
  {"accel_sigma_mps2", Type::kReal, 0.0, true, kInf, false,
   [](const PclTrackerParams& p) { return p.accel_sigma_mps2; },
   [](PclTrackerParams& p, double v) { p.accel_sigma_mps2 = v; },
   "white-acceleration sigma on Rb, m/s^2"},
  {"gate_tentative", Type::kGate, 0, false, 0, false,
   [](const PclTrackerParams& p) { return gate_probability(p.gate_tentative); },
   [](PclTrackerParams& p, double v) { p.gate_tentative = gate_of(v); },
   "chi-square gate probability of tentative tracks"},
  {"gate_confirmed", Type::kGate, 0, false, 0, false,
   [](const PclTrackerParams& p) { return gate_probability(p.gate_confirmed); },
   [](PclTrackerParams& p, double v) { p.gate_confirmed = gate_of(v); },
   "chi-square gate probability of confirmed tracks"},
  {"confirm_m", Type::kWhole, 1.0, false, 8.0, false,
   [](const PclTrackerParams& p) { return static_cast<double>(p.confirm_m); },
   [](PclTrackerParams& p, double v) { p.confirm_m = static_cast<std::uint8_t>(v); },
   "M of M-of-N confirmation, <= confirm_n"},
  {"confirm_n", Type::kWhole, 1.0, false, 8.0, false,
   [](const PclTrackerParams& p) { return static_cast<double>(p.confirm_n); },
   [](PclTrackerParams& p, double v) { p.confirm_n = static_cast<std::uint8_t>(v); },
   "N of M-of-N confirmation, frames"},
  {"min_start_doppler_hz", Type::kReal, 0.0, false, kInf, false,
   [](const PclTrackerParams& p) { return p.min_start_doppler_hz; },
   [](PclTrackerParams& p, double v) { p.min_start_doppler_hz = v; },
   "no track starts from a candidate with |fD| below this, Hz"},
  {"max_coast_misses", Type::kWhole, 0.0, false, 65535.0, false,
   [](const PclTrackerParams& p) { return static_cast<double>(p.max_coast_misses); },
   [](PclTrackerParams& p, double v) { p.max_coast_misses = static_cast<std::uint16_t>(v); },
   "misses in a row before a confirmed track is deleted"},
  {"max_rb_variance_m2", Type::kReal, 0.0, true, kInf, false,
   [](const PclTrackerParams& p) { return p.max_rb_variance_m2; },
   [](PclTrackerParams& p, double v) { p.max_rb_variance_m2 = v; },
   "a track whose var(Rb) exceeds this is deleted, m^2"},
  {"detection_probability", Type::kReal, 0.0, true, 1.0, true,
   [](const PclTrackerParams& p) { return p.detection_probability; },
   [](PclTrackerParams& p, double v) { p.detection_probability = v; },
   "P_D for the pda associator and the score manager, < 1"},
  {"clutter_density", Type::kReal, 0.0, true, kInf, true,
   [](const PclTrackerParams& p) { return p.clutter_density; },
   [](PclTrackerParams& p, double v) { p.clutter_density = v; },
   "false candidates per m x m/s and frame, for pda and score"},
  {"new_target_density", Type::kReal, 0.0, true, kInf, false,
   [](const PclTrackerParams& p) { return p.new_target_density; },
   [](PclTrackerParams& p, double v) { p.new_target_density = v; },
   "new targets per m x m/s and frame, for score"},
  {"false_track_probability", Type::kReal, 0.0, true, 1.0, false,
   [](const PclTrackerParams& p) { return p.false_track_probability; },
   [](PclTrackerParams& p, double v) { p.false_track_probability = v; },
   "alpha of score's confirmation test, < 1"},
  {"missed_track_probability", Type::kReal, 0.0, true, 1.0, false,
   [](const PclTrackerParams& p) { return p.missed_track_probability; },
   [](PclTrackerParams& p, double v) { p.missed_track_probability = v; },
   "beta of score's deletion test, < 1"},
};

const Key<SonarTrackerParams> kSonarKeys[] = {
  {"sigma_toa_s", Type::kReal, 0.0, true, kInf, true,
   [](const SonarTrackerParams& p) { return p.sigma_toa_s; },
   [](SonarTrackerParams& p, double v) { p.sigma_toa_s = v; },
   "TOA noise sigma the filter assumes, s"},
  {"seabed_depth_m", Type::kReal, 0.0, true, kInf, true,
   [](const SonarTrackerParams& p) { return p.seabed_depth_m; },
   [](SonarTrackerParams& p, double v) { p.seabed_depth_m = v; },
   "seabed depth D the reflected-path model assumes, m"},
  {"accel_sigma_mps2", Type::kReal, 0.0, true, kInf, false,
   [](const SonarTrackerParams& p) { return p.accel_sigma_mps2; },
   [](SonarTrackerParams& p, double v) { p.accel_sigma_mps2 = v; },
   "white acceleration per axis, m/s^2"},
  {"sound_speed_sigma_mps_per_sqrt_s", Type::kReal, 0.0, false, kInf, false,
   [](const SonarTrackerParams& p) { return p.sound_speed_sigma_mps_per_sqrt_s; },
   [](SonarTrackerParams& p, double v) { p.sound_speed_sigma_mps_per_sqrt_s = v; },
   "sound-speed random walk, m/s per sqrt(s)"},
  {"initial_sound_speed_mps", Type::kReal, 0.0, true, kInf, false,
   [](const SonarTrackerParams& p) { return p.initial_sound_speed_mps; },
   [](SonarTrackerParams& p, double v) { p.initial_sound_speed_mps = v; },
   "c of the first fix and of the filter start, m/s"},
  {"initial_sound_speed_sigma_mps", Type::kReal, 0.0, true, kInf, false,
   [](const SonarTrackerParams& p) { return p.initial_sound_speed_sigma_mps; },
   [](SonarTrackerParams& p, double v) { p.initial_sound_speed_sigma_mps = v; },
   "initial sound-speed sigma, m/s"},
  {"initial_velocity_sigma_mps", Type::kReal, 0.0, true, kInf, false,
   [](const SonarTrackerParams& p) { return p.initial_velocity_sigma_mps; },
   [](SonarTrackerParams& p, double v) { p.initial_velocity_sigma_mps = v; },
   "initial velocity sigma per axis, m/s"},
  {"initial_position_sigma_m", Type::kReal, 0.0, true, kInf, false,
   [](const SonarTrackerParams& p) { return p.initial_position_sigma_m; },
   [](SonarTrackerParams& p, double v) { p.initial_position_sigma_m = v; },
   "prior position sigma before the first update, m"},
  {"per_channel_gate", Type::kBool, 0, false, 0, false,
   [](const SonarTrackerParams& p) { return p.per_channel_gate ? 1.0 : 0.0; },
   [](SonarTrackerParams& p, double v) { p.per_channel_gate = v == 1.0; },
   "per-channel gate on"},
  {"gate_k_sigma", Type::kReal, 0.0, true, kInf, false,
   [](const SonarTrackerParams& p) { return p.gate_k_sigma; },
   [](SonarTrackerParams& p, double v) { p.gate_k_sigma = v; },
   "per-channel gate multiplier k"},
  {"ellipsoidal_gate", Type::kBool, 0, false, 0, false,
   [](const SonarTrackerParams& p) { return p.ellipsoidal_gate ? 1.0 : 0.0; },
   [](SonarTrackerParams& p, double v) { p.ellipsoidal_gate = v == 1.0; },
   "ellipsoidal gate on, after the per-channel gate"},
  {"ellipsoid_probability", Type::kGate, 0, false, 0, false,
   [](const SonarTrackerParams& p) { return gate_probability(p.ellipsoid_probability); },
   [](SonarTrackerParams& p, double v) { p.ellipsoid_probability = gate_of(v); },
   "the ellipsoidal gate's probability"},
  {"reject_sigma", Type::kReal, 0.0, true, kInf, false,
   [](const SonarTrackerParams& p) { return p.reject_sigma; },
   [](SonarTrackerParams& p, double v) { p.reject_sigma = v; },
   "multilateration fix: arrivals off by more than this many sigma are rejected"},
  {"reacquire_after_lost_frames", Type::kWhole, 0.0, false, 65535.0, false,
   [](const SonarTrackerParams& p) { return static_cast<double>(p.reacquire_after_lost_frames); },
   [](SonarTrackerParams& p, double v) { p.reacquire_after_lost_frames = static_cast<std::uint16_t>(v); },
   "re-run the fix after this many frames in a row fusing at most half their arrivals, 0: never"},
  {"gate_truncation_covariance", Type::kBool, 0, false, 0, false,
   [](const SonarTrackerParams& p) { return p.gate_truncation_covariance ? 1.0 : 0.0; },
   [](SonarTrackerParams& p, double v) { p.gate_truncation_covariance = v == 1.0; },
   "widen P for channels the per-channel gate dropped"},
  {"project_depth", Type::kBool, 0, false, 0, false,
   [](const SonarTrackerParams& p) { return p.project_depth ? 1.0 : 0.0; },
   [](SonarTrackerParams& p, double v) { p.project_depth = v == 1.0; },
   "keep the depth estimate within (0, D)"},
};
// clang-format on

std::string shortest(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  if (std::strtod(text, nullptr) == v) return text;
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

template <class P>
std::string range_text(const Key<P>& k) {
  switch (k.type) {
    case Type::kBool: return "false or true";
    case Type::kGate: return "0.9, 0.95, 0.99, 0.995, 0.999";
    case Type::kWhole:
    case Type::kReal: break;
  }
  std::string r = k.type == Type::kWhole ? "whole, " : "";
  if (k.lo_open) {
    r += "> " + shortest(k.lo);
    if (k.hi != kInf) r += ", " + std::string(k.hi == 1.0 ? "< " : "<= ") + shortest(k.hi);
  } else {
    r += k.hi != kInf ? shortest(k.lo) + ".." + shortest(k.hi) : ">= " + shortest(k.lo);
  }
  return r;
}

template <class P>
void check(const Setting& s, const Key<P>& k) {
  const double v = s.value;
  bool ok = std::isfinite(v);
  GateProbability gate{};
  switch (k.type) {
    case Type::kBool: ok = ok && (v == 0.0 || v == 1.0); break;
    case Type::kGate: ok = ok && gate_probability_from(v, gate); break;
    case Type::kWhole: ok = ok && v == std::floor(v); [[fallthrough]];
    case Type::kReal:
      ok = ok && (k.lo_open ? v > k.lo : v >= k.lo);
      // A probability's upper bound 1 is open; other bounds are inclusive.
      ok = ok && (k.hi == 1.0 && k.lo_open ? v < k.hi : v <= k.hi);
      break;
  }
  if (!ok) throw std::invalid_argument(s.origin + " " + s.key + "=" + shortest(v) + ": out of range (" + range_text(k) + ")");
}

template <class P, std::size_t N>
void apply(std::span<const Setting> settings, P& params, const Key<P> (&keys)[N], const char* tracker) {
  P p = params;
  for (const Setting& s : settings) {
    const Key<P>* found = nullptr;
    for (const Key<P>& k : keys) {
      if (s.key == k.key) found = &k;
    }
    if (found == nullptr) {
      std::string known;
      for (const Key<P>& k : keys) known += (known.empty() ? "" : ", ") + std::string(k.key);
      const std::string owners = trackers_taking(s.key);
      throw std::invalid_argument(s.origin + " " + s.key + "=" + shortest(s.value) + ": unknown key of the " + tracker +
                                  " tracker (known: " + known + ")" +
                                  (owners.empty() ? std::string() : "; it is a key of the " + owners) +
                                  ". The keys of each tracker: `kestrel-sim list --settings`");
    }
    check(s, *found);
    found->set(p, s.value);
  }
  params = p;
}

template <class P, std::size_t N>
std::map<std::string, double> values(const P& p, const Key<P> (&keys)[N]) {
  std::map<std::string, double> m;
  for (const Key<P>& k : keys) m[k.key] = k.get(p);
  return m;
}

template <class P, std::size_t N>
std::vector<SettingInfo> table(const P& defaults, const Key<P> (&keys)[N], const std::string& scenario) {
  std::vector<SettingInfo> t;
  for (const Key<P>& k : keys) {
    std::string d = k.type == Type::kBool ? (k.get(defaults) == 1.0 ? "true" : "false") : shortest(k.get(defaults));
    if (k.from_scenario) d = "the scenario's (" + scenario + ": " + d + ")";
    t.push_back({k.key, d, range_text(k), k.meaning});
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
    throw std::invalid_argument(s.origin + " " + s.key + "=" + shortest(s.value) + ": '" + s.key +
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
