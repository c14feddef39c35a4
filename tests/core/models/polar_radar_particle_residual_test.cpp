// SPDX-License-Identifier: Apache-2.0
// PolarRadar::particle_residual (the CRPF's per-particle cost, paper 001
// eqs. 5-6): the range residual is residual(z, predict(x))'s bit for bit,
// the bearing residual within a few ulp of pi (it differs only through
// deterministic_atan2, within 1 ulp of std::atan2, and the wrap), in all
// four quadrants and across the +-pi cut; double and float.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>

#include "kestrel/models/measurement/polar_radar.hpp"
#include "kestrel/models/motion/constant_velocity_2d.hpp"

namespace {

template <class S>
void check_against_residual() {
  using Motion = kestrel::ConstantVelocity2D<S>;
  using Radar = kestrel::PolarRadar<Motion>;
  const Radar radar{};
  constexpr double kPi = 3.14159265358979323846;
  // Bearings of the measurement and the particle all round the circle
  // (the particle 0.003 rad off, and also on the other side of the cut).
  const int n = 2000;
  int range_mismatch = 0;
  double worst_bearing = 0.0;
  for (int i = 0; i < n; ++i) {
    const double b = -kPi + 2.0 * kPi * (i + 0.5) / n;
    for (const double db : {0.003, -0.003, 2.0 * kPi - 0.003}) {
      typename Motion::State x;
      x << static_cast<S>(1400.0 * std::cos(b + db)), S(10), static_cast<S>(1400.0 * std::sin(b + db)), S(5);
      const typename Radar::Measurement z(static_cast<S>(1401.5), static_cast<S>(std::remainder(b, 2.0 * kPi)));
      const typename Radar::Measurement want = radar.residual(z, radar.predict(x));
      const typename Radar::Measurement got = radar.particle_residual(z, x);
      if (std::memcmp(&want(0), &got(0), sizeof(S)) != 0) ++range_mismatch;
      worst_bearing = std::max(worst_bearing, std::abs(static_cast<double>(got(1)) - static_cast<double>(want(1))));
    }
  }
  INFO("range mismatches " << range_mismatch << ", worst bearing difference " << worst_bearing << " rad");
  CHECK(range_mismatch == 0);
  // One ulp of the atan2 result (at most ulp(pi)) passes through z_b - h_b
  // exactly or with one more rounding: 2 ulp(pi) bounds it.
  const double ulp_pi = static_cast<double>(std::nextafter(static_cast<S>(kPi), S(4)) - static_cast<S>(kPi));
  CHECK(worst_bearing <= 2.0 * ulp_pi);
}

}  // namespace

SCENARIO("PolarRadar::particle_residual equals residual(z, predict(x)) up to an ulp of the bearing",
         "[models][polar][crpf]") {
  GIVEN("double") { check_against_residual<double>(); }
  GIVEN("float") { check_against_residual<float>(); }
}
