// SPDX-License-Identifier: Apache-2.0
#include "scenarios/uw003.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

#include "scenarios/rng.hpp"

namespace kestrel::sim {

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  return s;
}

double path_length(const SonarTruth& t, const std::array<double, 3>& b, hal::ToaPath path, double seabed_m) {
  const double z = path == hal::ToaPath::kDirect ? t.z_m : 2.0 * seabed_m - t.z_m;
  const double dx = t.x_m - b[0];
  const double dy = t.y_m - b[1];
  const double dz = z - b[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

}  // namespace

SonarScenarioParams uw003_config() {
  SonarScenarioParams c;
  c.name = "uw003";
  c.description = "UW-003: 4 surface beacons, seabed 150 m, direct + reflected TOA, 3 ms, 5 % outliers";
  return c;
}

std::vector<std::string> sonar_scenario_names() {
  return {"uw003", "uw003-direct", "uw003-clean", "uw003-d100", "uw003-1ms"};
}

SonarScenarioParams sonar_config_by_name(const std::string& name) {
  const std::string n = lower(name);
  SonarScenarioParams c = uw003_config();
  if (n == "uw003") return c;
  c.name = n;
  if (n == "uw003-direct") {
    c.reflected = false;
    c.description = "UW-003 with direct arrivals only";
  } else if (n == "uw003-clean") {
    c.outlier_probability = 0.0;
    c.description = "UW-003 without outliers";
  } else if (n == "uw003-d100") {
    c.seabed_depth_m = 100.0;
    c.description = "UW-003 with the seabed at 100 m";
  } else if (n == "uw003-1ms") {
    c.sigma_toa_s = 1e-3;
    c.description = "UW-003 with 1 ms TOA noise";
  } else {
    throw std::invalid_argument("unknown UW scenario '" + name +
                                "' (uw003, uw003-direct, uw003-clean, uw003-d100, uw003-1ms)");
  }
  return c;
}

SonarScenarioRun generate_sonar(const SonarScenarioParams& cfg, std::uint64_t seed) {
  if (cfg.beacons_m.empty() || cfg.beacons_m.size() * 2 > hal::kMaxSonarArrivals) {
    throw std::invalid_argument("UW scenario: 1..8 beacons");
  }
  Rng rng(seed);
  SonarScenarioRun run;
  SonarTruth s;
  s.x_m = cfg.start_m[0];
  s.y_m = cfg.start_m[1];
  s.z_m = cfg.start_m[2];
  s.vx_mps = cfg.start_v_mps[0];
  s.vy_mps = cfg.start_v_mps[1];
  s.vz_mps = cfg.start_v_mps[2];
  s.c_mps = cfg.sound_speed_mps;
  const double T = cfg.period_s;
  const double z_lo = 1.0;
  const double z_hi = cfg.seabed_depth_m - 1.0;
  for (std::size_t k = 0; k < cfg.frames; ++k) {
    // The target and the medium move between pings; frame 0 is the start.
    const double ax = rng.normal(cfg.accel_sigma_mps2);
    const double ay = rng.normal(cfg.accel_sigma_mps2);
    const double az = rng.normal(cfg.accel_sigma_mps2);
    const double dc = rng.normal(cfg.sound_speed_step_mps);
    if (k > 0) {
      s.x_m += s.vx_mps * T + 0.5 * ax * T * T;
      s.y_m += s.vy_mps * T + 0.5 * ay * T * T;
      s.z_m += s.vz_mps * T + 0.5 * az * T * T;
      s.vx_mps += ax * T;
      s.vy_mps += ay * T;
      s.vz_mps += az * T;
      if (s.z_m < z_lo || s.z_m > z_hi) {
        s.z_m = s.z_m < z_lo ? 2.0 * z_lo - s.z_m : 2.0 * z_hi - s.z_m;
        s.vz_mps = -s.vz_mps;
        ++run.depth_reflections;
      }
      s.c_mps = std::clamp(s.c_mps + dc, cfg.sound_speed_mps - cfg.sound_speed_limit_mps,
                           cfg.sound_speed_mps + cfg.sound_speed_limit_mps);
    }
    s.t_s = static_cast<double>(k) * T;
    run.truth.push_back(s);

    SonarFrameRecord f;
    f.wire.kind = hal::FrameKind::kSonar;
    f.wire.t_us = std::llround(s.t_s * 1e6);
    f.wire.count = 0;
    for (std::size_t b = 0; b < cfg.beacons_m.size(); ++b) {
      for (const hal::ToaPath path : {hal::ToaPath::kDirect, hal::ToaPath::kReflected}) {
        const double noise = rng.normal(cfg.sigma_toa_s);
        const double coin = rng.uniform();
        const double delay = rng.uniform(cfg.outlier_min_s, cfg.outlier_max_s);
        if (path == hal::ToaPath::kReflected && !cfg.reflected) continue;
        SonarArrivalRecord a;
        a.beacon = static_cast<std::uint8_t>(b);
        a.path = path;
        a.true_toa_s = path_length(s, cfg.beacons_m[b], path, cfg.seabed_depth_m) / s.c_mps;
        a.outlier = coin < cfg.outlier_probability;
        a.outlier_s = a.outlier ? delay : 0.0;
        a.toa_s = a.true_toa_s + noise + a.outlier_s;
        const double ns = std::round(a.toa_s * 1e9);
        hal::SonarArrival& w = f.wire.sonar[f.wire.count++];
        w.time_of_flight_ns = static_cast<std::uint32_t>(std::clamp(ns, 0.0, 4294967295.0));
        w.beacon_id = a.beacon;
        w.path = path;
        f.arrivals.push_back(a);
      }
    }
    run.frames.push_back(std::move(f));
  }
  return run;
}

}  // namespace kestrel::sim
