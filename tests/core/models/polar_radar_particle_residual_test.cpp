// SPDX-License-Identifier: Apache-2.0
// PolarRadar::particle_residuals (the CRPF's per-particle risk and cost,
// paper 001 eqs. 5-6): the bearing of a state near the reference as the
// reference's bearing plus a small angle. Checked against the residual in
// long double: within 4 ulp of pi in double and float, all round the circle
// and across the +-pi cut, on both sides of the switch (tangent 1/16); the range,
// and the bearing of a state the series does not serve, are bit for bit
// residual(z, predict(x)), and so is every residual in fixed point.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>

#include "kestrel/models/measurement/polar_radar.hpp"
#include "kestrel/models/motion/constant_velocity_2d.hpp"
#include "kestrel/scalar/fixed_point_eigen.hpp"
#include "kestrel/scalar/fixed_point_math.hpp"

namespace {

constexpr long double kPiL = 3.141592653589793238462643383279502884L;

template <class S>
bool same_bits(S a, S b) {
  return std::memcmp(&a, &b, sizeof(S)) == 0;
}

/// z_b - atan2(y, x) wrapped to (-pi, pi], in long double.
long double exact_bearing_residual(long double zb, long double y, long double x) {
  long double d = std::remainder(zb - std::atan2(y, x), 2.0L * kPiL);
  if (d <= -kPiL) d += 2.0L * kPiL;
  return d;
}

template <class S>
typename kestrel::ConstantVelocity2D<S>::State at(double range, double bearing) {
  const auto v = [](double d) { return kestrel::ScalarTraits<S>::from_double(d); };
  typename kestrel::ConstantVelocity2D<S>::State x;
  x << v(range * std::cos(bearing)), v(10.0), v(range * std::sin(bearing)), v(5.0);
  return x;
}

struct Tally {
  long double worst_error = 0.0L;  ///< Of the bearing, rad.
  int range_mismatch = 0;          ///< Range not bit for bit residual()'s.
  int far_mismatch = 0;            ///< Bearing beyond the switch not bit for bit residual()'s.
  int near = 0;                    ///< States within the series' reach.
  int far = 0;
};

/// Measurements all round the circle at three ranges; the reference 0.01
/// rad off the measurement, states at angles from it on both sides of the
/// switch (atan(1/16) = 0.06242 rad), and on the other side of the cut.
template <class S>
Tally sweep() {
  using Motion = kestrel::ConstantVelocity2D<S>;
  using Radar = kestrel::PolarRadar<Motion>;
  const Radar radar{};
  constexpr double kPi = 3.14159265358979323846;
  Tally t;
  const int n = 1500;
  for (const double range : {3.0, 1414.0, 80000.0}) {
    for (int i = 0; i < n; ++i) {
      const double b = -kPi + 2.0 * kPi * (i + 0.5) / n;
      const typename Radar::Measurement z(static_cast<S>(range + 1.5), static_cast<S>(std::remainder(b, 2.0 * kPi)));
      const auto residual_of = radar.particle_residuals(z, at<S>(range, b + 0.01));
      for (const double offset : {0.0, 1e-9, 0.003, -0.003, 0.03, -0.05, 0.0624, -0.0624, 0.0627, -0.0627, 0.2,
                                  2.0 * kPi - 0.003, 3.0}) {
        const auto x = at<S>(range * (1.0 + 0.01 * std::sin(7.0 * b)), b + 0.01 + offset);
        const typename Radar::Measurement got = residual_of(x);
        const typename Radar::Measurement want = radar.residual(z, radar.predict(x));
        if (!same_bits(got(0), want(0))) ++t.range_mismatch;
        const long double exact =
            exact_bearing_residual(static_cast<long double>(z(1)), static_cast<long double>(x(2)),
                                   static_cast<long double>(x(0)));
        long double err = std::fabs(static_cast<long double>(got(1)) - exact);
        err = std::fmin(err, 2.0L * kPiL - err);  // +pi and -pi are the same angle
        if (err > t.worst_error) t.worst_error = err;
        const double from_ref = std::fabs(std::remainder(offset, 2.0 * kPi));
        if (from_ref < 0.0624) {
          ++t.near;
        } else if (from_ref > 0.0626) {
          ++t.far;
          if (!same_bits(got(1), want(1))) ++t.far_mismatch;
        }
      }
    }
  }
  return t;
}

template <class S>
long double ulp_of_pi() {
  const S pi = static_cast<S>(3.14159265358979323846);
  return static_cast<long double>(std::nextafter(pi, S(4)) - pi);
}

}  // namespace

