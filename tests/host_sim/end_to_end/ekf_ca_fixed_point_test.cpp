// SPDX-License-Identifier: Apache-2.0
// The fixed-point builds of kestrel-sim's EKF-CA ("ekf-ca-q31_32",
// "ekf-ca-q23_40") against the double build on docs/scenarios.md's radar scenarios
// (S1, S2, S1n, S2n; host_sim's own generators, through the wire stream and
// the host board loop): the same report sets frame by frame, position within
// 5 mm of the double tracker's (Q31.32; 0.1 mm for Q23.40) over whole runs,
// RMSE within 0.5 %, and no fixed-point saturation. The `scalars`
// subcommand prints the same comparison as a table (docs/fixed-point.md).
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <string>

#include "filters/filter_registry.hpp"
#include "kestrel/scalar/fixed_point.hpp"
#include "montecarlo/single_run.hpp"
#include "scenarios/registry.hpp"

namespace {

struct Difference {
  double max_deviation_m = 0.0;
  int other_frames = 0;
};

Difference compare(const kestrel::sim::RunDetail& ref, const kestrel::sim::RunDetail& run) {
  Difference d;
  REQUIRE(ref.stream.frames.size() == run.stream.frames.size());
  for (std::size_t k = 0; k < ref.stream.frames.size(); ++k) {
    const auto& a = ref.stream.frames[k].tracks;
    const auto& b = run.stream.frames[k].tracks;
    std::map<std::uint32_t, const kestrel::host::TrackRow*> by_id;
    for (const auto& t : a) by_id[t.track_id] = &t;
    bool same = a.size() == b.size();
    for (const auto& t : b) {
      const auto it = by_id.find(t.track_id);
      if (it == by_id.end()) {
        same = false;
        continue;
      }
      d.max_deviation_m = std::max(d.max_deviation_m, std::hypot(t.x_m - it->second->x_m, t.y_m - it->second->y_m));
    }
    d.other_frames += same ? 0 : 1;
  }
  return d;
}

}  // namespace

SCENARIO("the fixed-point EKF-CA builds of kestrel-sim follow the double build on S1, S2, S1n, S2n",
         "[end_to_end][fixed_point]") {
  using namespace kestrel::sim;  // NOLINT(google-build-using-namespace)
  const FilterEntry& dbl = find_filter("ekf-ca");
  const FilterEntry& q31 = find_filter("ekf-ca-q31_32");
  const FilterEntry& q23 = find_filter("ekf-ca-q23_40");
  const FilterOptions options;  // S1/S2 sensor (docs/scenarios.md), qj 1.6, ungated confirmed tracks
  const ScoringParams scoring;
  double dev31 = 0, dev23 = 0, rmse31 = 0, rmse23 = 0;
  int other31 = 0, other23 = 0;
  std::uint32_t saturations = 0;
  for (const char* name : {"s1", "s2", "s1n", "s2n"}) {
    const auto scenario = make_scenario(name);
    for (std::uint64_t seed = 0; seed < 5; ++seed) {
      const RunDetail ref = run_scenario_once(*scenario, seed, dbl, options, 1000000, scoring);
      kestrel::reset_fixed_point_overflow_count();
      const RunDetail a = run_scenario_once(*scenario, seed, q31, options, 1000000, scoring);
      const RunDetail b = run_scenario_once(*scenario, seed, q23, options, 1000000, scoring);
      saturations += kestrel::fixed_point_overflow_count();
      const Difference da = compare(ref, a), db = compare(ref, b);
      dev31 = std::max(dev31, da.max_deviation_m);
      dev23 = std::max(dev23, db.max_deviation_m);
      other31 += da.other_frames;
      other23 += db.other_frames;
      rmse31 = std::max(rmse31, std::fabs(a.metrics.rmse_m / ref.metrics.rmse_m - 1));
      rmse23 = std::max(rmse23, std::fabs(b.metrics.rmse_m / ref.metrics.rmse_m - 1));
    }
  }
  INFO("Q31.32: deviation " << dev31 << " m, RMSE " << rmse31 << " relative; Q23.40: " << dev23 << " m, " << rmse23);
  CHECK(other31 == 0);
  CHECK(other23 == 0);
  CHECK(dev31 <= 5e-3);
  CHECK(dev23 <= 1e-4);
  CHECK(rmse31 <= 5e-3);
  CHECK(rmse23 <= 5e-3);
  CHECK(saturations == 0);
}
