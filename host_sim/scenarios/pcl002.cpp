// SPDX-License-Identifier: Apache-2.0
#include "scenarios/pcl002.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "kestrel/models/measurement/bistatic_geometry.hpp"
#include "kestrel/models/measurement/bistatic_range_rate.hpp"
#include "scenarios/rng.hpp"
#include "stream/quantise.hpp"

namespace kestrel::sim {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kIntegrationStepS = 0.01;  // 50 sub-steps per 0.5 s frame
constexpr std::uint32_t kMaxTrajectoryAttempts = 1000;

/// splitmix64: independent sub-seeds from one seed.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

double wrap(double a) { return std::remainder(a, 2.0 * kPi); }

/// A smooth random signal with |s(t)| <= 1: three sinusoids of random
/// period in [period_min, period_max], phase and weight (weights sum to 1).
struct Smooth {
  double a[3], w[3], phi[3];
  double operator()(double t) const {
    double s = 0.0;
    for (int i = 0; i < 3; ++i) s += a[i] * std::sin(w[i] * t + phi[i]);
    return s;
  }
};

Smooth draw_smooth(Rng& r, double period_min, double period_max) {
  Smooth s{};
  double sum = 0.0;
  for (int i = 0; i < 3; ++i) {
    s.a[i] = r.uniform(0.2, 1.0);
    sum += s.a[i];
    s.w[i] = 2.0 * kPi / r.uniform(period_min, period_max);
    s.phi[i] = r.uniform(0.0, 2.0 * kPi);
  }
  for (double& a : s.a) a /= sum;
  return s;
}

struct Sample {
  double x, y, z, vx, vy, vz;
};

/// One attempt at a trajectory; false if it left the scenario's box.
bool simulate_drone(const PclScenarioParams& c, std::uint64_t sub_seed, std::vector<Sample>& out) {
  Rng r(sub_seed);
  // Start well inside the annulus, north of the receiver.
  const double r0 = r.uniform(c.r_min_m + 150.0, c.r_max_m - 150.0);
  const double th0 = r.uniform(0.35, kPi - 0.35);
  double px = r0 * std::cos(th0);
  double py = r0 * std::sin(th0);
  // Horizontal speed stays <= speed_max - 1 and the vertical <= about 3 m/s,
  // so the 3D speed stays under speed_max.
  const double v_max_h = c.speed_max_mps - 1.0;
  double v = r.uniform(8.0, 22.0);
  double psi = r.uniform(-kPi, kPi);
  // Altitude: a slow sinusoid inside the band (vertical acceleration
  // <= 20 (2 pi / 40)^2 = 0.5 m/s^2, leaving 2.8 m/s^2 for horizontal turns
  // under the 3 m/s^2 lateral limit).
  const double h_mid = r.uniform(c.alt_min_m + 20.0, c.alt_max_m - 20.0);
  const double h_amp = r.uniform(0.0, std::min({h_mid - c.alt_min_m, c.alt_max_m - h_mid, 20.0}));
  const double h_w = 2.0 * kPi / r.uniform(40.0, 80.0);
  const double h_phi = r.uniform(0.0, 2.0 * kPi);
  const Smooth s_long = draw_smooth(r, 10.0, 30.0);
  const Smooth s_lat = draw_smooth(r, 8.0, 25.0);
  const double a_lat_max = c.lateral_accel_max_mps2 - 0.2;

  const std::size_t sub = static_cast<std::size_t>(std::llround(c.frame_period_s / kIntegrationStepS));
  const std::size_t steps = c.frames * sub;
  const double cx = 0.0, cy = 0.5 * (c.r_min_m + c.r_max_m);  // steer toward the annulus middle
  const double comfort_in = c.r_min_m + 150.0, comfort_out = c.r_max_m - 150.0, comfort_y = 200.0;
  out.clear();
  for (std::size_t i = 0; i <= steps; ++i) {
    const double t = static_cast<double>(i) * kIntegrationStepS;
    const double vx = v * std::cos(psi), vy = v * std::sin(psi);
    const double rr = std::hypot(px, py);
    if (rr < c.r_min_m || rr > c.r_max_m || py <= 0.0) return false;
    if (i % sub == 0 && out.size() < c.frames) {
      out.push_back(Sample{px, py, h_mid + h_amp * std::sin(h_w * t + h_phi), vx, vy,
                           h_amp * h_w * std::cos(h_w * t + h_phi)});
    }
    if (i == steps) break;
    // Along-track: smooth random within the limit, speed kept in [3, v_max_h].
    const double a_long = c.along_accel_max_mps2 * s_long(t);
    // Lateral: smooth random, blended into a steering turn toward the middle
    // when the point 8 s ahead leaves the comfort zone (continuous blend).
    const double lx = px + 8.0 * vx, ly = py + 8.0 * vy;
    const double lr = std::hypot(lx, ly);
    const double out_by = std::max({comfort_in - lr, lr - comfort_out, comfort_y - ly, 0.0});
    const double blend = std::min(out_by / 100.0, 1.0);
    const double e = wrap(std::atan2(cy - py, cx - px) - psi);
    const double steer = std::clamp(1.0 * e * v, -a_lat_max, a_lat_max);
    const double a_lat = (1.0 - blend) * 2.0 * s_lat(t) + blend * steer;
    px += vx * kIntegrationStepS;
    py += vy * kIntegrationStepS;
    psi = wrap(psi + a_lat / v * kIntegrationStepS);
    v = std::clamp(v + a_long * kIntegrationStepS, 3.0, v_max_h);
  }
  return out.size() == c.frames;
}


std::int32_t to_wire_doppler_mhz(double fd_hz) {
  const double mhz = std::nearbyint(fd_hz * 1000.0);
  if (mhz <= -2147483648.0) return std::numeric_limits<std::int32_t>::min();
  if (mhz >= 2147483647.0) return std::numeric_limits<std::int32_t>::max();
  return static_cast<std::int32_t>(mhz);
}

struct CandidateSi {
  double rb_m, fd_hz, snr_db;
  bool target;
};

}  // namespace

