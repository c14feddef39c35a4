// SPDX-License-Identifier: Apache-2.0
#include "metrics/sonar_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

namespace kestrel::sim {

namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

std::uint32_t channel_bit(const SonarArrivalRecord& a) {
  return 1u << (2u * a.beacon + static_cast<std::uint32_t>(a.path));
}

}  // namespace

SonarRunMetrics score_sonar_run(const SonarScenarioRun& run, const SonarRunOutput& out) {
  SonarRunMetrics m;
  m.depth_reflections = run.depth_reflections;
  const std::size_t n = std::min(run.frames.size(), out.frames.size());
  m.e3_sq.assign(n, kNan);
  m.eh_sq.assign(n, kNan);
  m.ed_sq.assign(n, kNan);
  m.c_err.assign(n, kNan);
  double s3 = 0, sh = 0, sd = 0, snees = 0, sc = 0, sc2 = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const SonarFrameOutcome& f = out.frames[k];
    if (!f.stepped || f.status != Status::kOk) {
      ++m.frames_refused;
      continue;
    }
    m.step_ns.push_back(f.step_ns);
    for (const SonarArrivalRecord& a : run.frames[k].arrivals) {
      ++m.arrivals;
      const bool gated = (f.gated & channel_bit(a)) != 0;
      if (a.outlier) ++m.outliers;
      if (gated) ++m.gated;
      if (gated && a.outlier) ++m.outliers_gated;
      if (gated && !a.outlier) ++m.good_gated;
    }
    if (f.predict_only) ++m.predict_only;
    if (f.initialised) {
      if (m.init_frame < 0) {
        m.init_frame = static_cast<int>(k);
        continue;  // the fix frame is not scored
      }
      ++m.reinitialisations;
    }
    if (m.init_frame < 0 || !f.reported) continue;
    const SonarTruth& t = run.truth[k];
    const Eigen::Vector3d e(f.x[0] - t.x_m, f.x[1] - t.y_m, f.x[2] - t.z_m);
    Eigen::Matrix3d P;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) P(i, j) = f.p_pos[static_cast<std::size_t>(3 * i + j)];
    }
    const double e3 = e.squaredNorm();
    const double eh = e(0) * e(0) + e(1) * e(1);
    const double ed = e(2) * e(2);
    const double ce = f.x[6] - t.c_mps;
    m.e3_sq[k] = e3;
    m.eh_sq[k] = eh;
    m.ed_sq[k] = ed;
    m.c_err[k] = ce;
    s3 += e3;
    sh += eh;
    sd += ed;
    snees += e.dot(P.ldlt().solve(e));
    sc += ce;
    sc2 += ce * ce;
    m.peak_3d_m = std::max(m.peak_3d_m, std::sqrt(e3));
    ++m.scored_frames;
  }
  if (m.scored_frames == 0) {
    m.rmse_3d_m = m.rmse_h_m = m.rmse_depth_m = m.peak_3d_m = m.nees = m.c_err_mean_mps = m.c_err_std_mps = kNan;
    return m;
  }
  const double ns = static_cast<double>(m.scored_frames);
  m.rmse_3d_m = std::sqrt(s3 / ns);
  m.rmse_h_m = std::sqrt(sh / ns);
  m.rmse_depth_m = std::sqrt(sd / ns);
  m.nees = snees / ns;
  m.c_err_mean_mps = sc / ns;
  m.c_err_std_mps = std::sqrt(std::max(0.0, sc2 / ns - m.c_err_mean_mps * m.c_err_mean_mps));
  return m;
}

