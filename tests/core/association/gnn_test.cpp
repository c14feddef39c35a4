// SPDX-License-Identifier: Apache-2.0
// GNN (docs/tracking.md): the Hungarian solver against brute-force enumeration
// of every partial assignment on small random matrices (with forbidden
// pairs and misses), a case where greedy nearest neighbour is not optimal,
// bad inputs, and zero allocations.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>

#include "kestrel/association/gnn.hpp"
#include "support/alloc_guard.hpp"

namespace {

using kestrel::Status;
constexpr int kRows = 6;
constexpr int kCols = 7;
using G = kestrel::Gnn<double, kRows, kCols>;

/// Minimum over every assignment (each row a distinct column or none) of
/// sum cost + miss * unassigned, pairs with cost > miss or +Inf excluded.
double brute_force(const G::CostMatrix& c, double miss, int row, unsigned used_cols) {
  if (row == c.rows()) return 0.0;
  double best = miss + brute_force(c, miss, row + 1, used_cols);
  for (int j = 0; j < c.cols(); ++j) {
    if ((used_cols >> j) & 1u) continue;
    const double v = c(row, j);
    if (!std::isfinite(v) || v > miss) continue;
    best = std::min(best, v + brute_force(c, miss, row + 1, used_cols | (1u << j)));
  }
  return best;
}

/// The cost of an assignment as the solver returned it, or NaN if invalid.
double cost_of(const G::CostMatrix& c, double miss, const int (&a)[kRows]) {
  double sum = 0.0;
  unsigned used = 0;
  for (int i = 0; i < c.rows(); ++i) {
    if (a[i] < 0) {
      sum += miss;
      continue;
    }
    if (a[i] >= c.cols() || ((used >> a[i]) & 1u)) return std::nan("");
    const double v = c(i, a[i]);
    if (!std::isfinite(v) || v > miss) return std::nan("");
    used |= 1u << a[i];
    sum += v;
  }
  return sum;
}

}  // namespace

SCENARIO("GNN finds the optimal assignment that brute force finds", "[gnn]") {
  std::mt19937_64 rng(2024);
  std::uniform_int_distribution<int> rows(1, kRows), cols(0, kCols);
  std::uniform_real_distribution<double> value(0.0, 12.0), coin(0.0, 1.0);
  G gnn;
  int mismatches = 0, invalid = 0, with_misses = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const auto n_cols = cols(rng);  // own statements: argument order is unspecified
    const auto n_rows = rows(rng);
    G::CostMatrix c(n_rows, n_cols);
    for (int i = 0; i < c.rows(); ++i) {
      for (int j = 0; j < c.cols(); ++j) {
        const double r = coin(rng);
        // Some pairs forbidden by +Inf, some by exceeding the miss cost,
        // some ties (integer costs).
        c(i, j) = r < 0.15 ? std::numeric_limits<double>::infinity() : (r < 0.3 ? std::floor(value(rng)) : value(rng));
      }
    }
    const double miss = 9.21;  // a 2-D 0.99 gate threshold
    int a[kRows];
    double total = -1.0;
    REQUIRE(gnn.solve(c, miss, a, total) == Status::kOk);
    const double expected = brute_force(c, miss, 0, 0u);
    const double got = cost_of(c, miss, a);
    if (!std::isfinite(got)) ++invalid;
    // Sums of at most 6 terms below 13: 1e-9 covers any summation order.
    if (std::abs(got - expected) > 1e-9 || std::abs(total - expected) > 1e-9) ++mismatches;
    for (int i = 0; i < c.rows(); ++i) with_misses += a[i] < 0 ? 1 : 0;
  }
  CHECK(invalid == 0);
  CHECK(mismatches == 0);
  CHECK(with_misses > 0);
}

SCENARIO("GNN beats greedy nearest neighbour where the nearest choice blocks another track", "[gnn]") {
  // Track 0 is nearest to measurement 0 (1.0) but can also take 1 (2.0);
  // track 1 can only take measurement 0 (1.5). Greedy: 1.0 + miss 9.21;
  // optimal: 2.0 + 1.5.
  G gnn;
  G::CostMatrix c(2, 2);
  c << 1.0, 2.0, 1.5, std::numeric_limits<double>::infinity();
  int a[kRows];
  double total = 0.0;
  REQUIRE(gnn.solve(c, 9.21, a, total) == Status::kOk);
  CHECK(a[0] == 1);
  CHECK(a[1] == 0);
  CHECK(total == Approx(3.5));
}

SCENARIO("GNN refuses bad inputs and leaves its outputs alone", "[gnn]") {
  G gnn;
  int a[kRows] = {7, 7, 7, 7, 7, 7};
  double total = 42.0;
  G::CostMatrix c(2, 2);
  c << 1.0, std::nan(""), 2.0, 3.0;
  CHECK(gnn.solve(c, 9.21, a, total) == Status::kNonFinite);
  c(0, 1) = -std::numeric_limits<double>::infinity();
  CHECK(gnn.solve(c, 9.21, a, total) == Status::kNonFinite);
  c(0, 1) = 1.0;
  CHECK(gnn.solve(c, std::numeric_limits<double>::infinity(), a, total) == Status::kNonFinite);
  G::CostMatrix empty(0, 3);
  CHECK(gnn.solve(empty, 9.21, a, total) == Status::kOutOfRange);
  CHECK(a[0] == 7);
  CHECK(total == 42.0);
  WHEN("there are no measurements at all") {
    G::CostMatrix none(3, 0);
    REQUIRE(gnn.solve(none, 9.21, a, total) == Status::kOk);
    THEN("every track misses") {
      CHECK(a[0] == -1);
      CHECK(a[2] == -1);
      CHECK(total == Approx(3 * 9.21));
    }
  }
}

SCENARIO("GNN solves full-size problems without allocating", "[gnn][alloc]") {
  using Big = kestrel::Gnn<float, 32, 64>;
  static Big gnn;
  static Big::CostMatrix c(32, 64);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<float> value(0.0f, 20.0f);
  for (int i = 0; i < 32; ++i) {
    for (int j = 0; j < 64; ++j) c(i, j) = value(rng);
  }
  int a[32];
  float total = 0.0f;
  std::size_t allocations = 0;
  Status s = Status::kOk;
  {
    kestrel::test::AllocationGuard guard;
    s = gnn.solve(c, 9.21f, a, total);
    allocations = guard.allocations();
  }
  CHECK(s == Status::kOk);
  CHECK(allocations == 0);
  int assigned = 0;
  for (int i = 0; i < 32; ++i) assigned += a[i] >= 0 ? 1 : 0;
  CHECK(assigned > 16);  // about 46 % of costs lie below 9.21: most tracks find one
}
