// SPDX-License-Identifier: Apache-2.0
// Float EKF-CA/polar against a double reference over a long run: how far x
// and P drift, and whether P stays positive definite. Used to choose the
// structured EKF's covariance update (docs/performance.md, "Update form"):
// build it once against this tree (P - U U^T) and once against the
// expanded Joseph form of commit 812f870, then compare:
//
//   g++ -std=c++20 -O2 -Icore/include -I/usr/include/eigen3 tools/experiments/float_update_forms.cpp -o /tmp/new_form
//   git worktree add /tmp/k812 812f870
//   g++ -std=c++20 -O2 -I/tmp/k812/core/include -I/usr/include/eigen3 tools/experiments/float_update_forms.cpp -o /tmp/old_form
//   /tmp/new_form SR_M SB_RAD QJ STEPS      (e.g. 0.1 0.0001745 0.001 20000)
//
// Not part of the build: a one-off measurement kept so the figures in the
// docs can be re-run.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "kestrel/filters/ekf.hpp"
#include "kestrel/models/measurement/polar_radar.hpp"
#include "kestrel/models/motion/constant_acceleration_2d.hpp"

extern "C" void kestrel_assert_failed(const char* file, int line, const char* expr) {
  std::fprintf(stderr, "assertion failed: %s:%d: %s\n", file, line, expr);
  std::abort();
}

namespace {

using kestrel::Status;
template <class S>
using Ca = kestrel::ConstantAcceleration2D<S>;
template <class S>
using EkfCa = kestrel::Ekf<Ca<S>, kestrel::PolarRadar<Ca<S>>>;

template <class S>
EkfCa<S> make(double sr, double sb, double qj) {
  Ca<S> m;
  m.qj = static_cast<S>(qj);
  kestrel::PolarRadar<Ca<S>> h;
  h.sigma_range_m = static_cast<S>(sr);
  h.sigma_bearing_rad = static_cast<S>(sb);
  return EkfCa<S>(m, h);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: %s SR_M SB_RAD QJ STEPS\n", argv[0]);
    return 2;
  }
  const double sr = std::atof(argv[1]), sb = std::atof(argv[2]), qj = std::atof(argv[3]);
  const int steps = std::atoi(argv[4]);
  const double dt = 0.5;
  auto fd = make<double>(sr, sb, qj);
  auto ff = make<float>(sr, sb, qj);
  kestrel::Vec<double, 6> x0;
  x0 << 20000, 150, 0, 10000, -80, 0;
  kestrel::Mat<double, 6, 6> P0 = kestrel::Mat<double, 6, 6>::Zero();
  P0.diagonal() << 100, 400, 25, 100, 400, 25;
  if (fd.reset(x0, P0) != Status::kOk || ff.reset(x0.cast<float>(), P0.cast<float>()) != Status::kOk) return 1;

  std::mt19937_64 rng(7);
  std::normal_distribution<double> n01;
  kestrel::Vec<double, 6> xt = x0;
  double worst_sd = 0, worst_x = 0, worst_corr = 0;
  int not_pd = 0, fails = 0;
  for (int k = 0; k < steps; ++k) {
    // Truth: constant acceleration, the acceleration turning slowly.
    const double ax = 3 * std::sin(k * 0.01), ay = 3 * std::cos(k * 0.013);
    xt(2) = ax;
    xt(5) = ay;
    xt(0) += xt(1) * dt + 0.5 * ax * dt * dt;
    xt(1) += ax * dt;
    xt(3) += xt(4) * dt + 0.5 * ay * dt * dt;
    xt(4) += ay * dt;
    const double range = std::hypot(xt(0), xt(3)) + sr * n01(rng);  // draws in a fixed order
    const double bearing = std::atan2(xt(3), xt(0)) + sb * n01(rng);
    const kestrel::Vec<double, 2> z(range, bearing);
    if (fd.predict(dt) != Status::kOk || fd.update(z) != Status::kOk) {
      std::printf("double reference failed at step %d\n", k);
      return 1;
    }
    if (ff.predict(float(dt)) != Status::kOk || ff.update(z.cast<float>()) != Status::kOk) {
      ++fails;
      continue;
    }
    const auto& Pd = fd.P();
    const kestrel::Mat<double, 6, 6> Pf = ff.P().cast<double>();
    if (Eigen::LLT<kestrel::Mat<double, 6, 6>>(Pf).info() != Eigen::Success) ++not_pd;
    for (int i = 0; i < 6; ++i) {
      worst_sd = std::max(worst_sd, std::abs(std::sqrt(std::abs(Pf(i, i))) / std::sqrt(Pd(i, i)) - 1));
      worst_x = std::max(worst_x, std::abs(ff.x()(i) - fd.x()(i)) / std::sqrt(Pd(i, i)));
      for (int j = 0; j < i; ++j) {
        worst_corr = std::max(worst_corr, std::abs(Pf(i, j) / std::sqrt(Pf(i, i) * Pf(j, j)) -
                                                   Pd(i, j) / std::sqrt(Pd(i, i) * Pd(j, j))));
      }
    }
  }
  std::printf(
      "sr %g sb %g qj %g steps %d: float fails %d, float P not PD %d, worst |sd_f/sd_d-1| %.3g, "
      "worst |dx|/sd %.3g, worst corr diff %.3g\n",
      sr, sb, qj, steps, fails, not_pd, worst_sd, worst_x, worst_corr);
  return 0;
}
