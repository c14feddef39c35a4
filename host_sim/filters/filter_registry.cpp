// SPDX-License-Identifier: Apache-2.0
#include "filters/filter_registry.hpp"

#include <cctype>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "filters/ekf_ca.hpp"
#include "filters/ekf_ca_fixed.hpp"
#include "filters/ekf_ca_rr.hpp"
#include "filters/imm_filters.hpp"
#include "filters/r2aekf_filters.hpp"
#include "filters/radar_filter_family.hpp"
#include "kestrel/tracking/radar_tracker.hpp"

namespace kestrel::sim {

namespace {
// One line per filter.
const FilterEntry kFilters[] = {
    {"ekf-ca", "EKF, CA-2D white jerk, polar radar; double (paper 000 baseline, qj 1.6)",
     hal::FrameKind::kRadar, &ekf_ca_setup, &run_ekf_ca},
    {"ekf-ca-f32", "the same EKF-CA in float (the Cortex-M4F scalar)", hal::FrameKind::kRadar,
     &ekf_ca_f32_setup, &run_ekf_ca_f32},
    {"ekf-ca-q31_32", "the same EKF-CA in Q31.32 fixed point (the Cortex-M0+ scalar)", hal::FrameKind::kRadar,
     &ekf_ca_q31_32_setup, &run_ekf_ca_q31_32},
    {"ekf-ca-q23_40", "the same EKF-CA in Q23.40 fixed point", hal::FrameKind::kRadar, &ekf_ca_q23_40_setup,
     &run_ekf_ca_q23_40},
    {"ekf-ca-rr", "EKF-CA with the plots' range rate (srr 0.5 m/s); double; needs range-rate plots (s1rr, s2rr)",
     hal::FrameKind::kRadar, &ekf_ca_rr_setup, &run_ekf_ca_rr},
    {"ekf-ca-rr-f32", "the same EKF-CA with range rate in float", hal::FrameKind::kRadar, &ekf_ca_rr_f32_setup,
     &run_ekf_ca_rr_f32},
    {"imm", "IMM of CV-2D, CA-2D and CT-2D EKFs, polar radar, reported as CA-2D; double (docs/imm.md)",
     hal::FrameKind::kRadar, &imm_setup, &run_imm},
    {"imm-f32", "the same IMM in float (the Cortex-M4F scalar)", hal::FrameKind::kRadar, &imm_f32_setup, &run_imm_f32},
    {"r2aekf", "R2-AEKF default mode (corrections of docs/r2aekf.md) on EKF-CA; double", hal::FrameKind::kRadar, &r2aekf_setup,
     &run_r2aekf},
    {"r2aekf-paper", "R2-AEKF paper mode (paper 000 eqs. 7-18 as printed); double", hal::FrameKind::kRadar,
     &r2aekf_paper_setup, &run_r2aekf_paper},
    {"r2aekf-f32", "R2-AEKF default mode in float (the Cortex-M4F scalar)", hal::FrameKind::kRadar, &r2aekf_f32_setup,
     &run_r2aekf_f32},
    {"r2aekf-q31_32", "R2-AEKF default mode in Q31.32 fixed point (the Cortex-M0+ scalar)", hal::FrameKind::kRadar,
     &r2aekf_q31_32_setup, &run_r2aekf_q31_32},
    {"ukf", "UKF (paper 001), CA-2D, polar radar; double", hal::FrameKind::kRadar, &ukf_setup, &run_ukf},
    {"ukf-f32", "the same UKF in float", hal::FrameKind::kRadar, &ukf_f32_setup, &run_ukf_f32},
    {"cdkf", "CDKF (paper 001), CA-2D, polar radar; double", hal::FrameKind::kRadar, &cdkf_setup, &run_cdkf},
    {"cdkf-f32", "the same CDKF in float", hal::FrameKind::kRadar, &cdkf_f32_setup, &run_cdkf_f32},
    {"sr-ukf", "square-root UKF (paper 001); double", hal::FrameKind::kRadar, &sr_ukf_setup, &run_sr_ukf},
    {"sr-ukf-f32", "the same SR-UKF in float", hal::FrameKind::kRadar, &sr_ukf_f32_setup, &run_sr_ukf_f32},
    {"sr-cdkf", "square-root CDKF (paper 001); double", hal::FrameKind::kRadar, &sr_cdkf_setup, &run_sr_cdkf},
    {"sr-cdkf-f32", "the same SR-CDKF in float", hal::FrameKind::kRadar, &sr_cdkf_f32_setup, &run_sr_cdkf_f32},
    {"crpf-100",
     "cost-reference particle filter, 100 particles (paper 001); double; does not hold S1/S2 tracks (docs/filters.md)",
     hal::FrameKind::kRadar, &crpf100_setup, &run_crpf100},
    {"crpf-100-f32", "the same CRPF in float", hal::FrameKind::kRadar, &crpf100_f32_setup, &run_crpf100_f32},
};
}  // namespace

std::span<const FilterEntry> filter_registry() { return kFilters; }

namespace {
// The robust gate's factor that acts: only with the board's gate.
double robust_factor(const FilterOptions& options) {
  if (options.confirmed_gate_d2.has_value() || !options.board_gate) return 0.0;
  return options.robust_gate_factor.value_or(RadarTrackerParams{}.robust_gate_factor);
}
}  // namespace

std::string gate_label(const FilterOptions& options) {
  if (options.confirmed_gate_d2.has_value()) {
    char text[48];
    std::snprintf(text, sizeof text, ", gate d2 %g", *options.confirmed_gate_d2);
    return text;
  }
  if (!options.board_gate) return "";
  const double factor = robust_factor(options);
  if (!(factor > 1.0)) return ", board gate";
  char text[48];
  std::snprintf(text, sizeof text, ", board gate (robust x%g)", factor);
  return text;
}

void add_gate_parameters(const FilterOptions& options, std::map<std::string, double>& parameters) {
  parameters["confirmed_gate_d2"] = options.confirmed_gate_d2.value_or(std::numeric_limits<double>::infinity());
  parameters["board_gate"] = !options.confirmed_gate_d2.has_value() && options.board_gate ? 1.0 : 0.0;
  parameters["robust_gate_factor"] = robust_factor(options);
}

const FilterEntry& find_filter(std::string_view name) {
  std::string key(name);
  for (char& c : key) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  std::string known;
  for (const FilterEntry& e : kFilters) {
    if (e.name == key) return e;
    known += known.empty() ? "" : ", ";
    known += e.name;
  }
  throw std::invalid_argument("unknown filter '" + std::string(name) + "' (known: " + known + ")");
}

}  // namespace kestrel::sim
