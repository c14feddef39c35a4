// SPDX-License-Identifier: Apache-2.0
// Chi-square gate table against an independent evaluation of the CDF.
#include <catch2/catch.hpp>
#include <cmath>

#include "kestrel/association/chi_square.hpp"
#include "kestrel/association/gate.hpp"

namespace {
// Regularised lower incomplete gamma P(k/2, x/2) by its power series: an
// independent check of the table (the series converges for all x here).
double chi_square_cdf(int k, double x) {
  const double a = k / 2.0;
  const double hx = x / 2.0;
  double term = 1.0 / a;
  double sum = term;
  for (int n = 1; n < 500; ++n) {
    term *= hx / (a + n);
    sum += term;
  }
  return sum * std::exp(-hx + a * std::log(hx) - std::lgamma(a));
}
}  // namespace

SCENARIO("chi-square gate thresholds are the quantiles they claim", "[gate]") {
  using kestrel::GateProbability;
  const struct {
    GateProbability p;
    double prob;
  } probs[] = {{GateProbability::k90, 0.90}, {GateProbability::k95, 0.95}, {GateProbability::k99, 0.99},
               {GateProbability::k995, 0.995}, {GateProbability::k999, 0.999}};
  for (const auto& pr : probs) {
    // 3-decimal table: the CDF at the tabulated value is within 2e-4 of p.
    CHECK(chi_square_cdf(1, kestrel::chi_square_quantile<1>(pr.p)) == Approx(pr.prob).margin(2e-4));
    CHECK(chi_square_cdf(2, kestrel::chi_square_quantile<2>(pr.p)) == Approx(pr.prob).margin(2e-4));
    CHECK(chi_square_cdf(3, kestrel::chi_square_quantile<3>(pr.p)) == Approx(pr.prob).margin(2e-4));
    CHECK(chi_square_cdf(4, kestrel::chi_square_quantile<4>(pr.p)) == Approx(pr.prob).margin(2e-4));
    CHECK(chi_square_cdf(7, kestrel::chi_square_quantile<7>(pr.p)) == Approx(pr.prob).margin(2e-4));
    CHECK(chi_square_cdf(8, kestrel::chi_square_quantile<8>(pr.p)) == Approx(pr.prob).margin(2e-4));
  }
  GIVEN("a 2D gate at 99 %") {
    const auto gate = kestrel::EllipsoidalGate<double, 2>::with_probability(GateProbability::k99);
    kestrel::Innovation<double, 2> in{{1, 1}, Eigen::Matrix2d::Identity(), 9.2, kestrel::Status::kOk};
    THEN("d2 = 9.2 passes, 9.3 does not, and a failed innovation never passes") {
      CHECK(gate.accepts(in));
      in.d2 = 9.3;
      CHECK_FALSE(gate.accepts(in));
      in.d2 = 0.1;
      in.status = kestrel::Status::kNotPositiveDefinite;
      CHECK_FALSE(gate.accepts(in));
    }
  }
}

TEST_CASE("A gate probability read as a number names its gate, and any other number none", "[gate]") {
  using kestrel::GateProbability;
  for (const GateProbability p : {GateProbability::k90, GateProbability::k95, GateProbability::k99,
                                  GateProbability::k995, GateProbability::k999}) {
    GateProbability g = p == GateProbability::k90 ? GateProbability::k999 : GateProbability::k90;
    CHECK(kestrel::gate_probability_from(kestrel::gate_probability(p), g));
    CHECK(g == p);
  }
  GateProbability g = GateProbability::k95;
  CHECK(kestrel::gate_probability_from(0.995, g));  // as parsed from "0.995"
  CHECK(g == GateProbability::k995);
  for (const double other : {0.0, 0.97, 0.9901, 1.0, 99.0, -0.9, std::nan("")}) {
    g = GateProbability::k95;
    CHECK_FALSE(kestrel::gate_probability_from(other, g));
    CHECK(g == GateProbability::k95);  // unchanged
  }
  static_assert([] {
    GateProbability c{};
    return kestrel::gate_probability_from(0.99, c) && c == GateProbability::k99;
  }());
}
