// SPDX-License-Identifier: Apache-2.0
// Interacting multiple model filter (Blom and Bar-Shalom 1988; Bar-Shalom,
// Li, Kirubarajan 2001, section 11.6.6, its five steps: mixing
// probabilities, mixing, mode-matched filtering, mode probability update,
// combination) over a fixed set of mode filters, each an existing filter
// (Ekf on CV-2D, CA-2D, CT-2D, ...) with its own state. Modes are mixed in
// one common state [x vx ax y vy ay w] by their layouts' names, with padding
// variances for missing components; the tracker sees the combination
// projected onto the Output model's state, and the gate the moment-matched
// Gaussian. predict() mixes and predicts with the switching matrix scaled to
// dt by mean sojourn times; update() filters and updates the mode
// probabilities. Likelihoods are combined in logs; commit on success
// (kNonFinite, kNotPositiveDefinite, kOutOfRange). Details and why:
// docs/imm.md, "The IMM cycle" and its subsections.
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include "kestrel/filters/ekf.hpp"
#include "kestrel/filters/innovation.hpp"
#include "kestrel/math/eigen.hpp"
#include "kestrel/math/finite.hpp"
#include "kestrel/math/log_det.hpp"
#include "kestrel/math/positive_definite.hpp"
#include "kestrel/models/concepts.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"

namespace kestrel {

/// The state every mode is lifted into for mixing and combination.
struct ImmCommonLayout {
  static constexpr int kX = 0;   ///< x position, m
  static constexpr int kVx = 1;  ///< x velocity, m/s
  static constexpr int kAx = 2;  ///< x acceleration, m/s^2
  static constexpr int kY = 3;   ///< y position, m
  static constexpr int kVy = 4;  ///< y velocity, m/s
  static constexpr int kAy = 5;  ///< y acceleration, m/s^2
  static constexpr int kW = 6;   ///< turn rate, rad/s
  static constexpr int kDim = 7;
};

namespace imm_detail {

/// For a state with named Layout, the common component of each of its
/// components (-1 where the name is not a common one).
template <class Layout, int n>
constexpr std::array<int, static_cast<std::size_t>(n)> common_indices() {
  using C = ImmCommonLayout;
  std::array<int, static_cast<std::size_t>(n)> idx{};
  for (int& v : idx) v = -1;
  const auto set = [&idx](int local, int common) { idx[static_cast<std::size_t>(local)] = common; };
  set(Layout::kX, C::kX);
  set(Layout::kVx, C::kVx);
  set(Layout::kY, C::kY);
  set(Layout::kVy, C::kVy);
  if constexpr (requires { Layout::kAx; }) set(Layout::kAx, C::kAx);
  if constexpr (requires { Layout::kAy; }) set(Layout::kAy, C::kAy);
  if constexpr (requires { Layout::kW; }) set(Layout::kW, C::kW);
  return idx;
}

template <class Layout, int n>
constexpr bool maps_every_component() {
  for (const int c : common_indices<Layout, n>()) {
    if (c < 0) return false;
  }
  return true;
}

}  // namespace imm_detail

/// IMM parameters. valid() states what is required.
template <class Scalar, int kModes>
struct ImmConfig {
  using Matrix = Mat<Scalar, kModes, kModes>;
  using Probabilities = Vec<Scalar, kModes>;

  /// Switching matrix with p_stay on the diagonal and the rest spread evenly.
  static Matrix stay_matrix(Scalar p_stay) {
    if constexpr (kModes == 1) {
      return Matrix::Identity();
    } else {
      Matrix m = Matrix::Constant((Scalar(1) - p_stay) / Scalar(kModes - 1));
      for (int i = 0; i < kModes; ++i) m(i, i) = p_stay;
      return m;
    }
  }

