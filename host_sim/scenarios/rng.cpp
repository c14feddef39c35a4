// SPDX-License-Identifier: Apache-2.0
#include "scenarios/rng.hpp"

#include <cmath>
#include <numbers>

namespace kestrel::sim {

double Rng::uniform() {
  // Top 53 bits of a 64-bit draw, scaled by 2^-53: exact and in [0, 1).
  return static_cast<double>(engine_() >> 11) * 0x1.0p-53;
}

double Rng::normal() {
  // 1 - u is in (0, 1], so the log is finite.
  const double u1 = 1.0 - uniform();
  const double u2 = uniform();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

std::size_t Rng::poisson(double mean) {
  const double limit = std::exp(-mean);
  double p = 1.0;
  std::size_t k = 0;
  for (;;) {
    p *= uniform();
    if (p <= limit) return k;
    ++k;
  }
}

}  // namespace kestrel::sim
