// SPDX-License-Identifier: Apache-2.0
// kestrel-fixed-point-cost: instructions per step of the EKF-CA on each
// scalar (double, float, Q31.32, Q23.40, and double/float with the
// sequential whitened update), counted by callgrind around the measured
// calls only, on S1 seed 1 frames (tests/core/scalar/s1_integer_scenario.hpp).
//   filter/<scalar>/<form>   EKF predict + update per frame (one target)
//   tracker/<scalar>/<form>  Tracker::step per frame (EKF-CA radar tracker,
//                            qj 160 so one track holds S1 throughout)
// It also prints, outside callgrind's collection, how long a track coasts
// before its prediction saturates (docs/fixed-point.md, "Limits").
// Run:
//   valgrind --tool=callgrind --collect-atstart=no --callgrind-out-file=/tmp/cg.%p \
//     build/<dir>/tests/core/scalar/kestrel-fixed-point-cost
// and read the "Collected" line of each dump (callgrind_annotate /tmp/cg.<pid>.<n>),
// or let the program print them: it reads nothing back, so the figures come
// from callgrind_annotate. docs/fixed-point.md lists the numbers.
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#else
#define CALLGRIND_TOGGLE_COLLECT
#define CALLGRIND_DUMP_STATS_AT(label) static_cast<void>(label)
#endif

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/scalar/s1_integer_scenario.hpp"

extern "C" [[noreturn]] void kestrel_assert_failed(const char* file, int line, const char* expr) {
  std::fprintf(stderr, "%s:%d: assertion failed: %s\n", file, line, expr);
  std::abort();
}

