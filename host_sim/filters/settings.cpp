// SPDX-License-Identifier: Apache-2.0
#include "filters/settings.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "filters/sensor_settings.hpp"

namespace kestrel::sim {

namespace {

/// A key of RadarTrackerParams: its accessors, range and meaning.
struct RadarKey {
  const char* key;
  double lo;          ///< Smallest value (exclusive when lo_open).
  bool lo_open;
  double hi;          ///< Largest value (inclusive).
  bool integer;       ///< The field is an integer: the value must be whole.
  double (*get)(const RadarTrackerParams&);
  void (*set)(RadarTrackerParams&, double);
  const char* meaning;
};

constexpr double kInf = std::numeric_limits<double>::infinity();
// The largest whole number a double holds exactly, a bound for the us fields.
constexpr double kMaxWhole = 9007199254740992.0;

// clang-format off
const RadarKey kRadarKeys[] = {
  {"sigma_range_m", 0.0, true, kInf, false,
   [](const RadarTrackerParams& p) { return p.sigma_range_m; },
   [](RadarTrackerParams& p, double v) { p.sigma_range_m = v; },
   "range noise sigma of the sensor, m"},
  {"sigma_bearing_rad", 0.0, true, kInf, false,
   [](const RadarTrackerParams& p) { return p.sigma_bearing_rad; },
   [](RadarTrackerParams& p, double v) { p.sigma_bearing_rad = v; },
   "bearing noise sigma of the sensor, rad"},
  {"max_speed_mps", 0.0, true, kInf, false,
   [](const RadarTrackerParams& p) { return p.max_speed_mps; },
   [](RadarTrackerParams& p, double v) { p.max_speed_mps = v; },
   "two-point initiation refuses plot pairs faster than this, m/s"},
  {"init_accel_sigma_mps2", 0.0, true, kInf, false,
   [](const RadarTrackerParams& p) { return p.init_accel_sigma_mps2; },
   [](RadarTrackerParams& p, double v) { p.init_accel_sigma_mps2 = v; },
   "initial acceleration sigma of a new track, m/s^2"},
  {"max_range_m", 0.0, true, kInf, false,
   [](const RadarTrackerParams& p) { return p.max_range_m; },
   [](RadarTrackerParams& p, double v) { p.max_range_m = v; },
   "plots beyond this range are refused as out of range, m"},
  {"max_position_variance_m2", 0.0, true, kInf, false,
   [](const RadarTrackerParams& p) { return p.max_position_variance_m2; },
   [](RadarTrackerParams& p, double v) { p.max_position_variance_m2 = v; },
   "a track whose var(x) + var(y) exceeds this is deleted, m^2"},
  {"gate_probability", 0.0, true, 1.0, false,
   [](const RadarTrackerParams& p) { return gate_probability(p.gate); },
   [](RadarTrackerParams& p, double v) { (void)gate_probability_from(v, p.gate); },  // check_range() refuses others
   "chi-square gate of tentative tracks, and of confirmed ones under the board's gate: "
   "0.9, 0.95, 0.99, 0.995 or 0.999"},
  {"robust_noise_gain", 0.0, false, 1.0, false,
   [](const RadarTrackerParams& p) { return p.robust_noise_gain; },
   [](RadarTrackerParams& p, double v) { p.robust_noise_gain = v; },
   "with the robust gate, the weight of each plot's NIS excess in a confirmed track's scale of R (0: off; "
   "ekf-ca and imm only, the other filters refuse a gain)"},
  {"robust_noise_max_scale", 1.0, false, kInf, false,
   [](const RadarTrackerParams& p) { return p.robust_noise_max_scale; },
   [](RadarTrackerParams& p, double v) { p.robust_noise_max_scale = v; },
   "with the robust gate, the largest scale of R a confirmed track fuses with (1: off)"},
  {"confirm_m", 1.0, false, 8.0, true,
   [](const RadarTrackerParams& p) { return static_cast<double>(p.confirm_m); },
   [](RadarTrackerParams& p, double v) { p.confirm_m = static_cast<std::uint8_t>(v); },
   "M of M-of-N confirmation (the seed and the pairing plot count), <= confirm_n"},
  {"confirm_n", 1.0, false, 8.0, true,
   [](const RadarTrackerParams& p) { return static_cast<double>(p.confirm_n); },
   [](RadarTrackerParams& p, double v) { p.confirm_n = static_cast<std::uint8_t>(v); },
   "N of M-of-N confirmation, frames"},
  {"seed_extra_frames", 0.0, false, 7.0, true,
   [](const RadarTrackerParams& p) { return static_cast<double>(p.seed_extra_frames); },
   [](RadarTrackerParams& p, double v) { p.seed_extra_frames = static_cast<std::uint8_t>(v); },
   "two-point initiation: frames after the next one in which a seed still pairs, even after it has paired "
   "(0: the next frame only)"},
  {"seed_from_pairs", 0.0, false, 1.0, true,
   [](const RadarTrackerParams& p) { return p.seed_from_pairs ? 1.0 : 0.0; },
   [](RadarTrackerParams& p, double v) { p.seed_from_pairs = v == 1.0; },
   "two-point initiation: the plot that completes a pair also starts a seed (0 or 1)"},
  {"max_coast_misses", 0.0, false, 65535.0, true,
   [](const RadarTrackerParams& p) { return static_cast<double>(p.max_coast_misses); },
   [](RadarTrackerParams& p, double v) { p.max_coast_misses = static_cast<std::uint16_t>(v); },
   "a confirmed track is deleted after more misses in a row than this"},
  {"max_predict_us", 0.0, true, kMaxWhole, true,
   [](const RadarTrackerParams& p) { return static_cast<double>(p.max_predict_us); },
   [](RadarTrackerParams& p, double v) { p.max_predict_us = static_cast<std::int64_t>(v); },
   "a track older than this at a frame is deleted, not extrapolated, us"},
  {"max_forward_jump_us", 0.0, true, kMaxWhole, true,
   [](const RadarTrackerParams& p) { return static_cast<double>(p.max_forward_jump_us); },
   [](RadarTrackerParams& p, double v) { p.max_forward_jump_us = static_cast<std::int64_t>(v); },
   "a frame this far after the last accepted one is refused (kTimeJumpedForward), us"},
  {"resync_frames", 0.0, false, 255.0, true,
   [](const RadarTrackerParams& p) { return static_cast<double>(p.resync_frames); },
   [](RadarTrackerParams& p, double v) { p.resync_frames = static_cast<std::uint8_t>(v); },
   "consistent refused frames before the tracker restarts on the new clock (0: never)"},
};
// clang-format on

const RadarKey* find_radar_key(const std::string& key) {
  for (const RadarKey& k : kRadarKeys) {
    if (key == k.key) return &k;
  }
  return nullptr;
}

std::string format(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

std::string shortest(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  if (std::strtod(text, nullptr) == v) return text;
  return format(v);
}

[[noreturn]] void refuse(const Setting& s, const std::string& why) {
  throw std::invalid_argument(s.origin + " " + s.key + "=" + shortest(s.value) + ": " + why);
}

std::string range_text(const RadarKey& k) {
  if (std::string(k.key) == "gate_probability") return "0.9, 0.95, 0.99, 0.995, 0.999";
  std::string r = k.integer ? "whole, " : "";
  r += k.lo_open ? "> " + shortest(k.lo) : shortest(k.lo) + "..";
  if (k.hi != kInf) r += k.lo_open ? ", <= " + shortest(k.hi) : shortest(k.hi);
  return r;
}

void check_range(const Setting& s, const RadarKey& k) {
  const double v = s.value;
  const bool above = k.lo_open ? v > k.lo : v >= k.lo;
  if (!above || !(v <= k.hi) || (k.integer && v != std::floor(v))) refuse(s, "out of range (" + range_text(k) + ")");
  GateProbability g{};
  if (std::string(k.key) == "gate_probability" && !gate_probability_from(v, g)) {
    refuse(s, "not one of " + range_text(k));
  }
}

void apply_one(const Setting& s, FilterOptions& o) {
  if (!std::isfinite(s.value)) refuse(s, "not a finite number");
  if (s.key == "qj") {
    if (!(s.value > 0.0)) refuse(s, "out of range (> 0)");
    o.qj = s.value;
  } else if (s.key == "gate_d2") {
    if (!(s.value > 0.0)) refuse(s, "out of range (> 0)");
    o.confirmed_gate_d2 = s.value;
  } else if (s.key == "board_gate") {
    if (s.value != 0.0 && s.value != 1.0) refuse(s, "out of range (0 or 1, false or true)");
    o.board_gate = s.value == 1.0;
  } else if (s.key == "robust_gate_factor") {
    if (!(s.value == 0.0 || s.value > 1.0)) refuse(s, "out of range (0, off, or > 1)");
    o.robust_gate_factor = s.value;
  } else if (s.key.rfind("imm.", 0) == 0 && s.key.size() > 4) {
    // The IMM checks its own keys and values when it is built (filters/imm_filters.cpp).
    o.imm.push_back(s.key.substr(4) + "=" + format(s.value));
  } else if (const RadarKey* k = find_radar_key(s.key)) {
    check_range(s, *k);
    o.radar[s.key] = s.value;
  } else {
    std::string known;
    for (const SettingInfo& i : setting_table()) known += (known.empty() ? "" : ", ") + i.key;
    const std::string owners = trackers_taking(s.key);
    const std::string whose = owners.empty() ? std::string() : "; it is a key of the " + owners;
    refuse(s, "unknown key of the radar tracker (known: " + known + ")" + whose +
                  ". The keys of each tracker: `kestrel-sim list --settings`");
  }
}

void flatten(const nlohmann::json& object, const std::string& prefix, const std::string& path,
             std::vector<Setting>& out) {
  for (auto it = object.begin(); it != object.end(); ++it) {
    const std::string key = prefix + it.key();
    const nlohmann::json& v = it.value();
    if (v.is_object()) {
      flatten(v, key + ".", path, out);
    } else if (v.is_boolean()) {
      out.push_back({key, v.get<bool>() ? 1.0 : 0.0, path});
    } else if (v.is_number()) {
      out.push_back({key, v.get<double>(), path});
    } else {
      throw std::invalid_argument(path + " " + key + ": a number or true/false is expected, not " + v.dump());
    }
  }
}

}  // namespace

Setting parse_setting(const std::string& text, const std::string& origin) {
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0) throw std::invalid_argument(origin + " " + text + ": expected KEY=VALUE");
  Setting s{text.substr(0, eq), 0.0, origin};
  const std::string value = text.substr(eq + 1);
  if (value == "true" || value == "false") {
    s.value = value == "true" ? 1.0 : 0.0;
    return s;
  }
  char* end = nullptr;
  s.value = std::strtod(value.c_str(), &end);
  if (value.empty() || end == nullptr || *end != '\0' || !std::isfinite(s.value)) {
    throw std::invalid_argument(origin + " " + text + ": the value is not a finite number");
  }
  return s;
}

std::vector<Setting> read_config_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("--config " + path + ": cannot be read");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw std::runtime_error("--config " + path + ": not valid JSON (" + e.what() + ")");
  }
  if (!j.is_object()) throw std::invalid_argument("--config " + path + ": a JSON object of KEY: VALUE is expected");
  std::vector<Setting> out;
  flatten(j, "", "--config " + path + ":", out);
  return out;
}

