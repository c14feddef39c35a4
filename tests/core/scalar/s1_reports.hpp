// SPDX-License-Identifier: Apache-2.0
// A radar tracker's reports over an S1 run (s1_integer_scenario.hpp), kept
// per step beside the truth, and how two scalars' runs compare: the report
// sets (count and ids), the largest position deviation, and the position
// RMSE of the track nearest the truth. Shared by the fixed-point accuracy
// tests of EKF-CA and R2-AEKF. Host tests only (std::vector).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/scalar/s1_integer_scenario.hpp"

namespace kestrel::test {

struct S1Report {
  std::uint32_t id;
  double x, y;
};

struct S1Step {
  double truth_x = 0, truth_y = 0;
  std::vector<S1Report> reports;
};

/// Runs S1 (or S1n) through `tracker` and keeps every step's reports.
/// @return one S1Step per step, or fewer if a frame was refused.
template <class Tracker>
std::vector<S1Step> s1_reports(Tracker& tracker, const S1Options& o) {
  using S = typename Tracker::Scalar;
  std::vector<S1Step> steps;
  run_s1_on(tracker, o, [&steps](int, const S1Sample& s, const Tracker& tr) {
    S1Step st;
    st.truth_x = static_cast<double>(s.x_m);
    st.truth_y = static_cast<double>(s.y_m);
    for (const auto& r : tr.reports()) {
      st.reports.push_back({r.track_id, ScalarTraits<S>::to_double(r.x(0)), ScalarTraits<S>::to_double(r.x(3))});
    }
    steps.push_back(st);
  });
  return steps;
}

/// Tracker-level position RMSE: per step the reported track nearest the truth.
inline double s1_rmse(const std::vector<S1Step>& steps) {
  double sum = 0;
  int n = 0;
  for (const auto& s : steps) {
    if (s.reports.empty()) continue;
    double best = 1e300;
    for (const auto& r : s.reports) best = std::min(best, std::hypot(r.x - s.truth_x, r.y - s.truth_y));
    sum += best * best;
    ++n;
  }
  return n > 0 ? std::sqrt(sum / n) : 0.0;
}

struct S1Comparison {
  double max_deviation_m = 0;  ///< Largest |p - p_ref| over every report of every step.
  int decision_mismatches = 0; ///< Steps whose report set (count, ids) differs from the reference's.
  int reports_compared = 0;    ///< Reports that entered max_deviation_m.
};

inline S1Comparison compare_s1(const std::vector<S1Step>& ref, const std::vector<S1Step>& got) {
  S1Comparison c;
  for (std::size_t k = 0; k < ref.size(); ++k) {
    if (k >= got.size() || ref[k].reports.size() != got[k].reports.size()) {
      ++c.decision_mismatches;
      continue;
    }
    for (std::size_t i = 0; i < ref[k].reports.size(); ++i) {
      const S1Report& a = ref[k].reports[i];
      const S1Report& b = got[k].reports[i];
      if (a.id != b.id) {
        ++c.decision_mismatches;
        continue;
      }
      c.max_deviation_m = std::max(c.max_deviation_m, std::hypot(a.x - b.x, a.y - b.y));
      ++c.reports_compared;
    }
  }
  return c;
}

}  // namespace kestrel::test
