// SPDX-License-Identifier: Apache-2.0
// FNV-1a hash of everything a CRPF exposes (estimate, covariance, every
// particle, cost and weight) after each step of one MC-001 middle-cell run,
// for the golden-bits test in crpf_test.cpp. The data come from
// sigma_test_support.hpp (std::hypot, std::atan2, std::remainder), so the
// recorded values hold for the host's C library; the filter itself uses
// only the core's deterministic arithmetic.
#pragma once

#include <cstdint>
#include <cstring>

#include "core/filters/sigma_test_support.hpp"
#include "kestrel/filters/crpf.hpp"
#include "kestrel/models/measurement/polar_radar.hpp"
#include "kestrel/models/motion/constant_velocity_2d.hpp"

namespace kestrel::test {

struct Fnv1a {
  std::uint64_t h = 0xcbf29ce484222325ull;
  template <class S>
  void add(S v) {
    unsigned char bytes[sizeof(S)];
    std::memcpy(bytes, &v, sizeof(S));
    for (const unsigned char b : bytes) {
      h ^= b;
      h *= 0x100000001b3ull;
    }
  }
};

/// Hash of a 100-step MC-001 middle-cell run (data seed 1000 + run) of a
/// CRPF over CV-2D in scalar S with kN particles, PMF exponent beta and
/// filter seed `seed`; a step that does not return kOk adds a marker.
template <class S, int kN>
std::uint64_t crpf_trace_hash(std::uint64_t run, std::uint64_t seed, int beta) {
  using M = ConstantVelocity2D<S>;
  using R = PolarRadar<M>;
  using F = Crpf<M, R, kN>;
  constexpr double kDegree = kPi / 180.0;
  NormalGenerator<double> noise(1000 + run);
  const auto truth = mc001_truth(100, 0.1, noise);
  M motion;
  motion.sa = static_cast<S>(0.1);
  R radar;
  radar.sigma_range_m = static_cast<S>(1.0);
  radar.sigma_bearing_rad = static_cast<S>(0.1 * kDegree);
  CrpfConfig<S> params;
  params.seed = seed;
  params.beta = beta;
  params.refuse_indefinite = false;
  F f(motion, radar, params);
  const double sd[4] = {50.0, 5.0, 50.0, 5.0};
  typename F::State x0;
  typename F::Cov P0 = F::Cov::Zero();
  for (int i = 0; i < 4; ++i) {
    x0(i) = static_cast<S>(truth[0](i) + sd[i] * noise());
    P0(i, i) = static_cast<S>(sd[i] * sd[i]);
  }
  Fnv1a hash;
  hash.add(static_cast<int>(f.reset(x0, P0)));
  for (std::size_t k = 1; k <= 100; ++k) {
    const Eigen::Vector2d z = polar_measurement(truth[k](0), truth[k](2), 1.0, 0.1 * kDegree, noise);
    hash.add(static_cast<int>(f.predict(S(1))));
    for (int i = 0; i < 4; ++i) hash.add(f.x()(i));
    hash.add(static_cast<int>(f.update(typename F::MeasVec(static_cast<S>(z(0)), static_cast<S>(z(1))))));
    for (int i = 0; i < 4; ++i) hash.add(f.x()(i));
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 4; ++j) hash.add(f.P()(i, j));
    }
    for (int p = 0; p < kN; ++p) {
      for (int i = 0; i < 4; ++i) hash.add(f.particle(p)(i));
      hash.add(f.cost(p));
      hash.add(f.weight(p));
    }
  }
  return hash.h;
}

}  // namespace kestrel::test