namespace {

using namespace kestrel;

template <class S>
using Scan = typename test::S1Tracker<S>::Scan;

template <class S>
std::vector<Scan<S>> s1_scans() {
  test::S1Options o;
  o.seed = 1;
  test::SplitMix64 rng(o.seed);
  std::vector<Scan<S>> scans(static_cast<std::size_t>(o.steps));
  for (int k = 0; k < o.steps; ++k) {
    if (hal::to_scan(test::s1_frame(test::s1_sample(k, o, rng)), scans[static_cast<std::size_t>(k)]) != Status::kOk) {
      std::abort();
    }
  }
  return scans;
}

template <class S, EkfUpdateForm kForm>
void count_filter(const char* scalar, const char* form) {
  using T = ScalarTraits<S>;
  using F = Ekf<CaMotion<S>, CaPolarRadar<S>, kForm>;
  static constexpr RadarTrackerConfig<S> kS = radar_tracker_config<S>(test::tuned_params());
  CaMotion<S> motion;
  motion.qj = kS.qj;
  CaPolarRadar<S> radar;
  radar.sigma_range_m = kS.sigma_range_m;
  radar.sigma_bearing_rad = kS.sigma_bearing_rad;
  F f(motion, radar);
  typename F::State x0;
  x0 << S(-15000), S(200), S(0), S(8000), T::from_ratio(1257, 10), S(0);
  if (f.reset(x0, F::Cov::Identity() * S(100)) != Status::kOk) std::abort();
  const auto scans = s1_scans<S>();
  const S dt = T::from_ratio(1, 2);
  CALLGRIND_TOGGLE_COLLECT;
  for (std::size_t k = 1; k < scans.size(); ++k) {
    if (f.predict(dt) != Status::kOk || f.update(scans[k].z[0]) != Status::kOk) std::abort();
  }
  CALLGRIND_TOGGLE_COLLECT;
  const std::string label = std::string("filter/") + scalar + "/" + form + " steps=" + std::to_string(scans.size() - 1);
  CALLGRIND_DUMP_STATS_AT(label.c_str());
  std::printf("%s\n", label.c_str());
}

template <class S, EkfUpdateForm kForm>
void count_tracker(const char* scalar, const char* form) {
  using F = Ekf<CaMotion<S>, CaPolarRadar<S>, kForm>;
  using Tr = RadarTracker<F, 4, 4>;
  static constexpr RadarTrackerParams kP = test::tuned_params();
  static constexpr RadarTrackerConfig<S> kS = radar_tracker_config<S>(kP);
  CaMotion<S> motion;
  motion.qj = kS.qj;
  CaPolarRadar<S> radar;
  radar.sigma_range_m = kS.sigma_range_m;
  radar.sigma_bearing_rad = kS.sigma_bearing_rad;
  Tr tracker(F(motion, radar), {radar, kS.max_speed_mps, kS.init_accel_sigma_mps2}, tracker_config_of<S>(kP, kS));
  const auto scans = s1_scans<S>();
  CALLGRIND_TOGGLE_COLLECT;
  for (const auto& scan : scans) {
    if (tracker.step(scan) != Status::kOk) std::abort();
  }
  CALLGRIND_TOGGLE_COLLECT;
  const std::string label = std::string("tracker/") + scalar + "/" + form + " steps=" + std::to_string(scans.size());
  CALLGRIND_DUMP_STATS_AT(label.c_str());
  std::printf("%s\n", label.c_str());
}

/// Coast the first confirmed track of S1 seed 1 after 100 frames at
/// T = 0.5 s until predict() is refused; print how long that took.
template <class Q>
void coast(bool tuned) {
  test::S1Options o;
  o.seed = 1;
  o.steps = 100;
  o.tuned = tuned;
  EkfCa<Q> f;
  bool have = false;
  test::run_s1<Q>(o, [&](int, const test::S1Sample&, const test::S1Tracker<Q>& tr) {
    // The first confirmed track in table order, as it is after the last frame.
    for (std::size_t i = 0; i < tr.tracks().capacity(); ++i) {
      const auto& t = tr.tracks()[i];
      if (tr.tracks().active(i) && t.initialised && t.status == TrackStatus::kConfirmed) {
        f = t.filter;
        have = true;
        break;
      }
    }
  });
  if (!have) std::abort();
  reset_fixed_point_overflow_count();
  int k = 0;
  double var_before = 0;
  for (; k < 100000; ++k) {
    const auto P = f.P();
    if (f.predict(ScalarTraits<Q>::from_ratio(1, 2)) != Status::kOk) {
      var_before = static_cast<double>(P(0, 0)) + static_cast<double>(P(3, 3));
      break;
    }
  }
  std::printf("coast Q%d.%d qj %s: predict refused after %d steps = %.1f s (var x + var y before: %.3g m^2), "
              "saturations %u\n",
              63 - Q::kFractionBits, Q::kFractionBits, tuned ? "160" : "1.6", k, 0.5 * k, var_before,
              static_cast<unsigned>(fixed_point_overflow_count()));
}

}  // namespace

int main() {
  using kestrel::EkfUpdateForm;
  count_filter<double, EkfUpdateForm::kBatch>("double", "batch");
  count_filter<double, EkfUpdateForm::kSequentialWhitened>("double", "sequential");
  count_filter<float, EkfUpdateForm::kBatch>("float", "batch");
  count_filter<float, EkfUpdateForm::kSequentialWhitened>("float", "sequential");
  count_filter<kestrel::Q31_32, EkfUpdateForm::kSequentialWhitened>("q31_32", "sequential");
  count_filter<kestrel::Q23_40, EkfUpdateForm::kSequentialWhitened>("q23_40", "sequential");
  count_tracker<double, EkfUpdateForm::kBatch>("double", "batch");
  count_tracker<double, EkfUpdateForm::kSequentialWhitened>("double", "sequential");
  count_tracker<float, EkfUpdateForm::kBatch>("float", "batch");
  count_tracker<float, EkfUpdateForm::kSequentialWhitened>("float", "sequential");
  count_tracker<kestrel::Q31_32, EkfUpdateForm::kSequentialWhitened>("q31_32", "sequential");
  count_tracker<kestrel::Q23_40, EkfUpdateForm::kSequentialWhitened>("q23_40", "sequential");
  coast<kestrel::Q31_32>(false);
  coast<kestrel::Q31_32>(true);
  coast<kestrel::Q23_40>(false);
  coast<kestrel::Q23_40>(true);
  return 0;
}
