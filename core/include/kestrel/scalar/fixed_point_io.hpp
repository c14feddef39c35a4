// SPDX-License-Identifier: Apache-2.0
// Host-side stream output of FixedPoint (tests, logs, host_sim): the value
// as a double with enough digits, so Catch2 and Eigen's operator<< can print
// fixed-point scalars and matrices. Never included by core or a board.
#pragma once

#include <ios>
#include <ostream>

#include "kestrel/scalar/fixed_point.hpp"

namespace kestrel::fixed {

template <int F>
std::ostream& operator<<(std::ostream& os, FixedPoint<F> v) {
  if (!v.is_finite()) return os << (v.raw() < 0 ? "-sat" : "+sat");
  const std::streamsize precision = os.precision(17);
  os << static_cast<double>(v);
  os.precision(precision);
  return os;
}

}  // namespace kestrel::fixed