void apply_settings(std::span<const Setting> settings, FilterOptions& options) {
  FilterOptions o = options;
  for (const Setting& s : settings) apply_one(s, o);
  // M <= N is a property of the pair: checked once both are known.
  const RadarTrackerParams p = radar_tracker_params(o);
  if (p.confirm_m > p.confirm_n) {
    throw std::invalid_argument("confirm_m " + std::to_string(p.confirm_m) + " > confirm_n " +
                                std::to_string(p.confirm_n) + ": M-of-N needs M <= N");
  }
  options = o;
}

RadarTrackerParams radar_tracker_params(const FilterOptions& options) {
  RadarTrackerParams p;
  if (options.qj.has_value()) p.qj = *options.qj;
  for (const auto& [key, value] : options.radar) {
    if (const RadarKey* k = find_radar_key(key)) k->set(p, value);
  }
  return p;
}

void add_radar_parameters(const RadarTrackerParams& p, std::map<std::string, double>& parameters) {
  parameters["qj"] = p.qj;
  for (const RadarKey& k : kRadarKeys) parameters[k.key] = k.get(p);
}

std::vector<SettingInfo> setting_table() {
  const RadarTrackerParams d;
  std::vector<SettingInfo> t = {
      {"qj", shortest(d.qj) + " (IMM: its CA mode's)", "> 0", "white-jerk PSD of CA models, m^2/s^5 (same as --qj)"},
      {"gate_d2", "ungated (replay: the board's gate)", "> 0",
       "gate of confirmed tracks in d2 = nu' S^-1 nu units (same as --gate-d2)"},
      {"board_gate", "false (replay: true)", "false or true",
       "without gate_d2, gate confirmed tracks with the chi-square gate of gate_probability (same as --board-gate)"},
      {"robust_gate_factor", shortest(d.robust_gate_factor) + " (off)", "0 or > 1",
       "with the board's gate, take plots up to this factor x the gate's d2 with a shrunk innovation "
       "(same as --robust-gate)"},
  };
  for (const RadarKey& k : kRadarKeys) t.push_back({k.key, shortest(k.get(d)), range_text(k), k.meaning});
  t.push_back({"imm.KEY", "docs/imm.md", "docs/imm.md", "an IMM parameter (same as --imm KEY=VALUE)"});
  return t;
}

}  // namespace kestrel::sim
