// SPDX-License-Identifier: Apache-2.0
// Ignoring a Status is an error under the firmware flags ([[nodiscard]] with
// -Werror): a dropped predict() result must not compile.
#include "kestrel/filters/ekf.hpp"
#include "kestrel/models/measurement/polar_radar.hpp"
#include "kestrel/models/motion/constant_acceleration_2d.hpp"

extern "C" void kestrel_assert_failed(const char*, int, const char*) { __builtin_trap(); }

using Motion = kestrel::ConstantAcceleration2D<double>;

int main() {
  kestrel::Ekf<Motion, kestrel::PolarRadar<Motion>> ekf;
#ifdef KESTREL_SHOULD_FAIL
  ekf.predict(0.5);
#else
  const kestrel::Status s = ekf.predict(0.5);
  if (s != kestrel::Status::kOk) return 1;
#endif
  return 0;
}
