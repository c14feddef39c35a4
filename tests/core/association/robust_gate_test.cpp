// SPDX-License-Identifier: Apache-2.0
// The robust gate inside the tracker: an established confirmed track takes
// a plot beyond the chi-square gate with its innovation shrunk, a track of
// fewer than kRobustGateMinHits plots never does (the plot is a miss for
// it), with the nominal and with the adaptive measurement noise, in
// double and float.
#include <catch2/catch.hpp>
#include <cmath>

#include "kestrel/tracking/radar_tracker.hpp"

using kestrel::Status;

namespace {

/// The noise-free plot of a target flying straight from (-15000, 8000) at
/// (200, 50) m/s, `dr` metres added to its range.
template <class S>
kestrel::Vec<S, 2> plot_at(double t_s, double dr) {
  const double x = -15000 + 200 * t_s, y = 8000 + 50 * t_s;
  return kestrel::Vec<S, 2>(static_cast<S>(std::hypot(x, y) + dr), static_cast<S>(std::atan2(y, x)));
}

struct OutlierOutcome {
  int clipped = 0;         ///< Plots taken shrunk in the outlier's frame.
  bool associated = true;  ///< The track took the outlier's plot.
  double error_m = 0.0;    ///< The track's position error after that frame.
  int tracks = 0;          ///< Tracks reported after that frame.
};

/// One target, its plots clean but for frame `k_outlier`, whose range is
/// `dr` metres off; the robust gate at 25.
template <class Tracker, class S>
OutlierOutcome run(Tracker& tracker, int k_outlier, double dr) {
  OutlierOutcome out;
  for (int k = 0; k <= k_outlier; ++k) {
    typename Tracker::Scan scan;
    scan.t_us = k * 500000LL;
    scan.count = 1;
    scan.z[0] = plot_at<S>(0.5 * k, k == k_outlier ? dr : 0.0);
    REQUIRE(tracker.step(scan) == Status::kOk);
  }
  out.clipped = tracker.last_step().clipped;
  out.tracks = static_cast<int>(tracker.reports().size());
  for (const auto& r : tracker.reports()) {
    out.associated = r.associated;
    const double t = 0.5 * k_outlier;
    out.error_m = std::hypot(static_cast<double>(r.x(0)) - (-15000 + 200 * t), static_cast<double>(r.x(3)) - (8000 + 50 * t));
  }
  return out;
}

template <class S>
kestrel::RadarTrackerParams params() {
  kestrel::RadarTrackerParams p;
  p.qj = 16.0;
  p.robust_gate_factor = 25.0;
  return p;
}

}  // namespace

TEMPLATE_TEST_CASE("Scenario: under the robust gate a young track takes no plot beyond the chi-square gate, an established one takes it shrunk",
                   "[robust_gate][tracker]", double, float) {
  using S = TestType;
  using Nominal = decltype(kestrel::make_radar_tracker<S, 16, 32>(params<S>()));
  using Adaptive = kestrel::AdaptiveRadarTracker<kestrel::EkfCa<S>, 16, 32>;
  STATIC_REQUIRE(Nominal::kRobustGateMinHits == 4);
  // Range offsets from inside the chi-square gate to beyond the outer one.
  const double offsets[] = {15, 30, 60, 100, 150, 200, 300, 450, 600, 800, 1200};
  for (const bool adaptive : {false, true}) {
    GIVEN((adaptive ? "the adaptive measurement noise at gain 0.2" : "the nominal measurement noise")) {
      auto outcome = [&](int k_outlier, double dr) {
        const auto nominal = kestrel::make_radar_tracker<S, 16, 32>(params<S>());
        if (!adaptive) {
          auto tracker = nominal;
          return run<Nominal, S>(tracker, k_outlier, dr);
        }
        Adaptive tracker(nominal.prototype_filter(), nominal.initiator(), nominal.config());
        kestrel::RadarTrackerParams p = params<S>();
        p.robust_noise_gain = 0.2;
        REQUIRE(tracker.configure_measurement_noise(kestrel::radar_measurement_noise<S>(p)) == Status::kOk);
        return run<Adaptive, S>(tracker, k_outlier, dr);
      };
      WHEN("the third plot (the track's first after its two-point start) is the outlier") {
        THEN("whatever its offset it is plain or a miss, never shrunk, and the track stays on the target") {
          for (const double dr : offsets) {
            const OutlierOutcome o = outcome(2, dr);
            INFO("offset " << dr << " m: clipped " << o.clipped << ", associated " << o.associated << ", error "
                           << o.error_m << " m");
            CHECK(o.clipped == 0);
            CHECK(o.tracks >= 1);
            if (!o.associated) CHECK(o.error_m < 1.0);
          }
        }
      }
      WHEN("the same outlier comes to a track of 30 plots") {
        int shrunk = 0;
        for (const double dr : offsets) shrunk += outcome(30, dr).clipped;
        THEN("some offsets are taken shrunk: the gate the young track was spared is on") {
          CHECK(shrunk >= 2);
        }
      }
    }
  }
}
