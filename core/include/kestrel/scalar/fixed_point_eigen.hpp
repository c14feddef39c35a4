// SPDX-License-Identifier: Apache-2.0
// FixedPoint as an Eigen scalar, following Eigen's custom-scalar recipe
// (doc/CustomizingEigen_CustomScalar.dox): a NumTraits specialisation plus
// the math functions Eigen calls unqualified (abs, sqrt, isfinite, ... found
// by argument-dependent lookup in kestrel::fixed, fixed_point_math.hpp). No
// packet (SIMD) traits: Eigen falls back to scalar loops. Include this
// header (it brings the type, its math and ScalarTraits) before using a
// fixed-point scalar with any model or filter.
//
// Summation order inside Eigen's products does not matter for the result:
// each product is rounded once and the additions are exact integer
// additions (unless one saturates, which makes the result non-finite).
#pragma once

#include <cstdint>

#include "kestrel/math/eigen.hpp"
#include "kestrel/scalar/fixed_point.hpp"
#include "kestrel/scalar/fixed_point_math.hpp"

namespace Eigen {

template <int F>
struct NumTraits<kestrel::FixedPoint<F>> : GenericNumTraits<kestrel::FixedPoint<F>> {
  using Q = kestrel::FixedPoint<F>;
  using Real = Q;
  using NonInteger = Q;
  using Literal = Q;
  using Nested = Q;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = 1,
    AddCost = 2,
    MulCost = 8,  // a 64 x 64 -> 128-bit product from 32-bit pieces
  };
  /// One unit in the last place.
  static constexpr Q epsilon() { return Q::from_raw(1); }
  /// Tolerance of Eigen's isApprox/isMuchSmallerThan: 2^-(F/2).
  static constexpr Q dummy_precision() { return Q::from_raw(std::int64_t{1} << (F - F / 2)); }
  static constexpr Q highest() { return Q::from_raw(kestrel::fixed::detail::kMaxFinite); }
  static constexpr Q lowest() { return Q::from_raw(-kestrel::fixed::detail::kMaxFinite); }
  static constexpr int digits() { return 63; }
  static constexpr int digits10() { return 18; }
  static constexpr int max_digits10() { return 20; }
};

}  // namespace Eigen
