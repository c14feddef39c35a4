// SPDX-License-Identifier: Apache-2.0
// A measurement model without residual() (which owns angle wrapping) must
// not be accepted by a filter.
#include "kestrel/filters/ekf.hpp"
#include "kestrel/models/motion/constant_acceleration_2d.hpp"

extern "C" void kestrel_assert_failed(const char*, int, const char*) { __builtin_trap(); }

using Motion = kestrel::ConstantAcceleration2D<double>;

struct PositionSensor {
  using Scalar = double;
  static constexpr int kStateDim = 6;
  static constexpr int kMeasDim = 2;
  using Measurement = kestrel::Vec<double, 2>;
  using Jacobian = kestrel::Mat<double, 2, 6>;
  using NoiseCov = kestrel::Mat<double, 2, 2>;
  Measurement predict(const Motion::State& x) const { return Measurement(x(0), x(3)); }
  Jacobian jacobian(const Motion::State&) const { return Jacobian::Zero(); }
  NoiseCov noise() const { return NoiseCov::Identity(); }
#ifndef KESTREL_SHOULD_FAIL
  Measurement residual(const Measurement& z, const Measurement& zh) const { return z - zh; }
#endif
};

int main() {
  kestrel::Ekf<Motion, PositionSensor> ekf;
  return ekf.x().size() == 6 ? 0 : 1;
}
