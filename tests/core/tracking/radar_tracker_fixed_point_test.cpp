// SPDX-License-Identifier: Apache-2.0
// The EKF-CA radar tracker on the fixed-point scalars against double, on
// S1 and S1n frames generated with integer arithmetic and fed through the
// HAL boundary (tests/core/scalar/s1_integer_scenario.hpp): the same
// association decisions, position deviation <= 5 mm (Q31.32), RMSE within
// 0.5 % of double, no overflow event; and the golden hash of every step's
// state and covariance. Set KESTREL_PRINT_ACCURACY=1 to print the table of
// docs/fixed-point.md.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "kestrel/scalar/fixed_point_io.hpp"
#include "core/scalar/s1_reports.hpp"
#include "support/alloc_guard.hpp"

namespace {

using kestrel::test::S1Options;
using kestrel::test::S1Sample;
using kestrel::test::S1Tracker;
using Step = kestrel::test::S1Step;
using Comparison = kestrel::test::S1Comparison;
using kestrel::test::compare_s1;
using kestrel::test::s1_rmse;

template <class S>
std::vector<Step> run(const S1Options& o) {
  auto tracker = kestrel::test::make_s1_tracker<S>(o.tuned);
  std::vector<Step> steps = kestrel::test::s1_reports(tracker, o);
  REQUIRE(steps.size() == static_cast<std::size_t>(o.steps));
  return steps;
}

bool print_table() { return std::getenv("KESTREL_PRINT_ACCURACY") != nullptr; }

}  // namespace

SCENARIO("the fixed-point radar tracker matches the double tracker on S1 and S1n", "[tracker][fixed_point][s1]") {
  constexpr int kSeeds = 8;
  double worst_dev_q31 = 0, worst_dev_q23 = 0, worst_dev_f = 0;
  double worst_rmse_q31 = 0, worst_rmse_q23 = 0, worst_rmse_f = 0;
  int mismatches_q31 = 0, mismatches_q23 = 0;
  std::uint32_t overflows = 0;
  int runs = 0;
  if (print_table()) {
    std::printf("%-4s %-5s %4s | %9s | %9s %8s | %9s %8s | %9s %8s\n", "scen", "qj", "seed", "double m",
                "float m", "dev m", "Q31.32 m", "dev m", "Q23.40 m", "dev m");
  }
  for (int tuned = 0; tuned < 2; ++tuned) {
    for (int noisy = 0; noisy < 2; ++noisy) {
      for (int seed = 1; seed <= kSeeds; ++seed) {
        S1Options o;
        o.seed = static_cast<std::uint64_t>(seed);
        o.time_varying_noise = noisy != 0;
        o.tuned = tuned != 0;
        const auto d = run<double>(o);
        const auto f = run<float>(o);
        kestrel::reset_fixed_point_overflow_count();
        const auto q31 = run<kestrel::Q31_32>(o);
        const auto q23 = run<kestrel::Q23_40>(o);
        overflows += kestrel::fixed_point_overflow_count();
        const Comparison c31 = compare_s1(d, q31), c23 = compare_s1(d, q23), cf = compare_s1(d, f);
        const double r = s1_rmse(d);
        worst_dev_q31 = std::max(worst_dev_q31, c31.max_deviation_m);
        worst_dev_q23 = std::max(worst_dev_q23, c23.max_deviation_m);
        worst_dev_f = std::max(worst_dev_f, cf.max_deviation_m);
        worst_rmse_q31 = std::max(worst_rmse_q31, std::fabs(s1_rmse(q31) / r - 1));
        worst_rmse_q23 = std::max(worst_rmse_q23, std::fabs(s1_rmse(q23) / r - 1));
        worst_rmse_f = std::max(worst_rmse_f, std::fabs(s1_rmse(f) / r - 1));
        mismatches_q31 += c31.decision_mismatches;
        mismatches_q23 += c23.decision_mismatches;
        ++runs;
        if (print_table()) {
          std::printf("%-4s %-5s %4d | %9.4f | %9.4f %8.1e | %9.4f %8.1e | %9.4f %8.1e\n", noisy ? "S1n" : "S1",
                      tuned ? "160" : "1.6", seed, r, s1_rmse(f), cf.max_deviation_m, s1_rmse(q31), c31.max_deviation_m,
                      s1_rmse(q23), c23.max_deviation_m);
        }
      }
    }
  }
  if (print_table()) {
    std::printf("worst over %d runs: deviation float %.2e m, Q31.32 %.2e m, Q23.40 %.2e m; |RMSE/RMSE_double - 1| "
                "float %.2e, Q31.32 %.2e, Q23.40 %.2e\n",
                runs, worst_dev_f, worst_dev_q31, worst_dev_q23, worst_rmse_f, worst_rmse_q31, worst_rmse_q23);
  }
  // One THEN: Catch2 reruns the scenario body once per leaf section.
  THEN("Q31.32 stays within 5 mm of double, Q23.40 within 0.1 mm, with the same decisions, RMSE within 0.5 % "
       "and no saturation") {
    INFO("Q31.32 deviation " << worst_dev_q31 << " m, Q23.40 " << worst_dev_q23 << " m, float " << worst_dev_f << " m");
    CHECK(mismatches_q31 == 0);
    CHECK(mismatches_q23 == 0);
    CHECK(worst_dev_q31 <= 5e-3);
    CHECK(worst_dev_q23 <= 1e-4);
    CHECK(worst_rmse_q31 <= 5e-3);
    CHECK(worst_rmse_q23 <= 5e-3);
    CHECK(overflows == 0);
  }
}

SCENARIO("a fixed-point tracker step allocates nothing", "[tracker][fixed_point][alloc]") {
  auto tracker = kestrel::test::make_s1_tracker<kestrel::Q31_32>(false);
  kestrel::test::SplitMix64 rng(9);
  S1Options o;
  S1Tracker<kestrel::Q31_32>::Scan scan;
  std::size_t allocations = 0;
  for (int k = 0; k < 40; ++k) {
    const S1Sample s = kestrel::test::s1_sample(k, o, rng);
    REQUIRE(kestrel::hal::to_scan(kestrel::test::s1_frame(s), scan) == kestrel::Status::kOk);
    kestrel::test::AllocationGuard guard;
    REQUIRE(tracker.step(scan) == kestrel::Status::kOk);
    allocations += guard.allocations();
  }
  CHECK(allocations == 0);
  CHECK(tracker.reports().size() >= 1);
}

SCENARIO("the fixed-point golden hash of S1 is the checked-in constant", "[tracker][fixed_point][golden]") {
  kestrel::reset_fixed_point_overflow_count();
  const std::uint64_t q31 = kestrel::test::s1_golden_hash<32>();
  const std::uint64_t q23 = kestrel::test::s1_golden_hash<40>();
  INFO("Q31.32 hash 0x" << std::hex << q31 << ", Q23.40 hash 0x" << q23);
  CHECK(q31 == kestrel::test::kS1GoldenHashQ31_32);
  CHECK(q23 == kestrel::test::kS1GoldenHashQ23_40);
  CHECK(kestrel::fixed_point_overflow_count() == 0);
}