  /// p_ij = P(mode j after a predict | mode i before it); rows sum to 1.
  Matrix switching = stay_matrix(Scalar(0.95));
  /// Mode probabilities set by reset(); sum to 1.
  Probabilities initial_probabilities = Probabilities::Constant(Scalar(1) / Scalar(kModes));
  /// Floor of every mode probability (then renormalised): no mode can
  /// underflow to 0 and never come back.
  Scalar min_probability = Scalar(1e-4);
  /// Standard deviation given to the acceleration of a mode without one
  /// (mean 0) when it is lifted into the common state, m/s^2.
  Scalar accel_pad_sigma_mps2 = Scalar(10);
  /// Standard deviation given to the turn rate of a mode without one (mean
  /// 0) and of the Output state at reset(), rad/s.
  Scalar turn_rate_pad_sigma_radps = Scalar(0.1);
  /// The time step `switching` is given for, s (the nominal scan period).
  /// predict(dt) uses switching_over(dt); 0 applies `switching` once per
  /// predict() whatever dt.
  Scalar switching_period_s = Scalar(0);

  /// The switching matrix over dt seconds (header comment: sojourn times).
  /// Equals `switching` bit for bit at dt = switching_period_s, tends to
  /// the identity as dt -> 0 and to the jump proportions as dt grows; a
  /// mode with p_ii = 1 stays absorbing. dt <= 0 (or NaN) gives the
  /// identity. Every row is a probability vector for any dt.
  Matrix switching_over(Scalar dt) const {
    using T = ScalarTraits<Scalar>;
    if (!(switching_period_s > Scalar(0))) return switching;
    Matrix m = switching;
    const Scalar steps = dt > Scalar(0) ? dt / switching_period_s : Scalar(0);
    // p_ii^(dt/T0) as p_ii * exp(ln p_ii (dt/T0 - 1)): the exponent is
    // exactly 0 at dt = T0, so the configured entries come back unchanged.
    const Scalar excess = steps - Scalar(1);
    const Scalar kMaxExponent(80);  // e^80 fits a float; beyond it the row is settled
    for (int i = 0; i < kModes; ++i) {
      const Scalar p = switching(i, i);
      const Scalar leave = Scalar(1) - p;
      if (!(leave > Scalar(0)) || !(p > Scalar(0))) continue;
      Scalar y = T::deterministic_log(p) * excess;
      if (y > kMaxExponent) y = kMaxExponent;
      if (y < -kMaxExponent) y = -kMaxExponent;
      Scalar stay = p * T::deterministic_exp(y);
      if (stay > Scalar(1)) stay = Scalar(1);
      const Scalar share = (Scalar(1) - stay) / leave;
      for (int j = 0; j < kModes; ++j) m(i, j) = i == j ? stay : switching(i, j) * share;
    }
    return m;
  }

  /// Entries in [0, 1], rows summing to 1 within 1e-4, a positive diagonal
  /// (so every c_j > 0), initial probabilities in [0, 1] summing to 1,
  /// 0 < min_probability < 1 / kModes, positive pads, a finite
  /// switching_period_s >= 0.
  bool valid() const {
    const Scalar tol = Scalar(1e-4);
    for (int i = 0; i < kModes; ++i) {
      if (!(switching(i, i) > Scalar(0))) return false;
      for (int j = 0; j < kModes; ++j) {
        if (!(switching(i, j) >= Scalar(0) && switching(i, j) <= Scalar(1))) return false;
      }
      const Scalar row = switching.row(i).sum();
      if (!(row > Scalar(1) - tol && row < Scalar(1) + tol)) return false;
      if (!(initial_probabilities(i) >= Scalar(0) && initial_probabilities(i) <= Scalar(1))) return false;
    }
    const Scalar total = initial_probabilities.sum();
    return total > Scalar(1) - tol && total < Scalar(1) + tol && min_probability > Scalar(0) &&
           min_probability * Scalar(kModes) < Scalar(1) && accel_pad_sigma_mps2 > Scalar(0) &&
           turn_rate_pad_sigma_radps > Scalar(0) && switching_period_s >= Scalar(0) &&
           ScalarTraits<Scalar>::is_finite(switching_period_s);
  }
};

/// IMM over ModeFilters (each with reset, predict, innovation, update, x, P
/// and a Layout whose names are common ones), seen by the tracker as a
/// filter on Output's state measured by OutputMeasurement.
template <MotionModel Output, MeasurementModelFor<Output> OutputMeasurement, class... ModeFilters>
class Imm {
 public:
  using Scalar = typename Output::Scalar;
  static constexpr int kModes = static_cast<int>(sizeof...(ModeFilters));
  static constexpr int kStateDim = Output::kStateDim;
  static constexpr int kMeasDim = OutputMeasurement::kMeasDim;
  static constexpr int kCommonDim = ImmCommonLayout::kDim;
  using MotionModel = Output;
  using MeasurementModel = OutputMeasurement;
  using Layout = typename Output::Layout;
  using State = typename Output::State;
  using Cov = typename Output::Cov;
  using MeasVec = typename OutputMeasurement::Measurement;
  using MeasCov = typename OutputMeasurement::NoiseCov;
  using CommonState = Vec<Scalar, kCommonDim>;
  using CommonCov = Mat<Scalar, kCommonDim, kCommonDim>;
  using Probabilities = Vec<Scalar, kModes>;
  using Config = ImmConfig<Scalar, kModes>;
  using Innov = Innovation<Scalar, kMeasDim>;
  using Diagnostics = FusionDiagnostics<Scalar, kMeasDim>;
  using Modes = std::tuple<ModeFilters...>;
  template <int j>
  using Mode = std::tuple_element_t<static_cast<std::size_t>(j), Modes>;
  using ModeStates = std::array<CommonState, sizeof...(ModeFilters)>;  ///< Every mode lifted.
  using ModeCovs = std::array<CommonCov, sizeof...(ModeFilters)>;

