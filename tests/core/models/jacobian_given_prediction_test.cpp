// SPDX-License-Identifier: Apache-2.0
// The radar models' Jacobian columns given h(x) (which reuse its range, so
// a linearisation takes one square root, not two) are bit for bit the
// columns computed from x alone, in every scalar the filters run on.
#include <catch2/catch.hpp>
#include <vector>

#include "kestrel/models/measurement/polar_radar.hpp"
#include "kestrel/models/measurement/polar_radar_range_rate.hpp"
#include "kestrel/models/motion/constant_acceleration_2d.hpp"
#include "kestrel/scalar/fixed_point_eigen.hpp"
#include "kestrel/scalar/fixed_point_math.hpp"

namespace {

template <class S>
using Ca = kestrel::ConstantAcceleration2D<S>;

/// Target states from 3 m to 100 km, in every quadrant, moving.
template <class S>
std::vector<typename Ca<S>::State> states() {
  std::vector<typename Ca<S>::State> out;
  const double positions[][2] = {{-15000.0, 8000.0}, {3.0, -4.0}, {-1.0e5, -2.0e4}, {26000.0, 1.5}, {0.5, 9000.0}};
  for (const auto& p : positions) {
    const auto v = [](double d) { return kestrel::ScalarTraits<S>::from_double(d); };
    typename Ca<S>::State x;
    x << v(p[0]), v(10.0), v(1.0), v(p[1]), v(-235.0), v(0.5);
    out.push_back(x);
  }
  return out;
}

template <class R>
bool columns_agree() {
  using S = typename R::Scalar;
  R radar{};
  bool same = true;
  for (const auto& x : states<S>()) same = same && (radar.jacobian_columns(x, radar.predict(x)) == radar.jacobian_columns(x));
  return same;
}

}  // namespace

TEMPLATE_TEST_CASE("Scenario: Jacobian columns given h(x) equal those from x alone", "[models]", double, float,
                   kestrel::Q31_32) {
  GIVEN("the polar radar and the polar radar with range rate at targets from 3 m to 100 km") {
    THEN("both forms give the same bits") {
      CHECK(columns_agree<kestrel::PolarRadar<Ca<TestType>>>());
      CHECK(columns_agree<kestrel::PolarRadarRangeRate<Ca<TestType>>>());
    }
  }
}
