// SPDX-License-Identifier: Apache-2.0
// deterministic_atan2 (math/atan2.hpp): within 1 ulp of std::atan2 (glibc's
// is correctly rounded) on a dense grid over the circle, over magnitudes
// from 1e-300 to 1e300 with every sign, and on both sides of each reduction
// boundary (t = 7/16, 11/16, 1); the special values of C99 Annex F bit for
// bit; pinned by a golden hash so a board (or a compiler that contracts
// a*b+c into an FMA) that gives other bits is caught.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

#include "kestrel/math/atan2.hpp"

namespace {

/// Distance in units in the last place between two finite values of the
/// same sign (different signs count as far apart unless both are zero).
template <class F>
std::int64_t ulp_distance(F a, F b) {
  using U = std::conditional_t<sizeof(F) == 8, std::int64_t, std::int32_t>;
  U ia;
  U ib;
  std::memcpy(&ia, &a, sizeof a);
  std::memcpy(&ib, &b, sizeof b);
  if ((ia < 0) != (ib < 0)) return (a < b || b < a) ? std::int64_t{1} << 40 : 0;
  const std::int64_t d = static_cast<std::int64_t>(ia) - static_cast<std::int64_t>(ib);
  return d < 0 ? -d : d;
}

template <class F>
bool same_bits(F a, F b) {
  if (std::isnan(a) && std::isnan(b)) return true;
  return std::memcmp(&a, &b, sizeof a) == 0;
}

struct GridResult {
  std::int64_t worst_ulp = 0;
  long points = 0;
  long off_by_one = 0;
};

template <class F>
void check_point(F y, F x, GridResult& g) {
  const std::int64_t u = ulp_distance(kestrel::deterministic_atan2(y, x), std::atan2(y, x));
  ++g.points;
  if (u > 0) ++g.off_by_one;
  if (u > g.worst_ulp) g.worst_ulp = u;
}

template <class F>
GridResult dense_grid() {
  GridResult g;
  constexpr double kPi = 3.14159265358979323846;
  // The circle, 400 000 angles at three radii (the CRPF's targets sit
  // 1-2 km out; 1e-3 and 1 cover the relative case).
  const int n = 400000;
  for (int i = 0; i < n; ++i) {
    const double th = -kPi + 2.0 * kPi * (i + 0.5) / n;
    for (const double r : {1e-3, 1.0, 1.4e3}) {
      check_point(static_cast<F>(r * std::sin(th)), static_cast<F>(r * std::cos(th)), g);
    }
  }
  // Huge and tiny ratios: every pair of magnitudes 2^e1, 2^e2 in the
  // scalar's normal range (step 7 in the exponent), every sign.
  const int emax = sizeof(F) == 8 ? 1000 : 120;
  for (int e1 = -emax; e1 <= emax; e1 += 7) {
    for (int e2 = -emax; e2 <= emax; e2 += 7) {
      const F y = static_cast<F>(std::ldexp(1.2345, e1));
      const F x = static_cast<F>(std::ldexp(1.7, e2));
      check_point(y, x, g);
      check_point(-y, x, g);
      check_point(y, -x, g);
      check_point(-y, -x, g);
    }
  }
  // Both sides of each reduction boundary, in all four quadrants and both
  // octants of each.
  for (const double t : {0.4375, 0.6875, 1.0}) {
    F y = static_cast<F>(t);
    F down = y;
    for (int k = 0; k < 3000; ++k) {
      for (const F v : {y, down}) {
        check_point(v, F(1), g);
        check_point(F(1), v, g);
        check_point(-v, F(-1), g);
        check_point(F(-1), -v, g);
      }
      y = std::nextafter(y, F(2));
      down = std::nextafter(down, F(0));
    }
  }
  return g;
}

template <class F>
void check_specials() {
  const F inf = std::numeric_limits<F>::infinity();
  const F nan = std::numeric_limits<F>::quiet_NaN();
  const F values[] = {F(0), -F(0), F(1), F(-1), inf, -inf, nan,
                      std::numeric_limits<F>::max(), -std::numeric_limits<F>::max(),
                      std::numeric_limits<F>::denorm_min(), -std::numeric_limits<F>::denorm_min(),
                      std::numeric_limits<F>::min(), F(3e30), F(-1e-30)};
  for (const F y : values) {
    for (const F x : values) {
      const F got = kestrel::deterministic_atan2(y, x);
      const F want = std::atan2(y, x);
      INFO("y = " << y << ", x = " << x << ": got " << got << ", std::atan2 " << want);
      // Zeros, infinities and NaNs are exact by Annex F; finite pairs keep
      // the grid's 1 ulp.
      const bool special = !(std::fabs(y) > F(0) && std::fabs(x) > F(0)) || std::isinf(y) || std::isinf(x) ||
                           std::isnan(y) || std::isnan(x);
      if (special) {
        CHECK(same_bits(got, want));
      } else {
        CHECK(ulp_distance(got, want) <= 1);
      }
    }
  }
}

/// FNV-1a over the bits of deterministic_atan2 on a fixed grid.
template <class F>
std::uint64_t grid_hash() {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (int i = -200; i <= 200; ++i) {
    for (int j = -200; j <= 200; ++j) {
      const F v = kestrel::deterministic_atan2(static_cast<F>(i) * F(0.37), static_cast<F>(j) * F(1.13));
      unsigned char bytes[sizeof(F)];
      std::memcpy(bytes, &v, sizeof(F));
      for (const unsigned char b : bytes) {
        h ^= b;
        h *= 0x100000001b3ull;
      }
    }
  }
  return h;
}

}  // namespace

SCENARIO("deterministic_atan2 is within 1 ulp of std::atan2 on a dense grid", "[atan2][math]") {
  GIVEN("double") {
    const GridResult g = dense_grid<double>();
    INFO(g.points << " points, " << g.off_by_one << " off by one ulp, worst " << g.worst_ulp << " ulp");
    THEN("no point is more than 1 ulp away") {
      // Measured worst 1 ulp; the brief allowed 1-2 (one rounded division
      // feeding a rounded sum), so 1 is the bound that holds.
      CHECK(g.worst_ulp <= 1);
      CHECK(g.points > 1200000);
    }
  }
  GIVEN("float") {
    const GridResult g = dense_grid<float>();
    INFO(g.points << " points, " << g.off_by_one << " off by one ulp, worst " << g.worst_ulp << " ulp");
    THEN("no point is more than 1 ulp away") { CHECK(g.worst_ulp <= 1); }
  }
}

SCENARIO("deterministic_atan2 gives C99 Annex F's special values", "[atan2][math]") {
  GIVEN("signed zeros, infinities, NaN, the largest, smallest and subnormal values") {
    THEN("double: special pairs bit for bit as std::atan2, finite pairs within 1 ulp") { check_specials<double>(); }
    THEN("float: the same") { check_specials<float>(); }
  }
}

SCENARIO("deterministic_atan2 gives the same bits everywhere", "[atan2][math][determinism]") {
  GIVEN("a 401 x 401 grid through all four quadrants and the axes") {
    THEN("its hash equals the golden value recorded on the host (x86-64, no FMA)") {
      // If this fails on a board, the compiler contracted a*b+c into an FMA
      // or changed an operation's order: see the note in atan2.hpp.
      CHECK(grid_hash<double>() == 0x69b562eab2c34539ull);
      CHECK(grid_hash<float>() == 0x9917b1b87cd43e05ull);
    }
  }
}