SonarSummary summarise_sonar(const std::vector<SonarRunMetrics>& runs, std::uint64_t budget_ns) {
  SonarSummary s;
  s.runs = runs.size();
  s.rmse_3d_m = mean_ci95_of(runs, &SonarRunMetrics::rmse_3d_m);
  s.rmse_h_m = mean_ci95_of(runs, &SonarRunMetrics::rmse_h_m);
  s.rmse_depth_m = mean_ci95_of(runs, &SonarRunMetrics::rmse_depth_m);
  s.peak_3d_m = mean_ci95_of(runs, &SonarRunMetrics::peak_3d_m);
  s.nees = mean_ci95_of(runs, &SonarRunMetrics::nees);
  s.c_err_std_mps = mean_ci95_of(runs, &SonarRunMetrics::c_err_std_mps);
  s.c_err_mean_mps = mean_ci95_of(runs, &SonarRunMetrics::c_err_mean_mps);
  std::size_t frames = 0;
  for (const SonarRunMetrics& r : runs) frames = std::max(frames, r.e3_sq.size());
  std::vector<double> a3(frames, 0.0), ah(frames, 0.0), ad(frames, 0.0), ac(frames, 0.0);
  s.step_runs.assign(frames, 0);
  double pc = 0, pc2 = 0;
  std::size_t pn = 0;
  std::vector<std::uint64_t> step_ns;
  for (const SonarRunMetrics& r : runs) {
    if (r.init_frame < 0) ++s.runs_not_initialised;
    if (r.init_frame > 0) ++s.runs_late_init;
    s.arrivals += r.arrivals;
    s.outliers += r.outliers;
    s.outliers_gated += r.outliers_gated;
    s.good_gated += r.good_gated;
    s.gated += r.gated;
    s.predict_only += r.predict_only;
    s.reinitialisations += r.reinitialisations;
    s.frames_refused += r.frames_refused;
    s.depth_reflections += r.depth_reflections;
    step_ns.insert(step_ns.end(), r.step_ns.begin(), r.step_ns.end());
    for (std::size_t k = 0; k < r.e3_sq.size(); ++k) {
      if (!std::isfinite(r.e3_sq[k])) continue;
      a3[k] += r.e3_sq[k];
      ah[k] += r.eh_sq[k];
      ad[k] += r.ed_sq[k];
      ac[k] += r.c_err[k] * r.c_err[k];
      ++s.step_runs[k];
      pc += r.c_err[k];
      pc2 += r.c_err[k] * r.c_err[k];
      ++pn;
    }
  }
  for (std::size_t k = 0; k < frames; ++k) {
    const double c = static_cast<double>(s.step_runs[k]);
    s.step_rmse_3d_m.push_back(c > 0 ? std::sqrt(a3[k] / c) : kNan);
    s.step_rmse_h_m.push_back(c > 0 ? std::sqrt(ah[k] / c) : kNan);
    s.step_rmse_depth_m.push_back(c > 0 ? std::sqrt(ad[k] / c) : kNan);
    s.step_c_err_rms_mps.push_back(c > 0 ? std::sqrt(ac[k] / c) : kNan);
  }
  if (pn > 0) {
    s.pooled_c_err_mean_mps = pc / static_cast<double>(pn);
    s.pooled_c_err_std_mps =
        std::sqrt(std::max(0.0, pc2 / static_cast<double>(pn) - s.pooled_c_err_mean_mps * s.pooled_c_err_mean_mps));
  } else {
    s.pooled_c_err_mean_mps = s.pooled_c_err_std_mps = kNan;
  }
  s.timing = summarise_step_times(step_ns, budget_ns);
  return s;
}

SonarMonteCarloResult run_sonar_monte_carlo(const SonarScenarioParams& scenario, const SonarTrackerParams& params,
                                            const SonarMonteCarloParams& config) {
  return run_seeded<SonarMonteCarloResult>(
      config.runs, config.base_seed, config.jobs, scenario.name.c_str(),
      [&](std::uint64_t seed) { return generate_sonar(scenario, seed); },
      [&](const SonarScenarioRun& run) { return run_sonar(run, params, config.budget_ns); },
      [](const SonarScenarioRun& run, const SonarRunOutput& out) { return score_sonar_run(run, out); });
}

}  // namespace kestrel::sim
