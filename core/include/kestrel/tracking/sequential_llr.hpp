// SPDX-License-Identifier: Apache-2.0
// Score-based track management: the sequential log-likelihood ratio of
// "target" against "clutter" (Blackman and Popoli, Design and Analysis of
// Modern Tracking Systems, 1999, section 6.2), tested sequentially (Wald).
// A track starts at the prior odds ln(beta_NT / beta_FA), gains
// ln(P_D / beta_FA) - (m/2) ln(2 pi) - ln|S| / 2 - d2 / 2 per hit and
// ln(1 - P_D P_G) per miss; the thresholds follow from the chosen
// probabilities of confirming a false track and of dropping a true one.
// Unlike M-of-N it weighs how well each plot fits and how dense the clutter
// is, so one threshold pair holds from a clean scene to a dense one.
// Floating-point scalars only (a log per hit). The tests and why the
// tentative one ignores the prior: docs/tracking.md, "The track score".
#pragma once

#include <cstdint>

#include "kestrel/association/chi_square.hpp"
#include "kestrel/math/log_det.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/tracking/track.hpp"

namespace kestrel {

/// Parameters of SequentialLlr (probabilities, and densities per unit of
/// measurement volume).
struct SequentialLlrParams {
  double detection_probability = 0.9;         ///< P_D.
  double clutter_density = 1.0e-6;            ///< beta_FA, false plots per unit measurement volume and frame.
  double new_target_density = 1.0e-7;         ///< beta_NT, new targets per unit measurement volume and frame.
  double false_track_probability = 1.0e-4;    ///< alpha: a clutter track confirmed.
  double missed_track_probability = 0.05;     ///< beta: a true track deleted before confirmation.
};

template <class Scalar>
class SequentialLlr {
  using T = ScalarTraits<Scalar>;
  static_assert(!T::kIsFixedPoint, "the track score needs a logarithm per hit: float or double");

 public:
  /// hit() scores the innovation (the tracker computes one for the pairing plot too).
  static constexpr bool kScoresInnovations = true;

  SequentialLlr() : SequentialLlr(SequentialLlrParams{}) {}
  explicit SequentialLlr(const SequentialLlrParams& p) : params_(p) {}

  template <class Config>
  void configure(const Config& c) {
    const double pd = params_.detection_probability;
    const double alpha = params_.false_track_probability;
    const double beta = params_.missed_track_probability;
    start_ = T::from_double(std::log(params_.new_target_density / params_.clutter_density));
    hit_ = T::from_double(std::log(pd / params_.clutter_density) -
                          0.5 * static_cast<double>(c.z_min.size()) * std::log(2.0 * 3.14159265358979323846));
    miss_confirmed_ = T::from_double(std::log(1.0 - pd * gate_probability(c.gate_confirmed)));
    miss_tentative_ = T::from_double(std::log(1.0 - pd * gate_probability(c.gate_tentative)));
    confirm_ = T::from_double(std::log((1.0 - beta) / alpha));
    delete_ = T::from_double(std::log(beta / (1.0 - alpha)));
  }

  const SequentialLlrParams& params() const { return params_; }
  Scalar confirm_threshold() const { return confirm_; }
  Scalar delete_threshold() const { return delete_; }

  template <class TrackT>
  void start(TrackT& tr) const {
    tr.score = start_;
    tr.score_peak = start_;
  }

  template <class TrackT, class Innov>
  void hit(TrackT& tr, const Innov& in) const {
    Scalar ln_det{};
    // An S that is not positive definite cannot come from a filter that
    // accepted the plot; score it as a miss rather than take its log.
    tr.score += log_det_spd(in.S, ln_det) ? hit_ - Scalar(0.5) * ln_det - Scalar(0.5) * in.d2 : miss_tentative_;
    if (tr.score > tr.score_peak) tr.score_peak = tr.score;
  }

  /// A probabilistic (PDA) update with weight beta_none for "no plot is the
  /// target's": the likelihood ratio of the whole gate,
  /// 1 - P_D P_G + (P_D / beta_FA) sum_j N(nu_j; 0, S), is (1 - P_D P_G) / beta_none
  /// under the same P_D, P_G and clutter density (association/pda.hpp).
  template <class TrackT>
  void hit_weighted(TrackT& tr, Scalar beta_none) const {
    const Scalar miss = tr.status == TrackStatus::kConfirmed ? miss_confirmed_ : miss_tentative_;
    // beta_none > 0 always (b > 0); the floor only keeps the log finite.
    const Scalar kFloor = T::from_double(1e-30);
    tr.score += miss - T::log(beta_none > kFloor ? beta_none : kFloor);
    if (tr.score > tr.score_peak) tr.score_peak = tr.score;
  }

  template <class TrackT>
  TrackVerdict judge(TrackT& tr, bool hit) const {
    const bool confirmed = tr.status == TrackStatus::kConfirmed;
    if (!hit) tr.score += confirmed ? miss_confirmed_ : miss_tentative_;
    if (!confirmed) {
      if (tr.score >= confirm_) return TrackVerdict::kConfirm;
      return tr.score - tr.score_peak <= delete_ ? TrackVerdict::kDelete : TrackVerdict::kKeep;
    }
    return tr.score_peak - tr.score >= confirm_ - delete_ ? TrackVerdict::kDelete : TrackVerdict::kKeep;
  }

 private:
  SequentialLlrParams params_;
  Scalar start_{};
  Scalar hit_{};
  Scalar miss_confirmed_{};
  Scalar miss_tentative_{};
  Scalar confirm_{};
  Scalar delete_{};
};

}  // namespace kestrel
