// SPDX-License-Identifier: Apache-2.0
// The simulator's random numbers. Reproducible bit for bit (docs/scenarios.md)
// on every standard library: std::mt19937_64's output sequence is fixed by
// the C++ standard, but std::normal_distribution and
// std::uniform_real_distribution are not (libstdc++ and libc++ differ), so
// the conversions to uniform and Gaussian variates are written here.
#pragma once

#include <cstddef>
#include <cstdint>
#include <random>

namespace kestrel::sim {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}

  /// Uniform on [0, 1) with 53 random bits.
  double uniform();
  /// Uniform on [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// Standard normal, Box-Muller (one variate per two uniforms, no caching,
  /// so a draw's value depends only on how many draws came before).
  double normal();
  /// Normal with the given standard deviation.
  double normal(double sigma) { return sigma * normal(); }
  /// Poisson with the given mean, Knuth's product of uniforms (one uniform
  /// per count plus one; exact for the means of clutter counts, up to a few
  /// hundred, where exp(-mean) is still a normal double).
  std::size_t poisson(double mean);

 private:
  std::mt19937_64 engine_;
};

}  // namespace kestrel::sim