  static_assert(kModes >= 1, "an IMM needs at least one mode");
  static_assert((std::same_as<typename ModeFilters::Scalar, Scalar> && ...), "one scalar for every mode");
  static_assert(((ModeFilters::kMeasDim == kMeasDim) && ...), "every mode takes the same measurement");
  static_assert((imm_detail::maps_every_component<typename ModeFilters::Layout, ModeFilters::kStateDim>() && ...),
                "every mode state component must be a common one (ImmCommonLayout)");
  static_assert(imm_detail::maps_every_component<Layout, kStateDim>(),
                "every Output state component must be a common one (ImmCommonLayout)");

  Imm() : Imm(OutputMeasurement{}, Config{}, ModeFilters{}...) {}

  /// @param h      the measurement model of the combined (output) estimate,
  ///               used by innovation() (the gate) only.
  /// @param params switching matrix, floor and pads; should be valid()
  ///               (predict() refuses with kOutOfRange where c_j is not > 0).
  /// @param modes  the mode filters with their model parameters.
  Imm(const OutputMeasurement& h, const Config& params, const ModeFilters&... modes)
      : modes_(modes...), output_(Output{}, h), params_(params) {
    mu_ = floored(params_.initial_probabilities);
    mixing_ = Mat<Scalar, kModes, kModes>::Identity();
    xc_ = CommonState::Zero();
    Pc_ = pads();
    diag_ = Diagnostics{};
  }

  /// Set every mode to (x, P) (lifted, w = 0 with the turn-rate pad), the
  /// mode probabilities to their initial values.
  /// @return kOk; kNonFinite; kNotPositiveDefinite (filter unchanged).
  [[nodiscard]] Status reset(const State& x, const Cov& P) {
    if (!all_finite(x) || !all_finite(P)) return Status::kNonFinite;
    auto output = output_;
    KESTREL_TRY(output.reset(x, P));
    CommonState xc;
    CommonCov Pc;
    lift<Layout, kStateDim>(output.x(), output.P(), xc, Pc);
    Modes modes = modes_;
    KESTREL_TRY(for_each_mode([&](auto j) {
      constexpr int kJ = decltype(j)::value;
      typename Mode<kJ>::State xj;
      typename Mode<kJ>::Cov Pj;
      project<typename Mode<kJ>::Layout, Mode<kJ>::kStateDim>(xc, Pc, xj, Pj);
      return std::get<kJ>(modes).reset(xj, Pj);
    }));
    modes_ = modes;
    output_ = output;
    xc_ = xc;
    Pc_ = Pc;
    mu_ = floored(params_.initial_probabilities);
    mixing_ = Mat<Scalar, kModes, kModes>::Identity();
    return Status::kOk;
  }

