// SPDX-License-Identifier: Apache-2.0
// Seeded pseudo-random numbers for core (the CRPF's initial cloud, particle
// kicks and resampling offsets): no heap, no global state, a constant bound
// on every loop, and the same bits on every IEEE platform for the same seed,
// so a CRPF run replays identically on a board and on the host.
// Xoshiro256StarStar is Blackman and Vigna's xoshiro256** 1.0 (2018), seeded
// through SplitMix64; uniform01<F>() scales the top 53 or 24 bits by an exact
// power of two; NormalGenerator<F> is the 128-layer ziggurat of Marsaglia and
// Tsang (2000) in Doornik's ZIGNOR form (2005), its table generated into
// ziggurat_tables.hpp and its rare exp/log from math/exp_log.hpp, not libm.
// Every rejection loop is bounded (kMaxTries). Details: docs/filters.md,
// "Choices beyond the paper", "Core PRNG".
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

#include "kestrel/math/exp_log.hpp"
#include "kestrel/math/ziggurat_tables.hpp"

namespace kestrel {

/// SplitMix64 (Steele, Lea, Flood 2014): expands one seed into a state.
constexpr std::uint64_t splitmix64(std::uint64_t& x) {
  x += 0x9E3779B97F4A7C15ull;
  std::uint64_t z = x;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

/// xoshiro256** 1.0: 256-bit state, period 2^256 - 1.
class Xoshiro256StarStar {
 public:
  constexpr explicit Xoshiro256StarStar(std::uint64_t seed = 0) { this->seed(seed); }

  /// Restart the stream from a 64-bit seed (any value, 0 included).
  constexpr void seed(std::uint64_t seed) {
    std::uint64_t x = seed;
    for (auto& w : s_) w = splitmix64(x);
  }

  /// Next 64 random bits.
  constexpr std::uint64_t next() {
    const std::uint64_t result = rotl(s_[1] * 5u, 7) * 9u;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }

  /// Uniform in [0, 1) with the scalar's full mantissa.
  template <class F>
  F uniform01() {
    if constexpr (sizeof(F) >= 8) {
      return static_cast<F>(next() >> 11) * static_cast<F>(0x1.0p-53);
    } else {
      return static_cast<F>(static_cast<std::uint32_t>(next() >> 40)) * static_cast<F>(0x1.0p-24f);
    }
  }

  constexpr bool operator==(const Xoshiro256StarStar&) const = default;

 private:
  static constexpr std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::uint64_t s_[4] = {};
};


/// Standard normal deviates N(0, 1) in scalar F (double or float) from a
/// Xoshiro256StarStar stream: one 64-bit draw per deviate in the common case.
template <class F>
class NormalGenerator {
 public:
  static constexpr int kMaxTries = 64;

  constexpr explicit NormalGenerator(std::uint64_t seed = 0) : rng_(seed) {}

  /// Restart the stream.
  constexpr void seed(std::uint64_t seed) { rng_.seed(seed); }

  /// One N(0, 1) deviate (ZIGNOR). The first try's rectangle test, which
  /// accepts about 98.8 % of the draws, is inline; the rest of that try
  /// (wedge or tail) and any further tries are out of line in slow(), so a
  /// caller's loop is not burdened with the rare path's registers and calls.
  /// The draws and operations are the same either way, hence the same bits.
  F operator()() {
    const std::uint64_t bits = rng_.next();
    const int i = static_cast<int>(bits & 0x7Fu);  // layer: low 7 bits
    const F u = F(2) * top_bits_uniform(bits) - F(1);  // [-1, 1): the top bits
    // Inside the layer's rectangle under the next layer: accept at once.
    if ((u < F(0) ? -u : u) < static_cast<F>(detail::kZigguratRatio[i])) [[likely]] {
      return u * static_cast<F>(detail::kZigguratX[i]);
    }
    return slow(i, u);
  }

  /// Uniform in [0, 1) from the same stream (resampling offsets).
  F uniform01() { return rng_.template uniform01<F>(); }

  Xoshiro256StarStar& engine() { return rng_; }

 private:
  /// The uniform of uniform01<F>() from an already drawn 64-bit value.
  static F top_bits_uniform(std::uint64_t bits) {
    if constexpr (sizeof(F) >= 8) {
      return static_cast<F>(bits >> 11) * static_cast<F>(0x1.0p-53);
    } else {
      return static_cast<F>(static_cast<std::uint32_t>(bits >> 40)) * static_cast<F>(0x1.0p-24f);
    }
  }

  /// The first try after its rectangle test failed (layer i, uniform u),
  /// then tries 2..kMaxTries in full.
  [[gnu::noinline]] F slow(int i, F u) {
    using detail::kZigguratRatio;
    using detail::kZigguratX;
    for (int t = 0; t < kMaxTries; ++t) {
      if (t > 0) {
        const std::uint64_t bits = rng_.next();
        i = static_cast<int>(bits & 0x7Fu);
        u = F(2) * top_bits_uniform(bits) - F(1);
        if ((u < F(0) ? -u : u) < static_cast<F>(kZigguratRatio[i])) return u * static_cast<F>(kZigguratX[i]);
      }
      if (i == 0) return tail(u < F(0));
      // A wedge: accept x with probability (f(x) - f(X[i])) / (f(X[i+1]) - f(X[i])).
      const F xi = static_cast<F>(kZigguratX[i]);
      const F x = u * xi;
      const F xn = static_cast<F>(kZigguratX[i + 1]);
      const F f0 = detail::deterministic_exp(F(-0.5) * (xi * xi - x * x));
      const F f1 = detail::deterministic_exp(F(-0.5) * (xn * xn - x * x));
      if (f1 + rng_.template uniform01<F>() * (f0 - f1) < F(1)) return x;
    }
    return F(0);
  }

  /// Marsaglia's tail beyond R (Doornik 2005): x = -ln(U1)/R, y = -ln(U2),
  /// accept when 2y > x^2; U in (0, 1].
  F tail(bool negative) {
    const F r = static_cast<F>(detail::kZigguratR);
    for (int t = 0; t < kMaxTries; ++t) {
      const F x = detail::deterministic_log(F(1) - rng_.template uniform01<F>()) / r;
      const F y = detail::deterministic_log(F(1) - rng_.template uniform01<F>());
      if (!(F(-2) * y < x * x)) return negative ? x - r : r - x;
    }
    return negative ? -r : r;
  }

  Xoshiro256StarStar rng_;
};

}  // namespace kestrel
