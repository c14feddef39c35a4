// SPDX-License-Identifier: Apache-2.0
#include "filters/r2aekf_filters.hpp"

#include <cstdio>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "filters/ekf_ca.hpp"
#include "filters/settings.hpp"
#include "kestrel/host/board.hpp"
#include "kestrel/scalar/fixed_point_eigen.hpp"
#include "kestrel/scalar/fixed_point_math.hpp"
#include "pipeline/stream_run.hpp"

namespace kestrel::sim {

namespace {

template <class Scalar>
R2AekfConfig<Scalar> convert(const R2AekfConfig<double>& c) {
  using T = ScalarTraits<Scalar>;
  R2AekfConfig<Scalar> o;
  o.mode = c.mode;
  o.beta_r = T::from_double(c.beta_r);
  o.beta_b = T::from_double(c.beta_b);
  o.alpha_r = T::from_double(c.alpha_r);
  o.delta = T::from_double(c.delta);
  o.r_min = T::from_double(c.r_min);
  o.r_max = T::from_double(c.r_max);
  o.u_r = T::from_double(c.u_r);
  o.d_r = T::from_double(c.d_r);
  o.rho = T::from_double(c.rho);
  o.nis_threshold = T::from_double(c.nis_threshold);
  o.tau0 = T::from_double(c.tau0);
  o.printed_eq16 = c.printed_eq16;
  o.beta_q = T::from_double(c.beta_q);
  o.delta_q = T::from_double(c.delta_q);
  o.alpha_q_ax = T::from_double(c.alpha_q_ax);
  o.alpha_q_lat = T::from_double(c.alpha_q_lat);
  o.q_min = T::from_double(c.q_min);
  o.q_max = T::from_double(c.q_max);
  o.u_q = T::from_double(c.u_q);
  o.d_q = T::from_double(c.d_q);
  o.q_form = c.q_form;
  o.min_speed_mps = T::from_double(c.min_speed_mps);
  return o;
}

/// The board's tracker around an R2AekfCa or the logging wrapper (built
/// without the adaptive noise: it refuses a gain).
template <class Filter>
std::unique_ptr<host::BoardRadarTracker<Filter>> make_tracker_of(const FilterOptions& options,
                                                                 const Filter& prototype) {
  return make_sim_radar_tracker<host::BoardRadarTracker<Filter>>(prototype, options, radar_tracker_params(options));
}

template <class Scalar>
R2AekfCa<Scalar> make_filter(const FilterOptions& options, const R2AekfConfig<Scalar>& config) {
  if (!config.valid()) throw std::invalid_argument("R2-AEKF config out of range");
  return ca_polar_filter<R2AekfCa<Scalar>>(radar_tracker_params(options), config);
}

template <class Scalar>
StreamRunResult run_with(StreamInput stream, const FilterOptions& options,
                         const R2AekfConfig<Scalar>& config, std::uint64_t budget_ns) {
  const auto tracker = make_tracker_of(options, make_filter<Scalar>(options, config));
  return run_stream(*tracker, std::move(stream), budget_ns);
}

/// R2AekfCa<double> that appends its adaptation after every successful
/// update to a log owned by the run (reserved up front, so the loop does
/// not allocate). Host-only instrumentation: the Tracker calls update() on
/// this type, which hides the base's.
class LoggingR2Aekf : public R2AekfCa<double> {
 public:
  using Base = R2AekfCa<double>;
  LoggingR2Aekf() = default;
  LoggingR2Aekf(const Base& base, std::vector<ScaleSample>* log) : Base(base), log_(log) {}

