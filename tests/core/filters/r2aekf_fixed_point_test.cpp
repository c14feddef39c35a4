// SPDX-License-Identifier: Apache-2.0
// R2-AEKF's radar tracker on Q31.32 against double, on S1 and S1n frames
// generated with integer arithmetic and fed through the HAL boundary
// (tests/core/scalar/s1_integer_scenario.hpp): the same report sets, position
// deviation <= 5 mm, RMSE within 0.5 % of double, no saturation: the
// targets the EKF-CA tracker meets on fixed point (docs/fixed-point.md).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/scalar/s1_reports.hpp"
#include "kestrel/filters/r2aekf.hpp"

namespace {

using kestrel::RadarTrackerParams;
using kestrel::test::S1Options;

template <class S>
using R2Tracker = kestrel::RadarTracker<kestrel::R2AekfCa<S>, 4, 4>;

/// The radar tracker of make_radar_tracker() with R2-AEKF (default mode)
/// as its filter, the real constants converted as a board converts them.
template <class S>
R2Tracker<S> make_tracker() {
  static constexpr RadarTrackerParams kParams{};
  static constexpr kestrel::RadarTrackerConfig<S> s = kestrel::radar_tracker_config<S>(kParams);
  kestrel::CaMotion<S> motion;
  motion.qj = s.qj;
  kestrel::CaPolarRadar<S> radar;
  radar.sigma_range_m = s.sigma_range_m;
  radar.sigma_bearing_rad = s.sigma_bearing_rad;
  kestrel::TwoPointInitiator<kestrel::CaMotion<S>, kestrel::CaPolarRadar<S>> init{radar, s.max_speed_mps,
                                                                                  s.init_accel_sigma_mps2};
  return R2Tracker<S>(kestrel::R2AekfCa<S>(motion, radar, kestrel::R2AekfConfig<S>{}), init,
                      kestrel::tracker_config_of<S>(kParams, s));
}

template <class S>
std::vector<kestrel::test::S1Step> run(const S1Options& o) {
  R2Tracker<S> tracker = make_tracker<S>();
  std::vector<kestrel::test::S1Step> steps = kestrel::test::s1_reports(tracker, o);
  REQUIRE(steps.size() == static_cast<std::size_t>(o.steps));
  return steps;
}

}  // namespace

SCENARIO("R2-AEKF's radar tracker on Q31.32 matches double on S1 and S1n", "[r2aekf][fixed_point][s1]") {
  double worst_dev = 0;
  double worst_rmse = 0;
  int mismatches = 0;
  int reports = 0;
  kestrel::reset_fixed_point_overflow_count();
  for (int noisy = 0; noisy < 2; ++noisy) {
    for (int seed = 1; seed <= 8; ++seed) {
      S1Options o;
      o.seed = static_cast<std::uint64_t>(seed);
      o.time_varying_noise = noisy != 0;
      const auto d = run<double>(o);
      const auto q = run<kestrel::Q31_32>(o);
      const kestrel::test::S1Comparison c = kestrel::test::compare_s1(d, q);
      mismatches += c.decision_mismatches;
      reports += c.reports_compared;
      worst_dev = std::max(worst_dev, c.max_deviation_m);
      worst_rmse = std::max(worst_rmse, std::fabs(kestrel::test::s1_rmse(q) / kestrel::test::s1_rmse(d) - 1));
    }
  }
  THEN("the same reports, within 5 mm of double, RMSE within 0.5 %, no saturation") {
    INFO("worst deviation " << worst_dev << " m, worst |RMSE/RMSE_double - 1| " << worst_rmse);
    CHECK(reports > 16 * 250);
    CHECK(mismatches == 0);
    CHECK(worst_dev <= 5e-3);
    CHECK(worst_rmse <= 5e-3);
    CHECK(kestrel::fixed_point_overflow_count() == 0);
  }
}