  /// Interaction (mixing) and mode-conditioned prediction by dt seconds,
  /// with the switching matrix over dt (ImmConfig::switching_over).
  /// @return kOk; kNonFinite (dt, a mode), kNotPositiveDefinite (a mode
  ///         refused, or the combined covariance), kOutOfRange (some c_j
  ///         not > 0: invalid switching matrix); the filter is unchanged on
  ///         any refusal.
  [[nodiscard]] Status predict(Scalar dt) {
    if (!ScalarTraits<Scalar>::is_finite(dt)) return Status::kNonFinite;
    // Step 1: predicted mode probabilities c_j = sum_i p_ij mu_i.
    const Mat<Scalar, kModes, kModes> p = params_.switching_over(dt);
    const Probabilities c = p.transpose() * mu_;
    Mat<Scalar, kModes, kModes> mixing;  // (i, j): mu_i|j, step 1
    for (int j = 0; j < kModes; ++j) {
      if (!(c(j) > Scalar(0)) || !ScalarTraits<Scalar>::is_finite(c(j))) return Status::kOutOfRange;
      for (int i = 0; i < kModes; ++i) mixing(i, j) = p(i, j) * mu_(i) / c(j);
    }
    ModeStates X;
    ModeCovs PX;
    lift_modes(modes_, X, PX);

    Modes modes = modes_;
    // (named: the macro inside the lambda would shadow the outer one's status)
    const Status predicted = for_each_mode([&](auto j) {
      constexpr int kJ = decltype(j)::value;
      // Step 2: the mixed initial condition of mode j, in the common state.
      CommonState x0 = CommonState::Zero();
      for (int i = 0; i < kModes; ++i) x0 += mixing(i, kJ) * X[static_cast<std::size_t>(i)];
      CommonCov P0 = CommonCov::Zero();
      for (int i = 0; i < kModes; ++i) {
        const CommonState d = X[static_cast<std::size_t>(i)] - x0;
        P0 += mixing(i, kJ) * (PX[static_cast<std::size_t>(i)] + d * d.transpose());
      }
      typename Mode<kJ>::State xj;
      typename Mode<kJ>::Cov Pj;
      project<typename Mode<kJ>::Layout, Mode<kJ>::kStateDim>(x0, P0, xj, Pj);
      auto& mode = std::get<kJ>(modes);
      KESTREL_TRY(mode.reset(xj, Pj));
      return mode.predict(dt);
    });
    KESTREL_TRY(predicted);
    return commit(modes, floored(c), mixing);
  }

  /// Innovation of z against the combined prediction (header comment: the
  /// moment-matched Gaussian, linearised at its mean). Pure.
  Innov innovation(const MeasVec& z) const { return output_.innovation(z); }

  /// What the gate measures every plot against (the combined prediction's
  /// h(x) and factor of S): forwarded from the output Ekf.
  auto predicted_measurement() const
    requires requires(const Ekf<Output, OutputMeasurement>& e) { e.predicted_measurement(); }
  {
    return output_.predicted_measurement();
  }

  /// Innovation of z against the combined prediction with every R scaled
  /// by `scale` (lambda R, association/adaptive_noise.hpp). Pure.
  Innov innovation_scaled(const MeasVec& z, Scalar scale) const { return output_.innovation_scaled(z, scale); }

  /// Mode-conditioned updates with z, mode probability update and
  /// combination.
  /// @return kOk; kNonFinite or kNotPositiveDefinite (z, a mode's
  ///         innovation or update, or the combined covariance); the filter
  ///         is unchanged on any refusal.
  [[nodiscard]] Status update(const MeasVec& z) { return fuse<false>(z, Scalar(1)); }

  /// update(z) with every mode's R (and the combined innovation's) scaled
  /// by `scale`: the mode likelihoods then use lambda R as well.
  /// @param scale lambda, > 0 and finite.
  /// @return as update(z); kOutOfRange (scale not > 0).
  [[nodiscard]] Status update_scaled(const MeasVec& z, Scalar scale) {
    diag_.fused = false;
    if (!ScalarTraits<Scalar>::is_finite(scale)) return fail(Status::kNonFinite);
    if (!(scale > Scalar(0))) return fail(Status::kOutOfRange);
    return fuse<true>(z, scale);
  }