SCENARIO("PolarRadar::particle_residuals is within 4 ulp of pi of the exact residual", "[models][polar][crpf]") {
  GIVEN("double") {
    const Tally t = sweep<double>();
    CHECK(t.near > 10000);
    CHECK(t.far > 10000);
    CHECK(t.range_mismatch == 0);
    CHECK(t.far_mismatch == 0);
    CHECK(t.worst_error <= 4.0L * ulp_of_pi<double>());
  }
  GIVEN("float") {
    const Tally t = sweep<float>();
    CHECK(t.range_mismatch == 0);
    CHECK(t.far_mismatch == 0);
    CHECK(t.worst_error <= 4.0L * ulp_of_pi<float>());
  }
}

SCENARIO("PolarRadar::particle_residuals takes the full path when the reference cannot serve",
         "[models][polar][crpf][status]") {
  using Motion = kestrel::ConstantVelocity2D<double>;
  using Radar = kestrel::PolarRadar<Motion>;
  const Radar radar{};
  const Radar::Measurement z(1401.5, 0.79);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  GIVEN("a reference on the radar, one not finite, and one opposite the states") {
    int checked = 0;
    int mismatch = 0;
    for (const Motion::State& ref : {Motion::State(0.0, 0.0, 0.0, 0.0), Motion::State(nan, 1.0, 1000.0, 1.0),
                                     Motion::State(inf, 1.0, 1000.0, 1.0), Motion::State(-1000.0, 0.0, -1000.0, 0.0)}) {
      const auto residual_of = radar.particle_residuals(z, ref);
      for (const double b : {0.78, 0.8, -2.0, 3.1}) {
        const Motion::State x = at<double>(1400.0, b);
        const Radar::Measurement got = residual_of(x);
        const Radar::Measurement want = radar.residual(z, radar.predict(x));
        ++checked;
        if (!same_bits(got(0), want(0)) || !same_bits(got(1), want(1))) ++mismatch;
      }
    }
    THEN("every state's residual is residual(z, predict(x)) bit for bit") {
      CHECK(checked == 16);
      CHECK(mismatch == 0);
    }
  }
  GIVEN("a good reference and states that are not finite or sit on the radar") {
    const auto residual_of = radar.particle_residuals(z, at<double>(1400.0, 0.78));
    THEN("a NaN state gives a NaN residual and a state on the radar residual()'s") {
      const Radar::Measurement bad = residual_of(Motion::State(nan, 0.0, 1000.0, 0.0));
      CHECK(std::isnan(bad(0)));
      CHECK(std::isnan(bad(1)));
      const Motion::State origin(0.0, 1.0, 0.0, 1.0);
      const Radar::Measurement got = residual_of(origin);
      const Radar::Measurement want = radar.residual(z, radar.predict(origin));
      CHECK(same_bits(got(0), want(0)));
      CHECK(same_bits(got(1), want(1)));
    }
  }
}

SCENARIO("PolarRadar::particle_residuals in fixed point is residual(z, predict(x)) bit for bit",
         "[models][polar][crpf][fixed]") {
  using S = kestrel::Q31_32;
  using Motion = kestrel::ConstantVelocity2D<S>;
  using Radar = kestrel::PolarRadar<Motion>;
  const Radar radar{};
  const auto v = [](double d) { return S::from_double(d); };
  const Radar::Measurement z(v(1401.5), v(0.79));
  const auto residual_of = radar.particle_residuals(z, at<S>(1400.0, 0.78));
  int mismatch = 0;
  for (const double b : {0.78, 0.781, 0.8, -2.0, 3.1, -3.1}) {
    const Motion::State x = at<S>(1400.0, b);
    const Radar::Measurement got = residual_of(x);
    const Radar::Measurement want = radar.residual(z, radar.predict(x));
    if (!(got(0) == want(0)) || !(got(1) == want(1))) ++mismatch;
  }
  CHECK(mismatch == 0);
}
