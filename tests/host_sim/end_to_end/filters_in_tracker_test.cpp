// SPDX-License-Identifier: Apache-2.0
// Every filter of the family inside the same Tracker, on S1 and on S2 (seed
// 1 each; wire frames through hal::to_scan, the HAL boundary a board uses;
// the default 99.9 % gate), with the single-model qj that suits each (S1:
// 160, docs/r2aekf.md's tuned EKF-CA; S2: 50, the best of {1.6, 5, 16, 50, 160,
// 500} for EKF-CA there): the track starts by two points, is confirmed by
// frame 2 and held by one track to the end, through S1's weave and axial
// burst and S2's turns and jerk bursts, in double and in float, with a
// position error at most 1.5 times the EKF's in the same run.
// The IMM (CV/CA/CT, kestrel/filters/imm_radar.hpp) runs with its own
// defaults, not the single-model qj.
// S1 comes from the integer generator of the fixed-point golden hash
// (tests/core/scalar/s1_integer_scenario.hpp), S2 from kestrel-sim's
// scenario registry; both runs of one filter share its Tracker type.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "core/scalar/s1_integer_scenario.hpp"
#include "kestrel/filters/crpf.hpp"
#include "kestrel/filters/imm_radar.hpp"
#include "kestrel/filters/sigma_point_filter.hpp"
#include "kestrel/filters/sr_sigma_point_filter.hpp"
#include "kestrel/tracking/radar_tracker.hpp"
#include "scenarios/registry.hpp"
#include "stream/quantise.hpp"

namespace {

using kestrel::Status;

template <class M, class H>
using Crpf100 = kestrel::Crpf<M, H, 100>;

/// The radar IMM in the scalar of M (it brings its own models).
template <class M, class H>
using RadarImm = kestrel::RadarImm<typename M::Scalar>;

/// F from the single-model parameters, or the IMM with its defaults.
template <class F, class Motion, class Radar>
F make_filter(const Motion& motion, const Radar& radar) {
  if constexpr (std::is_same_v<F, kestrel::RadarImm<typename Motion::Scalar>>) {
    return kestrel::make_radar_imm<typename Motion::Scalar>(kestrel::RadarImmParams{});
  } else {
    return F(motion, radar);
  }
}

/// One scenario run as a board sees it: wire frames and the truth position.
struct WireRun {
  const char* name;
  double qj;
  std::vector<kestrel::hal::Frame> frames;
  std::vector<double> x_m;
  std::vector<double> y_m;
};

const WireRun& s1_run() {
  static const WireRun run = [] {
    WireRun r{"S1", 160.0, {}, {}, {}};
    kestrel::test::S1Options o;
    o.seed = 1;
    kestrel::test::SplitMix64 rng(o.seed);
    for (int k = 0; k < o.steps; ++k) {
      const auto sample = kestrel::test::s1_sample(k, o, rng);
      r.frames.push_back(kestrel::test::s1_frame(sample));
      r.x_m.push_back(kestrel::ScalarTraits<kestrel::Q31_32>::to_double(sample.x_m));
      r.y_m.push_back(kestrel::ScalarTraits<kestrel::Q31_32>::to_double(sample.y_m));
    }
    return r;
  }();
  return run;
}

const WireRun& s2_run() {
  static const WireRun run = [] {
    WireRun r{"S2", 50.0, {}, {}, {}};
    const kestrel::sim::ScenarioRun s = kestrel::sim::make_scenario("s2")->generate(1);
    for (std::size_t k = 0; k < s.frames.size(); ++k) {
      r.frames.push_back(kestrel::sim::to_wire_frame(s.frames[k]));
      r.x_m.push_back(s.truth[k].x_m);
      r.y_m.push_back(s.truth[k].y_m);
    }
    return r;
  }();
  return run;
}

struct TrackedRun {
  bool all_frames_accepted = true;
  int first_report = -1;              ///< Frame of the first confirmed report.
  int frames_reported = 0;            ///< Frames reporting the first track.
  int extra_tracks = 0;               ///< Reports of any other track id.
  double rms_position_m = 0;          ///< Over the frames reported.
  std::uint32_t filter_failures = 0;  ///< Filter refusals counted by the tracker.
};

template <template <class, class> class FilterT, class S>
TrackedRun track_with(const WireRun& run) {
  using Motion = kestrel::CaMotion<S>;
  using Radar = kestrel::CaPolarRadar<S>;
  using F = FilterT<Motion, Radar>;
  using Tracker = kestrel::Tracker<F, kestrel::TwoPointInitiator<Motion, Radar>, 4, 4>;
  kestrel::RadarTrackerParams p;
  p.qj = run.qj;
  const auto s = kestrel::radar_tracker_config<S>(p);
  Motion motion;
  motion.qj = s.qj;
  Radar radar;
  radar.sigma_range_m = s.sigma_range_m;
  radar.sigma_bearing_rad = s.sigma_bearing_rad;
  Tracker tracker(make_filter<F>(motion, radar), {radar, s.max_speed_mps, s.init_accel_sigma_mps2},
                  kestrel::tracker_config_of<S>(p, s));

  TrackedRun out;
  typename Tracker::Scan scan;
  std::uint32_t id = 0;
  double sum_sq = 0;
  for (std::size_t k = 0; k < run.frames.size(); ++k) {
    REQUIRE(kestrel::hal::to_scan(run.frames[k], scan) == Status::kOk);
    if (tracker.step(scan) != Status::kOk) out.all_frames_accepted = false;
    out.filter_failures += tracker.last_step().filter_failures;
    for (const auto& r : tracker.reports()) {
      if (id == 0) {
        id = r.track_id;
        out.first_report = static_cast<int>(k);
      }
      if (r.track_id != id) {
        ++out.extra_tracks;
        continue;
      }
      ++out.frames_reported;
      const double ex = static_cast<double>(r.x(0)) - run.x_m[k];
      const double ey = static_cast<double>(r.x(3)) - run.y_m[k];
      sum_sq += ex * ex + ey * ey;
    }
  }
  out.rms_position_m = out.frames_reported > 0 ? std::sqrt(sum_sq / out.frames_reported) : 0.0;
  return out;
}

/// Ekf with its default update form, as a two-parameter template: clang 14
/// does not match Ekf itself (a third, non-type parameter with a default)
/// to `template <class, class> class` without -frelaxed-template-template-args.
template <class Motion, class Measurement>
using DefaultEkf = kestrel::Ekf<Motion, Measurement>;

template <template <class, class> class FilterT, class S>
void check_holds(const char* name, const WireRun& wire) {
  const TrackedRun ekf = track_with<DefaultEkf, S>(wire);
  const TrackedRun run = track_with<FilterT, S>(wire);
  const int frames = static_cast<int>(wire.frames.size());
  INFO(name << " on " << wire.name << ": first report at frame " << run.first_report << ", "
            << run.frames_reported << " of " << frames << " frames reported, rms " << run.rms_position_m
            << " m (EKF " << ekf.rms_position_m << " m), " << run.filter_failures << " filter refusals, "
            << run.extra_tracks << " reports of other tracks");
  CHECK(run.all_frames_accepted);
  CHECK(run.first_report >= 1);
  CHECK(run.first_report <= 2);
  CHECK(run.frames_reported == frames - run.first_report);
  CHECK(run.extra_tracks == 0);
  CHECK(run.rms_position_m <= 1.5 * ekf.rms_position_m);
}

template <template <class, class> class FilterT, class S>
void check_holds_s1_and_s2(const char* name) {
  check_holds<FilterT, S>(name, s1_run());
  check_holds<FilterT, S>(name, s2_run());
}

}  // namespace

