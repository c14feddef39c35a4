// SPDX-License-Identifier: Apache-2.0
#include "filters/settings.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "filters/parameter_key.hpp"
#include "filters/sensor_settings.hpp"

namespace kestrel::sim {

namespace {

using RadarKey = ParameterKey<RadarTrackerParams>;
using P = RadarTrackerParams;

constexpr KeyRange kPositive{0.0, true};
// The largest whole number a double holds exactly, a bound for the us fields.
constexpr KeyRange kPositiveMicroseconds{0.0, true, 9007199254740992.0};

// clang-format off
const RadarKey kRadarKeys[] = {
  field_key<&P::sigma_range_m>("sigma_range_m", kPositive, "range noise sigma of the sensor, m"),
  field_key<&P::sigma_bearing_rad>("sigma_bearing_rad", kPositive, "bearing noise sigma of the sensor, rad"),
  field_key<&P::max_speed_mps>("max_speed_mps", kPositive, "two-point initiation refuses plot pairs faster than this, m/s"),
  field_key<&P::init_accel_sigma_mps2>("init_accel_sigma_mps2", kPositive, "initial acceleration sigma of a new track, m/s^2"),
  field_key<&P::max_range_m>("max_range_m", kPositive, "plots beyond this range are refused as out of range, m"),
  field_key<&P::max_position_variance_m2>("max_position_variance_m2", kPositive,
                                          "a track whose var(x) + var(y) exceeds this is deleted, m^2"),
  field_key<&P::gate>("gate_probability", {},
                      "chi-square gate of tentative tracks, and of confirmed ones under the board's gate"),
  field_key<&P::robust_noise_gain>("robust_noise_gain", {0.0, false, 1.0},
                                   "with the robust gate, the weight of each plot's NIS excess in a confirmed track's "
                                   "scale of R (0: off; ekf-ca and imm only, the other filters refuse a gain)"),
  field_key<&P::robust_noise_max_scale>("robust_noise_max_scale", {1.0},
                                        "with the robust gate, the largest scale of R a confirmed track fuses with (1: off)"),
  field_key<&P::confirm_m>("confirm_m", {1.0, false, 8.0},
                           "M of M-of-N confirmation (the seed and the pairing plot count), <= confirm_n"),
  field_key<&P::confirm_n>("confirm_n", {1.0, false, 8.0}, "N of M-of-N confirmation, frames"),
  field_key<&P::seed_extra_frames>("seed_extra_frames", {0.0, false, 7.0},
                                   "two-point initiation: frames after the next one in which a seed still pairs, even "
                                   "after it has paired (0: the next frame only)"),
  field_key<&P::seed_from_pairs>("seed_from_pairs", {},
                                 "two-point initiation: the plot that completes a pair also starts a seed"),
  field_key<&P::max_coast_misses>("max_coast_misses", {0.0, false, 65535.0},
                                  "a confirmed track is deleted after more misses in a row than this"),
  field_key<&P::max_predict_us>("max_predict_us", kPositiveMicroseconds,
                                "a track older than this at a frame is deleted, not extrapolated, us"),
  field_key<&P::max_forward_jump_us>("max_forward_jump_us", kPositiveMicroseconds,
                                     "a frame this far after the last accepted one is refused (kTimeJumpedForward), us"),
  field_key<&P::resync_frames>("resync_frames", {0.0, false, 255.0},
                               "consistent refused frames before the tracker restarts on the new clock (0: never)"),
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

[[noreturn]] void refuse(const Setting& s, const std::string& why) {
  throw std::invalid_argument(s.origin + " " + s.key + "=" + shortest_text(s.value) + ": " + why);
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
    if (!key_accepts(k->type, k->range, s.value)) refuse(s, "out of range (" + range_text(k->type, k->range) + ")");
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
      {"qj", shortest_text(d.qj) + " (IMM: its CA mode's)", "> 0", "white-jerk PSD of CA models, m^2/s^5 (same as --qj)"},
      {"gate_d2", "ungated (replay: the board's gate)", "> 0",
       "gate of confirmed tracks in d2 = nu' S^-1 nu units (same as --gate-d2)"},
      {"board_gate", "false (replay: true)", "false or true",
       "without gate_d2, gate confirmed tracks with the chi-square gate of gate_probability (same as --board-gate)"},
      {"robust_gate_factor", shortest_text(d.robust_gate_factor) + " (off)", "0 or > 1",
       "with the board's gate, take plots up to this factor x the gate's d2 with a shrunk innovation "
       "(same as --robust-gate)"},
  };
  for (const RadarKey& k : kRadarKeys) t.push_back({k.key, default_text(k, d), range_text(k.type, k.range), k.meaning});
  t.push_back({"imm.KEY", "docs/imm.md", "docs/imm.md", "an IMM parameter (same as --imm KEY=VALUE)"});
  return t;
}

}  // namespace kestrel::sim
