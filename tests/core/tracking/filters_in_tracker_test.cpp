// Every filter of the family inside the same Tracker on S1 (seed 1, tuned
// qj = 160, the HAL's integer plots, the default gate): the track starts by
// two points, is confirmed, and is held by one track to the end, in double
// and in float, with a position error at most 1.5 times the EKF's in the
// same run.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>

#include "core/scalar/s1_integer_scenario.hpp"
#include "kestrel/filters/crpf.hpp"
#include "kestrel/filters/sigma_point_filter.hpp"
#include "kestrel/filters/sr_sigma_point_filter.hpp"
#include "kestrel/tracking/radar_tracker.hpp"

namespace {

using kestrel::Status;

template <class M, class H>
using Crpf100 = kestrel::Crpf<M, H, 100>;

struct S1Run {
  bool all_frames_accepted = true;
  int first_report = -1;         ///< Frame of the first confirmed report.
  int frames_reported = 0;       ///< Frames with exactly one report, of the first track.
  int extra_tracks = 0;          ///< Reports of any other track id.
  double rms_position_m = 0;     ///< Over the frames reported.
  std::uint16_t filter_failures = 0;  ///< Filter refusals counted by the tracker.
};

template <template <class, class> class FilterT, class S>
S1Run run_s1_with() {
  using Motion = kestrel::CaMotion<S>;
  using Radar = kestrel::CaPolarRadar<S>;
  using F = FilterT<Motion, Radar>;
  using Tracker = kestrel::Tracker<F, kestrel::TwoPointInitiator<Motion, Radar>, 4, 4>;
  const kestrel::RadarTrackerParams p = kestrel::test::tuned_params();
  const auto s = kestrel::radar_tracker_scalars<S>(p);
  Motion motion;
  motion.qj = s.qj;
  Radar radar;
  radar.sigma_range_m = s.sigma_range_m;
  radar.sigma_bearing_rad = s.sigma_bearing_rad;
  Tracker tracker(F(motion, radar), {radar, s.max_speed_mps, s.init_accel_sigma_mps2},
                  kestrel::radar_tracker_config<S>(p, s));

  S1Run out;
  kestrel::test::S1Options o;
  o.seed = 1;
  o.tuned = true;
  kestrel::test::SplitMix64 rng(o.seed);
  typename Tracker::Scan scan;
  std::uint32_t id = 0;
  double sum_sq = 0;
  for (int k = 0; k < o.steps; ++k) {
    const auto sample = kestrel::test::s1_sample(k, o, rng);
    REQUIRE(kestrel::hal::to_scan(kestrel::test::s1_frame(sample), scan) == Status::kOk);
    if (tracker.step(scan) != Status::kOk) out.all_frames_accepted = false;
    out.filter_failures = static_cast<std::uint16_t>(out.filter_failures + tracker.last_step().filter_failures);
    for (const auto& r : tracker.reports()) {
      if (id == 0) {
        id = r.track_id;
        out.first_report = k;
      }
      if (r.track_id != id) {
        ++out.extra_tracks;
        continue;
      }
      ++out.frames_reported;
      const double ex = static_cast<double>(r.x(0)) - kestrel::ScalarTraits<kestrel::Q31_32>::to_double(sample.x_m);
      const double ey = static_cast<double>(r.x(3)) - kestrel::ScalarTraits<kestrel::Q31_32>::to_double(sample.y_m);
      sum_sq += ex * ex + ey * ey;
    }
  }
  out.rms_position_m = out.frames_reported > 0 ? std::sqrt(sum_sq / out.frames_reported) : 0.0;
  return out;
}

template <template <class, class> class FilterT, class S>
void check_holds_s1(const char* name) {
  const S1Run ekf = run_s1_with<kestrel::Ekf, S>();
  const S1Run run = run_s1_with<FilterT, S>();
  INFO(name << ": first report at frame " << run.first_report << ", " << run.frames_reported
            << " frames reported, rms " << run.rms_position_m << " m (EKF " << ekf.rms_position_m << " m), "
            << run.filter_failures << " filter refusals, " << run.extra_tracks << " reports of other tracks");
  CHECK(run.all_frames_accepted);
  CHECK(run.first_report >= 1);
  CHECK(run.first_report <= 2);
  CHECK(run.frames_reported == 300 - run.first_report);
  CHECK(run.extra_tracks == 0);
  CHECK(run.rms_position_m <= 1.5 * ekf.rms_position_m);
}

}  // namespace

TEMPLATE_TEST_CASE("Scenario: the UKF holds S1 inside the tracker", "[tracker][filters]", double, float) {
  check_holds_s1<kestrel::Ukf, TestType>("UKF");
}
TEMPLATE_TEST_CASE("Scenario: the CDKF holds S1 inside the tracker", "[tracker][filters]", double, float) {
  check_holds_s1<kestrel::Cdkf, TestType>("CDKF");
}
// In float the square-root forms hold only if sqrt(R) keeps its bearing
// channel: 2.7e-5 rad^2 is below 32 eps * 9 m^2, so a zero-pivot tolerance
// on the largest diagonal drops it, bearings become noise-free and the
// factor's downdate to a singular P+ is refused (docs/filters.md, "Inside
// the tracker").
TEMPLATE_TEST_CASE("Scenario: the SR-UKF holds S1 inside the tracker", "[tracker][filters]", double, float) {
  check_holds_s1<kestrel::SrUkf, TestType>("SR-UKF");
}
TEMPLATE_TEST_CASE("Scenario: the SR-CDKF holds S1 inside the tracker", "[tracker][filters]", double, float) {
  check_holds_s1<kestrel::SrCdkf, TestType>("SR-CDKF");
}

// Known defect, measured (docs/filters.md, "Inside the tracker"): this runs
// and is expected to fail until fixed; a pass fails the case, so the tag
// must then be removed. The CRPF loses the gated track after 14 frames with
// 100 particles (26 with 300, 28 with 1,000 in float): the first selections
// against the 3 m range keep a few ancestors of the two-point prior (ESS
// 3.6 at frame 2), whose velocity is 53 and 72 m/s off at frame 6; the
// cloud is then 3 to 5 m wide against an 89 m cross-range bearing sigma,
// cannot be steered back, and its bearing innovation leaves the gate at
// frame 10 (d2 18.0 against 13.8).
TEMPLATE_TEST_CASE("Scenario: the CRPF (100 particles) holds S1 inside the tracker (known defect)",
                   "[tracker][filters][!shouldfail]", double, float) {
  check_holds_s1<Crpf100, TestType>("CRPF-100");
}