TEMPLATE_TEST_CASE("Scenario: the UKF holds S1 and S2 inside the tracker", "[tracker][filters]", double, float) {
  check_holds_s1_and_s2<kestrel::Ukf, TestType>("UKF");
}
TEMPLATE_TEST_CASE("Scenario: the CDKF holds S1 and S2 inside the tracker", "[tracker][filters]", double, float) {
  check_holds_s1_and_s2<kestrel::Cdkf, TestType>("CDKF");
}
TEMPLATE_TEST_CASE("Scenario: the IMM holds S1 and S2 inside the tracker", "[tracker][filters][imm]", double, float) {
  check_holds_s1_and_s2<RadarImm, TestType>("IMM");
}
// In float the square-root forms hold only if sqrt(R) keeps its bearing
// channel: 2.7e-5 rad^2 is below 32 eps * 9 m^2, so a zero-pivot tolerance
// on the largest diagonal drops it, bearings become noise-free and the
// factor's downdate to a singular P+ is refused (docs/filters.md, "Inside
// the tracker").
TEMPLATE_TEST_CASE("Scenario: the SR-UKF holds S1 and S2 inside the tracker", "[tracker][filters]", double,
                   float) {
  check_holds_s1_and_s2<kestrel::SrUkf, TestType>("SR-UKF");
}
TEMPLATE_TEST_CASE("Scenario: the SR-CDKF holds S1 and S2 inside the tracker", "[tracker][filters]", double,
                   float) {
  check_holds_s1_and_s2<kestrel::SrCdkf, TestType>("SR-CDKF");
}

// Known defect, measured on S1 (docs/filters.md, "Inside the tracker"):
// this runs and is expected to fail until fixed; a pass fails the case, so
// the tag must then be removed. The CRPF loses the gated track after 14
// frames with 100 particles (26 with 300, 28 with 1,000 in float): the
// first selections against the 3 m range keep a few ancestors of the
// two-point prior (ESS 3.6 at frame 2), whose velocity is 53 and 72 m/s off
// at frame 6; the cloud is then 3 to 5 m wide against an 89 m cross-range
// bearing sigma, cannot be steered back, and its bearing innovation leaves
// the gate at frame 10 (d2 18.0 against 13.8).
TEMPLATE_TEST_CASE("Scenario: the CRPF (100 particles) holds S1 inside the tracker (known defect)",
                   "[tracker][filters][!shouldfail]", double, float) {
  check_holds<Crpf100, TestType>("CRPF-100", s1_run());
}
// The same defect on S2 (its own case, so that either scenario passing
// alone flips its tag): the two-point start and the selection are the same.
TEMPLATE_TEST_CASE("Scenario: the CRPF (100 particles) holds S2 inside the tracker (known defect)",
                   "[tracker][filters][!shouldfail]", double, float) {
  check_holds<Crpf100, TestType>("CRPF-100", s2_run());
}
