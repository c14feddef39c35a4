// SPDX-License-Identifier: Apache-2.0
// Robust least-squares multilateration of one TOA frame with a known sound
// speed: how the sonar tracker starts (paper 003; UW-003 in
// docs/scenarios.md). Gauss-Newton on the normalised residuals of the direct
// and the seabed-reflected arrivals, through the same MultipathToa model the
// filter uses (so the reflected paths fix depth), from several starting
// depths, with halved steps, depth clipped to the water, and the largest
// residual over reject_sigma rejected while enough arrivals remain. The
// answer is the start with the most inliers, then the lowest cost;
// kAmbiguous when another start as good lies far away. Every loop is bounded
// by compile-time maxima. Why raw residuals, and the known limits:
// docs/sonar.md, "Initialisation: robust multilateration".
#pragma once

#include <cstdint>

#include "kestrel/filters/channel_gated_ekf.hpp"
#include "kestrel/math/eigen.hpp"
#include "kestrel/math/finite.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"

namespace kestrel {

inline constexpr int kMaxStartDepths = 8;        ///< Capacity of MultilaterationConfig::start_depth_fraction.
inline constexpr int kMaxHorizontalStarts = 5;   ///< Capacity of MultilaterationConfig::horizontal_offset_m.

template <class Scalar>
struct MultilaterationConfig {
  Scalar sound_speed_mps = lit<Scalar>(1500.0);  ///< c used for the fix, m/s.
  /// Starting depths as fractions of the seabed depth D.
  Scalar start_depth_fraction[kMaxStartDepths] = {lit<Scalar>(0.1), lit<Scalar>(0.3), lit<Scalar>(0.5),
                                                  lit<Scalar>(0.7), lit<Scalar>(0.9)};
  std::uint8_t start_depth_count = 5;  ///< Entries used in start_depth_fraction (1..kMaxStartDepths).
  /// Horizontal starting points relative to the beacon centroid, m.
  Scalar horizontal_offset_m[kMaxHorizontalStarts][2] = {};
  std::uint8_t horizontal_start_count = 1;  ///< Entries used in horizontal_offset_m (1..kMaxHorizontalStarts).
  std::uint8_t max_iterations = 30;         ///< Gauss-Newton steps per solve.
  std::uint8_t max_rejections = 4;          ///< Arrivals that may be rejected per start.
  std::uint8_t min_arrivals = 4;            ///< Fewest arrivals (inliers) to attempt a fix.
  Scalar reject_sigma = lit<Scalar>(3.0);   ///< Reject an arrival whose |residual| exceeds this many sigma.
  Scalar converge_step_m = lit<Scalar>(1e-3);      ///< Converged when a step moves less than this, m ...
  Scalar converge_cost_fraction = lit<Scalar>(1e-3);  ///< ... or lowers the cost by less than this fraction.
  Scalar depth_margin_m = lit<Scalar>(0.01);       ///< Depth kept in [m, D - m], m.
  Scalar ambiguity_distance_m = lit<Scalar>(10.0); ///< Solutions closer than this are the same one, m.
  Scalar ambiguity_cost_margin = lit<Scalar>(1.0); ///< Costs (chi-square units) closer than this tie.
};

template <class Scalar>
struct MultilaterationResult {
  Status status = Status::kNotInitialised;  ///< kOk, or why there is no fix.
  Vec<Scalar, 3> position_m = Vec<Scalar, 3>::Zero();         ///< [x, y, depth], m (valid when kOk or kAmbiguous).
  Mat<Scalar, 3, 3> covariance_m2 = Mat<Scalar, 3, 3>::Zero(); ///< (J^T R^-1 J)^-1 over the inliers, m^2.
  ChannelMask inliers = 0;   ///< Channels used in the fix.
  ChannelMask rejected = 0;  ///< Channels rejected as outliers.
  Scalar cost{};             ///< Sum of squared normalised residuals over the inliers.
  Scalar max_abs_residual_sigma{};  ///< Largest |residual| / sigma over the inliers.
  std::uint16_t iterations = 0;     ///< Gauss-Newton steps over all starts and rounds.
};

/// Multilaterate the `present` channels of z (arrival times, s, indexed as
/// in Toa) with the configuration's sound speed.
/// @param toa the MultipathToa model (beacons, seabed depth D, sigma).
/// @return result.status: kOk; kUnderdetermined (fewer than min_arrivals
///         valid arrivals, or D not positive); kNonFinite (a present time is
///         NaN/Inf); kNotPositiveDefinite (the geometry leaves a direction
///         unobserved from every start); kNoConvergence (no start converged
///         to a point that explains its inliers within reject_sigma);
///         kAmbiguous (two distinct points fit equally well; the best is in
///         position_m).
template <class Toa>
MultilaterationResult<typename Toa::Scalar> multilaterate(const Toa& toa, const typename Toa::Measurement& z,
                                                           ChannelMask present,
                                                           const MultilaterationConfig<typename Toa::Scalar>& cfg) {
  using S = typename Toa::Scalar;
  using T = ScalarTraits<S>;
  using P3 = Vec<S, 3>;
  using M3 = Mat<S, 3, 3>;
  constexpr int kN = Toa::kMeasDim;
  constexpr int kMaxHalvings = 12;
  using Result = MultilaterationResult<S>;

  Result best;  // status kNotInitialised until a start succeeds
  ChannelMask valid = 0;
  for (int ch = 0; ch < kN; ++ch) {
    if (!has_channel(present, ch) || !toa.channel_valid(ch)) continue;
    if (!T::is_finite(z(ch))) {
      best.status = Status::kNonFinite;
      return best;
    }
    valid = with_channel(valid, ch);
  }
  const S D = toa.config.seabed_depth_m;
  const S sigma = toa.config.sigma_toa_s;
  const S c = cfg.sound_speed_mps;
  if (channel_count(valid) < static_cast<int>(cfg.min_arrivals) || channel_count(valid) < 3 || !(D > S(0)) ||
      !(sigma > S(0)) || !(c > S(0))) {
    best.status = Status::kUnderdetermined;
    return best;
  }

  // Normalised residual of one channel and its gradient with respect to p.
  const auto residual = [&](const P3& p, int ch, P3* grad) {
    P3 g;
    const S len = toa.path_length(p, ch, &g);
    if (grad != nullptr) *grad = -g / (c * sigma);
    return (z(ch) - len / c) / sigma;
  };
  const auto cost_of = [&](const P3& p, ChannelMask inl) {
    S sum = S(0);
    for (int ch = 0; ch < kN; ++ch) {
      if (!has_channel(inl, ch)) continue;
      const S r = residual(p, ch, nullptr);
      sum += r * r;
    }
    return sum;
  };
  const S z_lo = cfg.depth_margin_m;
  const S z_hi = D - cfg.depth_margin_m;
  const auto clip = [&](P3 p) {
    if (!(p(2) >= z_lo)) p(2) = z_lo;  // also catches NaN
    if (p(2) > z_hi) p(2) = z_hi;
    return p;
  };
  // Normal matrix J^T J (normalised J) over the inliers.
  const auto normal = [&](const P3& p, ChannelMask inl, P3* rhs) {
    M3 N = M3::Zero();
    P3 b = P3::Zero();
    for (int ch = 0; ch < kN; ++ch) {
      if (!has_channel(inl, ch)) continue;
      P3 g;
      const S r = residual(p, ch, &g);
      N += g * g.transpose();
      b += g * r;
    }
    if (rhs != nullptr) *rhs = b;
    return N;
  };

  P3 centroid = P3::Zero();
  for (int i = 0; i < Toa::kBeacons; ++i) {
    if (i >= static_cast<int>(toa.config.beacon_count)) break;
    centroid += toa.config.beacons_m[i];
  }
  centroid /= T::from_ratio(static_cast<std::int64_t>(toa.config.beacon_count), 1);

  // Every converged start, compactly, for the ambiguity test; the best in full.
  struct Candidate {
    P3 position;
    S cost;
    int inliers;
  };
  constexpr int kMaxStarts = kMaxStartDepths * kMaxHorizontalStarts;
  Candidate candidates[kMaxStarts];
  int candidate_count = 0;
  bool any_singular = false;
  std::uint16_t total_iterations = 0;
  const int depth_starts = cfg.start_depth_count < 1 ? 1
                           : (cfg.start_depth_count > kMaxStartDepths ? kMaxStartDepths : cfg.start_depth_count);
  const int horiz_starts = cfg.horizontal_start_count < 1
                               ? 1
                               : (cfg.horizontal_start_count > kMaxHorizontalStarts ? kMaxHorizontalStarts
                                                                                    : cfg.horizontal_start_count);
  for (int hs = 0; hs < horiz_starts; ++hs) {
    for (int ds = 0; ds < depth_starts; ++ds) {
      Result run;
      P3 p = clip(P3(centroid(0) + cfg.horizontal_offset_m[hs][0], centroid(1) + cfg.horizontal_offset_m[hs][1],
                     cfg.start_depth_fraction[ds] * D));
      ChannelMask inl = valid;
      bool converged = false;
      bool singular = false;
      for (int round = 0; round <= static_cast<int>(cfg.max_rejections); ++round) {
        // 1. Gauss-Newton with step halving.
        converged = false;
        S cost = cost_of(p, inl);
        for (int it = 0; it < static_cast<int>(cfg.max_iterations); ++it) {
          ++run.iterations;
          P3 b;
          const M3 N = normal(p, inl, &b);
          const Eigen::LLT<M3> llt(N);
          if (llt.info() != Eigen::Success || !all_finite(N)) {
            singular = true;
            break;
          }
          // r(p + dp) ~ r + J dp with J = grad: minimise |r + J dp|^2.
          const P3 dp = llt.solve(-b);
          S scale = S(1);
          P3 next = p;
          S next_cost = cost;
          bool improved = false;
          for (int h = 0; h < kMaxHalvings; ++h) {
            next = clip(p + dp * scale);
            next_cost = cost_of(next, inl);
            if (T::is_finite(next_cost) && next_cost <= cost) {
              improved = true;
              break;
            }
            scale = scale * S(0.5);
          }
          if (!improved) {  // no descent along the GN direction: stationary
            converged = true;
            break;
          }
          const S moved = T::sqrt((next - p).squaredNorm());
          const S dropped = cost - next_cost;
          p = next;
          cost = next_cost;
          // A large-residual problem (an outlier still in) creeps along a
          // flat valley: stop once the cost hardly moves, so the rejection
          // below can act, and continue from there.
          if (moved < cfg.converge_step_m || dropped <= cfg.converge_cost_fraction * cost) {
            converged = true;
            break;
          }
        }
        if (singular || !converged) break;
        // 2. Reject the worst arrival if it is beyond reject_sigma.
        int worst = -1;
        S worst_abs = S(0);
        for (int ch = 0; ch < kN; ++ch) {
          if (!has_channel(inl, ch)) continue;
          const S a = T::abs(residual(p, ch, nullptr));
          if (worst < 0 || a > worst_abs) {
            worst = ch;
            worst_abs = a;
          }
        }
        run.cost = cost;
        run.max_abs_residual_sigma = worst_abs;
        if (worst_abs <= cfg.reject_sigma) break;
        if (round == static_cast<int>(cfg.max_rejections) ||
            channel_count(inl) - 1 < static_cast<int>(cfg.min_arrivals)) {
          converged = false;  // cannot explain the data within reject_sigma
          break;
        }
        inl = without_channel(inl, worst);
      }
      total_iterations = static_cast<std::uint16_t>(total_iterations + run.iterations);
      if (singular) {
        any_singular = true;
        continue;
      }
      if (!converged) continue;
      const M3 N = normal(p, inl, nullptr);
      const Eigen::LLT<M3> llt(N);
      if (llt.info() != Eigen::Success) {
        any_singular = true;
        continue;
      }
      run.status = Status::kOk;
      run.position_m = p;
      // N^-1 column by column (a matrix right-hand side would use Eigen's
      // blocked solver, which references malloc).
      M3 N_inv;
      for (int j = 0; j < 3; ++j) N_inv.col(j) = llt.solve(M3::Identity().col(j));
      run.covariance_m2 = symmetrised(N_inv);
      run.inliers = inl;
      run.rejected = valid & ~inl;
      const int n_run = channel_count(inl);
      candidates[candidate_count++] = Candidate{p, run.cost, n_run};
      const int n_best = channel_count(best.inliers);
      if (best.status != Status::kOk || n_run > n_best || (n_run == n_best && run.cost < best.cost)) best = run;
    }
  }

  best.iterations = total_iterations;
  if (best.status != Status::kOk) {
    best.status = any_singular ? Status::kNotPositiveDefinite : Status::kNoConvergence;
    return best;
  }
  const int n_best = channel_count(best.inliers);
  for (int i = 0; i < kMaxStarts; ++i) {
    if (i >= candidate_count) break;
    if (candidates[i].inliers != n_best) continue;
    const S dist = T::sqrt((candidates[i].position - best.position_m).squaredNorm());
    if (dist > cfg.ambiguity_distance_m && candidates[i].cost - best.cost < cfg.ambiguity_cost_margin) {
      best.status = Status::kAmbiguous;
      break;
    }
  }
  return best;
}

}  // namespace kestrel
