// SPDX-License-Identifier: Apache-2.0
#include "filters/imm_filters.hpp"

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "filters/settings.hpp"
#include "kestrel/tracking/radar_tracker.hpp"
#include "pipeline/stream_run.hpp"

namespace kestrel::sim {

namespace {

double parse_value(const std::string& item, const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end == nullptr || *end != '\0') {
    throw std::invalid_argument("--imm " + item + ": the value is not a number");
  }
  return v;
}

void apply(RadarImmParams& p, const std::string& item) {
  const std::size_t eq = item.find('=');
  if (eq == std::string::npos) throw std::invalid_argument("--imm " + item + ": expected KEY=VALUE");
  const std::string key = item.substr(0, eq);
  const double v = parse_value(item, item.substr(eq + 1));
  if (key == "cv_sa") {
    p.cv_sa_mps2 = v;
  } else if (key == "ca_qj") {
    p.ca_qj = v;
  } else if (key == "ct_sa") {
    p.ct_sa_mps2 = v;
  } else if (key == "ct_sw") {
    p.ct_sw_radps = v;
  } else if (key == "p_stay") {
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) p.switching[i][j] = i == j ? v : (1.0 - v) / 2.0;
    }
  } else if (key.size() == 3 && key[0] == 'p' && key[1] >= '0' && key[1] <= '2' && key[2] >= '0' && key[2] <= '2') {
    p.switching[key[1] - '0'][key[2] - '0'] = v;
  } else if (key == "switch_period") {
    p.switching_period_s = v;
  } else if (key == "mu_cv") {
    p.initial_probabilities[0] = v;
  } else if (key == "mu_ca") {
    p.initial_probabilities[1] = v;
  } else if (key == "mu_ct") {
    p.initial_probabilities[2] = v;
  } else if (key == "min_prob") {
    p.min_probability = v;
  } else if (key == "pad_a") {
    p.accel_pad_sigma_mps2 = v;
  } else if (key == "pad_w") {
    p.turn_rate_pad_sigma_radps = v;
  } else {
    throw std::invalid_argument("--imm " + item + ": unknown key (filters/imm_filters.hpp lists them)");
  }
}

/// make_imm_tracker's tracker, off the stack.
template <class Scalar>
std::unique_ptr<SimRadarTracker<RadarImm<Scalar>>> imm_tracker_on_heap(const FilterOptions& options) {
  const RadarTrackerParams tp = radar_tracker_params(options);  // initiation and management of "ekf-ca"
  return make_sim_radar_tracker<SimRadarTracker<RadarImm<Scalar>>>(make_radar_imm<Scalar>(imm_params(options)),
                                                                    options, tp);
}

template <class Scalar>
StreamRunResult run_typed(StreamInput stream, const FilterOptions& options, std::uint64_t budget_ns) {
  StreamRunResult r = run_stream(*imm_tracker_on_heap<Scalar>(options), std::move(stream), budget_ns);
  r.mode_names = {"cv", "ca", "ct"};  // RadarImm's mode order
  return r;
}

FilterSetup setup_with(const FilterOptions& options, const char* scalar) {
  const RadarImmParams p = imm_params(options);
  char label[160];
  std::snprintf(label, sizeof label, "IMM CV/CA/CT (%s), cv_sa %g, ca_qj %g, ct_sa %g, ct_sw %g, p_stay %g/%g/%g%s",
                scalar, p.cv_sa_mps2, p.ca_qj, p.ct_sa_mps2, p.ct_sw_radps, p.switching[0][0], p.switching[1][1],
                p.switching[2][2], gate_label(options).c_str());
  FilterSetup s{label,
                {{"cv_sa_mps2", p.cv_sa_mps2},
                 {"ca_qj", p.ca_qj},
                 {"ct_sa_mps2", p.ct_sa_mps2},
                 {"ct_sw_radps", p.ct_sw_radps},
                 {"mu0_cv", p.initial_probabilities[0]},
                 {"mu0_ca", p.initial_probabilities[1]},
                 {"mu0_ct", p.initial_probabilities[2]},
                 {"min_probability", p.min_probability},
                 {"accel_pad_sigma_mps2", p.accel_pad_sigma_mps2},
                 {"turn_rate_pad_sigma_radps", p.turn_rate_pad_sigma_radps},
                 {"switching_period_s", p.switching_period_s}}};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      s.parameters["p" + std::to_string(i) + std::to_string(j)] = p.switching[i][j];
    }
  }
  add_radar_parameters(radar_tracker_params(options), s.parameters);
  s.parameters.erase("qj");  // the IMM's CA mode has ca_qj
  add_gate_parameters(options, s.parameters);
  return s;
}

}  // namespace

RadarImmParams imm_params(const FilterOptions& options) {
  RadarImmParams p;  // mode noise and matrix: docs/imm.md
  // The sensor is the radar tracker's (S1/S2 by default, or as set).
  const RadarTrackerParams radar = radar_tracker_params(options);
  p.sigma_range_m = radar.sigma_range_m;
  p.sigma_bearing_rad = radar.sigma_bearing_rad;
  if (options.qj.has_value()) p.ca_qj = *options.qj;
  for (const std::string& item : options.imm) apply(p, item);
  if (!make_radar_imm<double>(p).params().valid()) {
    throw std::invalid_argument("--imm: the switching matrix, probabilities or pads are not valid (docs/imm.md)");
  }
  return p;
}

template <class Scalar>
SimRadarTracker<RadarImm<Scalar>> make_imm_tracker(const FilterOptions& options) {
  return *imm_tracker_on_heap<Scalar>(options);
}

template SimRadarTracker<RadarImm<double>> make_imm_tracker<double>(const FilterOptions&);
template SimRadarTracker<RadarImm<float>> make_imm_tracker<float>(const FilterOptions&);

FilterSetup imm_setup(const FilterOptions& options) { return setup_with(options, "double"); }
FilterSetup imm_f32_setup(const FilterOptions& options) { return setup_with(options, "float"); }

StreamRunResult run_imm(StreamInput stream, const FilterOptions& options, std::uint64_t budget_ns) {
  return run_typed<double>(std::move(stream), options, budget_ns);
}

StreamRunResult run_imm_f32(StreamInput stream, const FilterOptions& options, std::uint64_t budget_ns) {
  return run_typed<float>(std::move(stream), options, budget_ns);
}

}  // namespace kestrel::sim