  /// Combined estimate on Output's state (what the tracker reports).
  const State& x() const { return output_.x(); }
  const Cov& P() const { return output_.P(); }
  /// Combined estimate on the common state [x vx ax y vy ay w].
  const CommonState& common_x() const { return xc_; }
  const CommonCov& common_P() const { return Pc_; }
  /// Mode probabilities: after update() the posterior mu_j, after a
  /// predict() with no update the predicted c_j. They sum to 1.
  const Probabilities& mode_probabilities() const { return mu_; }
  /// Mixing probabilities mu_i|j (row i, column j) of the last predict().
  const Mat<Scalar, kModes, kModes>& mixing_probabilities() const { return mixing_; }
  /// ln L_j + ln c_j of the last update (before normalisation), for diagnostics.
  const Probabilities& log_weights() const { return log_likelihood_; }
  /// Mode filter j (its mode-conditioned estimate).
  template <int j>
  const Mode<j>& mode() const {
    return std::get<static_cast<std::size_t>(j)>(modes_);
  }
  const Config& params() const { return params_; }
  const OutputMeasurement& measurement() const { return output_.measurement(); }
  /// Diagnostics of the last update attempt (the combined innovation).
  const Diagnostics& diagnostics() const { return diag_; }

 private:
  /// f(integral_constant<int, j>) for j = 0 .. kModes-1 in order, stopping
  /// at the first status other than kOk, which is returned.
  template <class F>
  static Status for_each_mode(F&& f) {
    return for_each_mode_impl(f, std::make_integer_sequence<int, kModes>{});
  }
  template <class F, int... kJ>
  static Status for_each_mode_impl(F& f, std::integer_sequence<int, kJ...>) {
    Status s = Status::kOk;
    static_cast<void>(((s = f(std::integral_constant<int, kJ>{}), s == Status::kOk) && ...));
    return s;
  }

  /// diag of the pads: 0 on x, vx, y, vy (every mode has them).
  CommonCov pads() const {
    using C = ImmCommonLayout;
    const Scalar a2 = params_.accel_pad_sigma_mps2 * params_.accel_pad_sigma_mps2;
    CommonCov P = CommonCov::Zero();
    P(C::kAx, C::kAx) = a2;
    P(C::kAy, C::kAy) = a2;
    P(C::kW, C::kW) = params_.turn_rate_pad_sigma_radps * params_.turn_rate_pad_sigma_radps;
    return P;
  }

  /// A state with named Layout lifted into the common state: its own
  /// components copied, the others 0 with the pad variance.
  template <class L, int n>
  void lift(const Vec<Scalar, n>& x, const Mat<Scalar, n, n>& P, CommonState& X, CommonCov& PX) const {
    constexpr auto idx = imm_detail::common_indices<L, n>();
    X = CommonState::Zero();
    PX = pads();
    for (int a = 0; a < n; ++a) {
      const int ca = idx[static_cast<std::size_t>(a)];
      X(ca) = x(a);
      for (int b = 0; b < n; ++b) PX(ca, idx[static_cast<std::size_t>(b)]) = P(a, b);
    }
  }

  /// The components of a state with named Layout taken from the common state.
  template <class L, int n>
  static void project(const CommonState& X, const CommonCov& PX, Vec<Scalar, n>& x, Mat<Scalar, n, n>& P) {
    constexpr auto idx = imm_detail::common_indices<L, n>();
    for (int a = 0; a < n; ++a) {
      const int ca = idx[static_cast<std::size_t>(a)];
      x(a) = X(ca);
      for (int b = 0; b < n; ++b) P(a, b) = PX(ca, idx[static_cast<std::size_t>(b)]);
    }
  }

  void lift_modes(const Modes& modes, ModeStates& X,
                  ModeCovs& PX) const {
    static_cast<void>(for_each_mode([&](auto j) {
      constexpr int kJ = decltype(j)::value;
      const auto& mode = std::get<kJ>(modes);
      lift<typename Mode<kJ>::Layout, Mode<kJ>::kStateDim>(mode.x(), mode.P(), X[static_cast<std::size_t>(kJ)],
                                                            PX[static_cast<std::size_t>(kJ)]);
      return Status::kOk;
    }));
  }