  [[nodiscard]] Status update(const MeasVec& z) {
    const Status s = Base::update(z);
    if (s == Status::kOk && log_ != nullptr) {
      const auto& a = adaptation();
      ScaleSample r;
      r.x_m = x()(Layout::kX);
      r.y_m = x()(Layout::kY);
      r.s_r_range = a.s_r_range;
      r.s_r_bearing = a.s_r_bearing;
      r.s_q_axial = a.s_q_axial;
      r.s_q_lateral = a.s_q_lateral;
      r.s_q_x = a.q_mix(0, 0);
      r.s_q_y = a.q_mix(1, 1);
      r.e_range = a.e(0);
      r.e_bearing = a.e(1);
      r.spread_range = a.spread(0);
      r.spread_bearing = a.spread(1);
      r.d2 = a.d2;
      r.robust_gated = a.robust_gated;
      r.phi_axial = a.phi_axial;
      r.phi_lateral = a.phi_lateral;
      log_->push_back(r);
    }
    return s;
  }

 private:
  std::vector<ScaleSample>* log_ = nullptr;
};

R2AekfConfig<double> g_study_config{};

StreamRunResult run_study(StreamInput stream, const FilterOptions& options, std::uint64_t budget_ns) {
  return run_with<double>(std::move(stream), options, g_study_config, budget_ns);
}

FilterSetup study_setup(const FilterOptions& options) {
  return r2aekf_setup_for(options, g_study_config, "R2-AEKF study variant (double)");
}

FilterEntry g_study_entry{"r2aekf-study", "R2-AEKF with the study's config (not registered)", hal::FrameKind::kRadar,
                          &study_setup, &run_study};

}  // namespace

template <class Scalar>
host::BoardRadarTracker<R2AekfCa<Scalar>> make_r2aekf_tracker(const FilterOptions& options,
                                                              const R2AekfConfig<Scalar>& config) {
  return *make_tracker_of(options, make_filter<Scalar>(options, config));
}

template host::BoardRadarTracker<R2AekfCa<double>> make_r2aekf_tracker<double>(const FilterOptions&,
                                                                               const R2AekfConfig<double>&);
template host::BoardRadarTracker<R2AekfCa<float>> make_r2aekf_tracker<float>(const FilterOptions&,
                                                                             const R2AekfConfig<float>&);

FilterSetup r2aekf_setup_for(const FilterOptions& options, const R2AekfConfig<double>& c, const char* label) {
  const RadarTrackerParams p = radar_tracker_params(options);
  char text[160];
  std::snprintf(text, sizeof text, "%s, qj %g%s", label, p.qj, gate_label(options).c_str());
  FilterSetup setup{text,
                     {{"paper_mode", c.mode == R2AekfMode::kPaper ? 1.0 : 0.0},
                      {"beta_r", c.beta_r},
                      {"beta_b", c.beta_b},
                      {"alpha_r", c.alpha_r},
                      {"delta", c.delta},
                      {"r_min", c.r_min},
                      {"r_max", c.r_max},
                      {"u_r", c.u_r},
                      {"d_r", c.d_r},
                      {"rho", c.rho},
                      {"nis_threshold", c.nis_threshold},
                      {"tau0", c.tau0},
                      {"printed_eq16", c.printed_eq16 ? 1.0 : 0.0},
                      {"beta_q", c.beta_q},
                      {"delta_q", c.delta_q},
                      {"alpha_q_ax", c.alpha_q_ax},
                      {"alpha_q_lat", c.alpha_q_lat},
                      {"q_min", c.q_min},
                      {"q_max", c.q_max},
                      {"u_q", c.u_q},
                      {"d_q", c.d_q},
                      {"full_rotated_q", c.q_form == R2AekfQForm::kFullRotated ? 1.0 : 0.0}}};
  add_radar_parameters(p, setup.parameters);
  add_gate_parameters(options, setup.parameters);
  return setup;
}

FilterSetup r2aekf_setup(const FilterOptions& options) {
  return r2aekf_setup_for(options, R2AekfConfig<double>{}, "R2-AEKF default mode (double)");
}
FilterSetup r2aekf_paper_setup(const FilterOptions& options) {
  return r2aekf_setup_for(options, R2AekfConfig<double>::paper(), "R2-AEKF paper mode (double)");
}
FilterSetup r2aekf_f32_setup(const FilterOptions& options) {
  return r2aekf_setup_for(options, R2AekfConfig<double>{}, "R2-AEKF default mode (float)");
}
FilterSetup r2aekf_q31_32_setup(const FilterOptions& options) {
  return r2aekf_setup_for(options, R2AekfConfig<double>{}, "R2-AEKF default mode (Q31.32)");
}

StreamRunResult run_r2aekf(StreamInput stream, const FilterOptions& options, std::uint64_t budget_ns) {
  return run_with<double>(std::move(stream), options, R2AekfConfig<double>{}, budget_ns);
}
StreamRunResult run_r2aekf_paper(StreamInput stream, const FilterOptions& options,
                                 std::uint64_t budget_ns) {
  return run_with<double>(std::move(stream), options, R2AekfConfig<double>::paper(), budget_ns);
}
StreamRunResult run_r2aekf_f32(StreamInput stream, const FilterOptions& options,
                               std::uint64_t budget_ns) {
  return run_with<float>(std::move(stream), options, R2AekfConfig<float>{}, budget_ns);
}
StreamRunResult run_r2aekf_q31_32(StreamInput stream, const FilterOptions& options,
                                  std::uint64_t budget_ns) {
  return run_with<Q31_32>(std::move(stream), options, convert<Q31_32>(R2AekfConfig<double>{}), budget_ns);
}

const FilterEntry& r2aekf_study_entry(const R2AekfConfig<double>& config) {
  if (!config.valid()) throw std::invalid_argument("R2-AEKF config out of range");
  g_study_config = config;
  return g_study_entry;
}

LoggedR2AekfRun run_r2aekf_logged(std::vector<std::uint8_t> stream, const FilterOptions& options,
                                  const R2AekfConfig<double>& config, std::uint64_t budget_ns) {
  using Tracker = host::BoardRadarTracker<LoggingR2Aekf>;
  std::vector<ScaleSample> log;
  // At most one update per track and frame; a frame is at least a header.
  log.reserve((stream.size() / 16 + 1) * Tracker::Table::kMaxTracks);
  const auto tracker = make_tracker_of(options, LoggingR2Aekf(make_filter<double>(options, config), &log));
  LoggedR2AekfRun out;
  out.stream = run_stream(*tracker, std::move(stream), budget_ns);

  // Join: a report of an associated track carries the state its update
  // produced, bit for bit, so the sample with the same (x, y) is its own.
  // Samples are in update order and reports in frame order, so one forward
  // scan suffices; an unmatched sample (a track never reported) is skipped.
  std::size_t next = 0;
  for (const FrameOutcome& f : out.stream.frames) {
    for (const host::TrackRow& row : f.tracks) {
      if (!row.associated) continue;
      for (std::size_t i = next; i < log.size(); ++i) {
        if (log[i].x_m == row.x_m && log[i].y_m == row.y_m) {
          ScaleSample s = log[i];
          s.time_s = row.time_s;
          s.track_id = row.track_id;
          out.scales.push_back(s);
          next = i + 1;
          break;
        }
      }
    }
  }
  return out;
}

void write_scale_csv(const std::filesystem::path& path, const std::vector<ScaleSample>& scales) {
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "w"), &std::fclose);
  if (!file) throw std::runtime_error("cannot create scale CSV '" + path.string() + "'");
  std::FILE* f = file.get();
  std::fprintf(f,
               "time_s,track_id,s_r_range,s_r_bearing,s_q_axial,s_q_lateral,s_q_x,s_q_y,e_range,e_bearing,"
               "spread_range,spread_bearing,d2,robust_gated,phi_axial,phi_lateral\n");
  for (const ScaleSample& s : scales) {
    std::fprintf(f, "%.6f,%u,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%d,%.6g,%.6g\n", s.time_s,
                 s.track_id, s.s_r_range, s.s_r_bearing, s.s_q_axial, s.s_q_lateral, s.s_q_x, s.s_q_y, s.e_range,
                 s.e_bearing, s.spread_range, s.spread_bearing, s.d2, s.robust_gated ? 1 : 0, s.phi_axial,
                 s.phi_lateral);
  }
  if (std::ferror(f) != 0) throw std::runtime_error("cannot write scale CSV '" + path.string() + "'");
}

}  // namespace kestrel::sim
