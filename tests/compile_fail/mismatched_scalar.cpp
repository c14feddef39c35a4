// SPDX-License-Identifier: Apache-2.0
// An EKF whose motion model is double and measurement model float must not
// compile: the MeasurementModelFor concept requires one scalar.
#include "kestrel/filters/ekf.hpp"
#include "kestrel/models/measurement/polar_radar.hpp"
#include "kestrel/models/motion/constant_acceleration_2d.hpp"

extern "C" void kestrel_assert_failed(const char*, int, const char*) { __builtin_trap(); }

int main() {
  using MotionD = kestrel::ConstantAcceleration2D<double>;
#ifdef KESTREL_SHOULD_FAIL
  using RadarF = kestrel::PolarRadar<kestrel::ConstantAcceleration2D<float>>;
  kestrel::Ekf<MotionD, RadarF> ekf;
#else
  kestrel::Ekf<MotionD, kestrel::PolarRadar<MotionD>> ekf;
#endif
  return ekf.x().size() == 6 ? 0 : 1;
}
