// SPDX-License-Identifier: Apache-2.0
// wrap_angle in float and double: the fast paths (already wrapped, one turn
// off) return exactly what the remainder() reduction returns, so moving a
// bearing residual through them changes no bit of any result.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <random>

#include "kestrel/scalar/scalar_traits.hpp"

namespace {

/// The reduction without fast paths: remainder() into [-pi, pi], -pi to pi.
template <class F>
F wrap_by_remainder(F a) {
  const F two_pi = static_cast<F>(2.0 * 3.14159265358979323846);
  const F r = std::remainder(a, two_pi);
  return r <= -kestrel::ScalarTraits<F>::pi() ? r + two_pi : r;
}

template <class F>
bool same_bits(F a, F b) {
  return std::memcmp(&a, &b, sizeof(F)) == 0;
}

}  // namespace

TEMPLATE_TEST_CASE("Scenario: wrap_angle equals the remainder reduction bit for bit", "[math][wrap]", float, double) {
  using F = TestType;
  using T = kestrel::ScalarTraits<F>;
  const F pi = T::pi();
  const F two_pi = static_cast<F>(2.0 * 3.14159265358979323846);
  GIVEN("random angles in (-8, 8) rad and the differences of two wrapped angles") {
    std::mt19937_64 g(17);
    std::uniform_real_distribution<double> wide(-8.0, 8.0);
    std::uniform_real_distribution<double> wrapped(-3.14159265358979323846, 3.14159265358979323846);
    int differ = 0;
    int outside = 0;
    for (int i = 0; i < 200000; ++i) {
      const F a = (i % 2 == 0) ? static_cast<F>(wide(g)) : static_cast<F>(wrapped(g)) - static_cast<F>(wrapped(g));
      const F w = T::wrap_angle(a);
      differ += same_bits(w, wrap_by_remainder(a)) ? 0 : 1;
      outside += (w > -pi && w <= pi) ? 0 : 1;
    }
    THEN("every result is the reduction's, in (-pi, pi]") {
      CHECK(differ == 0);
      CHECK(outside == 0);
    }
  }
  GIVEN("the ends of each fast path and their neighbours") {
    const F ends[] = {pi, -pi, two_pi, -two_pi, F(0), F(-0.0), 3 * pi, -3 * pi};
    int differ = 0;
    for (const F e : ends) {
      for (const F a : {e, std::nextafter(e, F(10)), std::nextafter(e, F(-10))}) {
        differ += same_bits(T::wrap_angle(a), wrap_by_remainder(a)) ? 0 : 1;
      }
    }
    THEN("they agree too, and -pi maps to pi") {
      CHECK(differ == 0);
      CHECK(T::wrap_angle(-pi) == pi);
      CHECK(T::wrap_angle(two_pi) == F(0));
    }
  }
}
