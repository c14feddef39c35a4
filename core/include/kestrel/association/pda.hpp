// SPDX-License-Identifier: Apache-2.0
// Probabilistic data association (PDA) for a target in dense clutter
// (Bar-Shalom and Tse, 1975; Bar-Shalom, Willett and Tian, Tracking and
// Data Fusion, 2011, section 3.4): instead of betting on one plot, a track
// is updated with every free plot in its gate, each weighted by the
// probability that it is the target's,
//   beta_j    = e_j / (b + sum e),   e_j = exp(-d2_j / 2),
//   beta_none = b / (b + sum e),     b = lambda (2 pi)^(m/2) |S|^(1/2) (1 - P_D P_G) / P_D,
// lambda the clutter density (false plots per unit measurement volume and
// frame; 0: estimated from the plots in the gate, the non-parametric PDA,
// lambda = n / V_gate). The filter does the update (Ekf::update_pda).
//
// Each track is treated as alone: the plots in its gate are taken by it
// (they start no track) and are not offered to later tracks. That is the
// single-target PDA; targets closer than a gate need joint association
// (JPDA), which this is not.
#pragma once

#include <cstddef>

#include "kestrel/math/log_det.hpp"
#include "kestrel/scalar/scalar_traits.hpp"

namespace kestrel {

/// Parameters of ProbabilisticDataAssociation.
struct PdaParams {
  double detection_probability = 0.9;  ///< P_D.
  double clutter_density = 0.0;        ///< lambda per unit measurement volume and frame; 0: from the gate.
};

template <class Scalar, std::size_t kMaxTracks, std::size_t kMaxMeasurements>
class ProbabilisticDataAssociation {
  using T = ScalarTraits<Scalar>;
  static_assert(!T::kIsFixedPoint, "the association weights need exp and log: float or double");

 public:
  using Params = PdaParams;
  ProbabilisticDataAssociation() : ProbabilisticDataAssociation(PdaParams{}) {}
  explicit ProbabilisticDataAssociation(const PdaParams& p) : params_(p) {}
  const PdaParams& params() const { return params_; }

  template <class Candidates>
  void associate(Candidates& c) {
    constexpr double kTwoPi = 2.0 * 3.14159265358979323846;
    const double pd = params_.detection_probability;
    const Scalar log_two_pi = T::from_double(std::log(kTwoPi));
    const Scalar half_m = Scalar(0.5) * static_cast<Scalar>(Candidates::Innov::kDim);
    const double pg = static_cast<double>(c.gate_probability());
    const Scalar log_miss_odds = T::from_double(std::log((1.0 - pd * pg) / pd));
    for (std::size_t k = 0; k < kMaxTracks; ++k) {
      if (k >= c.tracks()) break;
      const auto track = c.track(k);
      std::size_t n = 0;
      Scalar d2[kMaxMeasurements] = {};
      for (std::size_t j = 0; j < kMaxMeasurements; ++j) {
        if (j >= c.measurements()) break;
        if (!c.free(j)) continue;
        const auto d = c.distance(track, j);
        if (!c.gated(d)) continue;
        index_[n] = j;
        d2[n] = d.d2;
        ++n;
      }
      if (n == 0) continue;
      Scalar ln_det{};
      if (!log_det_spd(c.innovation(k, index_[0]).S, ln_det)) continue;  // S: the same for every plot of the track
      // ln b; the weights are normalised in the log domain (largest term 0).
      Scalar log_lambda;
      if (params_.clutter_density > 0.0) {
        log_lambda = T::from_double(std::log(params_.clutter_density));
      } else {
        // V_gate = c_m gamma^(m/2) |S|^(1/2); for m = 2, c_m = pi.
        const Scalar log_volume = T::from_double(std::log(unit_ball_volume(Candidates::Innov::kDim))) +
                                  half_m * T::log(c.gate_threshold()) + Scalar(0.5) * ln_det;
        log_lambda = T::log(static_cast<Scalar>(n)) - log_volume;
      }
      const Scalar log_b = log_lambda + half_m * log_two_pi + Scalar(0.5) * ln_det + log_miss_odds;
      Scalar top = log_b;
      for (std::size_t i = 0; i < kMaxMeasurements; ++i) {
        if (i >= n) break;
        if (-Scalar(0.5) * d2[i] > top) top = -Scalar(0.5) * d2[i];
      }
      Scalar sum = T::exp(log_b - top);
      for (std::size_t i = 0; i < kMaxMeasurements; ++i) {
        if (i >= n) break;
        beta_[i] = T::exp(-Scalar(0.5) * d2[i] - top);
        sum += beta_[i];
      }
      for (std::size_t i = 0; i < kMaxMeasurements; ++i) {
        if (i >= n) break;
        beta_[i] /= sum;
      }
      c.assign_weighted(k, index_, beta_, n, T::exp(log_b - top) / sum);
    }
  }

 private:
  /// Volume of the unit ball in m dimensions (m <= 16).
  static double unit_ball_volume(int m) {
    constexpr double kPi = 3.14159265358979323846;
    double v = 1.0;  // m = 0
    double prev = 2.0;  // m = 1
    if (m == 1) return 2.0;
    for (int d = 2; d <= 16; ++d) {  // V_d = 2 pi / d * V_(d-2)
      const double next = 2.0 * kPi / d * v;
      v = prev;
      prev = next;
      if (d == m) return next;
    }
    return prev;
  }

  PdaParams params_;
  std::size_t index_[kMaxMeasurements] = {};
  Scalar beta_[kMaxMeasurements] = {};
};

}  // namespace kestrel
