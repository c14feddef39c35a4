// SPDX-License-Identifier: Apache-2.0
// CV-2D exposes the block structure of CA-2D: kAxisDim,
// axis_transition(), axis_process_noise() and a unit upper triangular F1.
// The filters trust the contract (structure.hpp): jacobian(x, dt) equals
// blkdiag(axis_transition(dt), ...) and process_noise(dt) equals
// blkdiag(axis_process_noise(dt), ...), exactly, for any x and dt; and F1
// is unit upper triangular when kAxisTransitionUnitUpper says so.
#include <catch2/catch.hpp>

#include "kestrel/filters/structure.hpp"
#include "kestrel/models/motion/constant_acceleration_2d.hpp"
#include "kestrel/models/motion/constant_velocity_2d.hpp"

namespace {

/// blkdiag(B, ..., B) over the model's axes.
template <class M>
typename M::Cov block_diagonal(const kestrel::Mat<typename M::Scalar, M::kAxisDim, M::kAxisDim>& B) {
  typename M::Cov out = M::Cov::Zero();
  for (int a = 0; a < M::kStateDim; a += M::kAxisDim) out.template block<M::kAxisDim, M::kAxisDim>(a, a) = B;
  return out;
}

template <class M>
void check_contract(const M& m) {
  using S = typename M::Scalar;
  typename M::State x;
  for (int i = 0; i < M::kStateDim; ++i) x(i) = S(1000) * S(i + 1) - S(2500);
  for (const S dt : {S(0), S(0.25), S(1), S(3.5)}) {
    const auto F1 = m.axis_transition(dt);
    CHECK(m.jacobian(x, dt) == block_diagonal<M>(F1));
    const typename M::State origin = M::State::Zero();
    CHECK(m.jacobian(origin, dt) == block_diagonal<M>(F1));
    CHECK(m.process_noise(dt) == block_diagonal<M>(m.axis_process_noise(dt)));
    // propagate() is the affine map F x (the sigma-point filters' closed
    // form relies on it): exact here, both sides form the same products.
    const typename M::State fx = m.propagate(x, dt);
    const typename M::State Fx = m.jacobian(x, dt) * x;
    for (int i = 0; i < M::kStateDim; ++i) CHECK(double(fx(i)) == Approx(double(Fx(i))).epsilon(1e-12));
    if constexpr (kestrel::UnitUpperAxisTransition<M>) {
      for (int r = 0; r < M::kAxisDim; ++r) {
        CHECK(F1(r, r) == S(1));
        for (int c = 0; c < r; ++c) CHECK(F1(r, c) == S(0));
      }
    }
  }
}

}  // namespace

SCENARIO("CV-2D exposes the block structure of CA-2D", "[structure][cv2d]") {
  STATIC_REQUIRE(kestrel::BlockDiagonalMotion<kestrel::ConstantVelocity2D<double>>);
  STATIC_REQUIRE(kestrel::BlockDiagonalMotion<kestrel::ConstantVelocity2D<float>>);
  STATIC_REQUIRE(kestrel::UnitUpperAxisTransition<kestrel::ConstantVelocity2D<double>>);
  STATIC_REQUIRE(kestrel::UnitUpperAxisTransition<kestrel::ConstantAcceleration2D<double>>);
  STATIC_REQUIRE_FALSE(kestrel::BlockDiagonalMotion<kestrel::Dense<kestrel::ConstantVelocity2D<double>>>);

  GIVEN("CV-2D with sa = 0.7 m/s^2, double and float") {
    kestrel::ConstantVelocity2D<double> d;
    d.sa = 0.7;
    kestrel::ConstantVelocity2D<float> f;
    f.sa = 0.7f;
    THEN("jacobian and process noise are blkdiag of the axis blocks, F1 unit upper") {
      check_contract(d);
      check_contract(f);
    }
  }
  GIVEN("CA-2D with qj = 16 (the same contract)") {
    kestrel::ConstantAcceleration2D<double> m;
    m.qj = 16.0;
    THEN("it holds too") { check_contract(m); }
  }
}