  /// Normalised, floored at min_probability, renormalised.
  Probabilities floored(const Probabilities& w) const {
    Probabilities p = w / w.sum();
    for (int j = 0; j < kModes; ++j) {
      if (!(p(j) > params_.min_probability)) p(j) = params_.min_probability;
    }
    return p / p.sum();
  }

  /// Step 5: combine the modes with weights mu, check,
  /// project onto Output and commit everything.
  [[nodiscard]] Status commit(const Modes& modes, const Probabilities& mu, const Mat<Scalar, kModes, kModes>& mixing) {
    if (!all_finite(mu)) return Status::kNonFinite;
    ModeStates X;
    ModeCovs PX;
    lift_modes(modes, X, PX);
    CommonState xc = CommonState::Zero();
    for (int j = 0; j < kModes; ++j) xc += mu(j) * X[static_cast<std::size_t>(j)];
    CommonCov Pc = CommonCov::Zero();
    for (int j = 0; j < kModes; ++j) {
      const CommonState d = X[static_cast<std::size_t>(j)] - xc;
      Pc += mu(j) * (PX[static_cast<std::size_t>(j)] + d * d.transpose());
    }
    Pc = symmetrised(Pc);
    KESTREL_TRY(state_status(xc, Pc));
    State x;
    Cov P;
    project<Layout, kStateDim>(xc, Pc, x, P);
    auto output = output_;
    KESTREL_TRY(output.reset(x, P));

    modes_ = modes;
    output_ = output;
    xc_ = xc;
    Pc_ = Pc;
    mu_ = mu;
    mixing_ = mixing;
    return Status::kOk;
  }

  /// update()'s cycle (steps 3-5) with R, or with lambda R when kScaled.
  template <bool kScaled>
  [[nodiscard]] Status fuse(const MeasVec& z, [[maybe_unused]] Scalar scale) {
    diag_.fused = false;
    if (!all_finite(z)) return fail(Status::kNonFinite);
    const Innov combined = kScaled ? output_.innovation_scaled(z, scale) : output_.innovation(z);
    KESTREL_TRY_OR(fail, combined.status);
    Modes modes = modes_;
    Probabilities log_posterior;
    // (named: the macro inside the lambda would shadow the outer one's status)
    const Status fused = for_each_mode([&](auto j) {
      constexpr int kJ = decltype(j)::value;
      auto& mode = std::get<kJ>(modes);
      const auto inn = kScaled ? mode.innovation_scaled(z, scale) : mode.innovation(z);
      KESTREL_TRY(inn.status);
      Scalar log_det(0);
      if (!log_det_spd(inn.S, log_det)) return Status::kNotPositiveDefinite;
      // Step 3's likelihood in logs (the 2 pi term is common to all modes
      // and dropped), plus ln c_j: the numerator of step 4.
      log_posterior(kJ) = -(inn.d2 + log_det) / Scalar(2) + ScalarTraits<Scalar>::log(mu_(kJ));
      if constexpr (kScaled) {
        return mode.update_scaled(z, scale);
      } else {
        return mode.update(z);
      }
    });
    KESTREL_TRY_OR(fail, fused);
    if (!all_finite(log_posterior)) return fail(Status::kNonFinite);

    // Step 4, shifted by the largest term before exp, so the
    // largest weight is exactly 1 and the sum is in [1, kModes].
    const Scalar top = log_posterior.maxCoeff();
    Probabilities w;
    for (int j = 0; j < kModes; ++j) w(j) = ScalarTraits<Scalar>::exp(log_posterior(j) - top);
    KESTREL_TRY_OR(fail, commit(modes, floored(w), mixing_));
    log_likelihood_ = log_posterior;
    diag_.fused_all(combined.nu, combined.S.diagonal(), combined.d2);
    return Status::kOk;
  }

  Status fail(Status s) {
    diag_.fused = false;
    diag_.fused_channels = 0;
    diag_.status = s;
    return s;
  }

  Modes modes_;
  Ekf<Output, OutputMeasurement> output_;  ///< Combined estimate on Output's state (x, P, gate).
  Config params_;
  CommonState xc_;
  CommonCov Pc_;
  Probabilities mu_;
  Mat<Scalar, kModes, kModes> mixing_;
  Probabilities log_likelihood_ = Probabilities::Zero();
  Diagnostics diag_;
};

}  // namespace kestrel