PclScenarioParams pcl002_config() {
  PclScenarioParams c;
  c.name = "pcl002";
  c.description = "PCL-002: DTV passive radar, drone 300-900 m, Pd 0.9, Poisson(21) clutter + 0-3 ridge, 32/scan";
  return c;
}

PclScenarioParams pcl002_hard_config() {
  PclScenarioParams c = pcl002_config();
  c.name = "pcl002-hard";
  c.description = "PCL-002 hard: Poisson(63) clutter, Pd 0.7, 64 candidates per scan";
  c.clutter_mean = 63.0;
  c.pd = 0.7;
  c.scan_capacity = 64;
  return c;
}

std::vector<std::string> pcl_scenario_names() { return {"pcl002", "pcl002-hard"}; }

PclScenarioParams pcl_config_by_name(const std::string& name) {
  std::string key(name);
  for (char& ch : key) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (key == "pcl002") return pcl002_config();
  if (key == "pcl002-hard") return pcl002_hard_config();
  throw std::invalid_argument("unknown PCL scenario '" + name + "' (known: pcl002, pcl002-hard)");
}

double pcl_lambda_m(const PclScenarioParams& config) { return kSpeedOfLightMps / config.carrier_hz; }

PclScenarioRun generate_pcl(const PclScenarioParams& c, std::uint64_t seed) {
  PclScenarioRun run;
  std::vector<Sample> samples;
  std::uint32_t attempt = 0;
  for (;; ++attempt) {
    if (attempt >= kMaxTrajectoryAttempts) throw std::runtime_error("no PCL trajectory met the scenario's box");
    if (simulate_drone(c, mix(mix(seed) + attempt), samples)) break;
  }
  run.trajectory_attempts = attempt + 1;

  const double lambda = pcl_lambda_m(c);
  const Vec<double, 3> tx(c.tx_x_m, c.tx_y_m, c.tx_z_m);
  const Vec<double, 3> rx(0.0, 0.0, 0.0);
  Rng m(mix(seed ^ 0x5CA1AB1EULL));
  for (std::size_t k = 0; k < c.frames; ++k) {
    const Sample& s = samples[k];
    PclTruth tr;
    tr.t_s = static_cast<double>(k) * c.frame_period_s;
    tr.x_m = s.x;
    tr.y_m = s.y;
    tr.z_m = s.z;
    tr.vx_mps = s.vx;
    tr.vy_mps = s.vy;
    tr.vz_mps = s.vz;
    const Vec<double, 3> p(s.x, s.y, s.z), v(s.vx, s.vy, s.vz);
    tr.rb_m = bistatic_range(p, tx, rx);
    tr.drb_mps = bistatic_range_rate(p, v, tx, rx);
    tr.fd_hz = doppler_from_range_rate(tr.drb_mps, lambda);
    run.truth.push_back(tr);

    // The frame: detection, clutter, ridge, SNR, shuffle, 64-candidate cut.
    std::vector<CandidateSi> cands;
    PclFrameRecord rec;
    rec.detected = m.uniform() < c.pd;
    if (rec.detected) {
      const double rb = tr.rb_m + m.normal(c.sigma_rb_m);
      const double fd = tr.fd_hz + m.normal(c.sigma_fd_hz);
      cands.push_back(CandidateSi{rb, fd, 0.0, true});
    }
    const std::size_t n_clutter = m.poisson(c.clutter_mean);
    for (std::size_t i = 0; i < n_clutter; ++i) {
      const double rb = m.uniform(0.0, c.clutter_rb_max_m);
      const double fd = m.uniform(-c.clutter_fd_max_hz, c.clutter_fd_max_hz);
      cands.push_back(CandidateSi{rb, fd, 0.0, false});
    }
    const auto n_ridge = static_cast<std::size_t>(m.uniform() * static_cast<double>(c.ridge_max + 1));
    for (std::size_t i = 0; i < n_ridge; ++i) {
      const double rb = m.uniform(0.0, c.clutter_rb_max_m);
      const double fd = m.uniform(-c.ridge_fd_max_hz, c.ridge_fd_max_hz);
      cands.push_back(CandidateSi{rb, fd, 0.0, false});
    }
    for (CandidateSi& cd : cands) cd.snr_db = m.uniform(12.0, 20.0);
    for (std::size_t i = cands.size(); i > 1; --i) {  // Fisher-Yates
      const auto j = static_cast<std::size_t>(m.uniform() * static_cast<double>(i));
      std::swap(cands[i - 1], cands[j]);
    }
    rec.generated = cands.size();
    if (cands.size() > hal::kMaxPclCandidates) {
      // The extractor sends its kMaxPclCandidates strongest, in frame order.
      std::vector<std::size_t> order(cands.size());
      for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
      std::stable_sort(order.begin(), order.end(),
                       [&](std::size_t a, std::size_t b) { return cands[a].snr_db > cands[b].snr_db; });
      order.resize(hal::kMaxPclCandidates);
      std::sort(order.begin(), order.end());
      std::vector<CandidateSi> kept;
      for (const std::size_t i : order) kept.push_back(cands[i]);
      cands = std::move(kept);
    }
    rec.wire.kind = hal::FrameKind::kPcl;
    rec.wire.t_us = to_wire_time_us(tr.t_s);
    rec.wire.count = static_cast<std::uint16_t>(cands.size());
    for (std::size_t i = 0; i < cands.size(); ++i) {
      // The simulated extractor reports a noisy bistatic range below zero
      // (a target near the baseline) as 0: the field is unsigned.
      // to_wire_range_mm refuses a negative value rather than clamp it.
      const double rb_m = std::max(cands[i].rb_m, 0.0);
      rec.wire.pcl[i] = hal::PclCandidate{to_wire_range_mm(rb_m), to_wire_doppler_mhz(cands[i].fd_hz),
                                          static_cast<std::int16_t>(std::lround(cands[i].snr_db * 100.0))};
      if (cands[i].target) rec.target_index = static_cast<int>(i);
    }
    run.frames.push_back(rec);
  }
  return run;
}

}  // namespace kestrel::sim
