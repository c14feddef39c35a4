// SPDX-License-Identifier: Apache-2.0
// PolarRadar::particle_residual (the CRPF's per-particle cost, paper 001
// eqs. 5-6) is residual(z, predict(x)) bit for bit: both bearings come from
// ScalarTraits' atan2. All four quadrants and across the +-pi cut; double
// and float.
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
  int bearing_mismatch = 0;
  for (int i = 0; i < n; ++i) {
    const double b = -kPi + 2.0 * kPi * (i + 0.5) / n;
    for (const double db : {0.003, -0.003, 2.0 * kPi - 0.003}) {
      typename Motion::State x;
      x << static_cast<S>(1400.0 * std::cos(b + db)), S(10), static_cast<S>(1400.0 * std::sin(b + db)), S(5);
      const typename Radar::Measurement z(static_cast<S>(1401.5), static_cast<S>(std::remainder(b, 2.0 * kPi)));
      const typename Radar::Measurement want = radar.residual(z, radar.predict(x));
      const typename Radar::Measurement got = radar.particle_residual(z, x);
      if (std::memcmp(&want(0), &got(0), sizeof(S)) != 0) ++range_mismatch;
      if (std::memcmp(&want(1), &got(1), sizeof(S)) != 0) ++bearing_mismatch;
    }
  }
  CHECK(range_mismatch == 0);
  CHECK(bearing_mismatch == 0);
}

}  // namespace

SCENARIO("PolarRadar::particle_residual equals residual(z, predict(x)) bit for bit",
         "[models][polar][crpf]") {
  GIVEN("double") { check_against_residual<double>(); }
  GIVEN("float") { check_against_residual<float>(); }
}
