// SPDX-License-Identifier: Apache-2.0
// Model structure the generic filters exploit when a model exposes it,
// detected at compile time: a block-diagonal motion model (F P F^T and Q per
// axis block), a measurement Jacobian with few non-zero columns (P H^T and
// H P H^T from those columns, the update through the Cholesky factor of S),
// and small innovation covariances factored by an unrolled Cholesky. A
// filter asks "does this model expose X?" (a concept below) and calls the
// kernel here in place of the dense product, so no filter is written twice.
// Dense<M> hides a model's structure: the dense path is the fallback, the
// test oracle (tests/core/filters/structured_*) and the baseline. Kernels
// and why: docs/filters.md, "EKF: update forms and model structure".
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <type_traits>
#include <utility>

#include "kestrel/math/eigen.hpp"
#include "kestrel/math/finite.hpp"
#include "kestrel/models/concepts.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"

namespace kestrel {

/// A model that declares kHideStructure = true (Dense<M>) is treated as dense.
template <class M>
concept HidesStructure = requires { requires M::kHideStructure; };

/// A motion model whose Jacobian and process noise are block-diagonal over
/// consecutive axes (contract: jacobian(x, dt) = blkdiag(axis_transition(dt), ...)
/// and process_noise(dt) = blkdiag(axis_process_noise(dt), ...)).
template <class M>
concept BlockDiagonalMotion =
    MotionModel<M> && !HidesStructure<M> && requires(const M& m, typename M::Scalar dt) {
      requires M::kAxisDim > 0;
      requires M::kStateDim % M::kAxisDim == 0;
      { m.axis_transition(dt) } -> std::same_as<Mat<typename M::Scalar, M::kAxisDim, M::kAxisDim>>;
      { m.axis_process_noise(dt) } -> std::same_as<Mat<typename M::Scalar, M::kAxisDim, M::kAxisDim>>;
    };

/// A block-diagonal motion model whose F1 is unit upper triangular (every
/// kinematic chain: position <- velocity <- acceleration), declared with
/// kAxisTransitionUnitUpper = true: the transform skips F1's structural
/// zeros and ones.
template <class M>
concept UnitUpperAxisTransition = BlockDiagonalMotion<M> && requires { requires M::kAxisTransitionUnitUpper; };

/// A measurement model whose Jacobian is zero outside the state columns
/// kJacobianColumns (contract: jacobian(x) has jacobian_columns(x).col(j) in
/// column kJacobianColumns[j] and zeros elsewhere). It may also offer
/// jacobian_columns(x, predict(x)), equal to jacobian_columns(x), for
/// columns that reuse part of h(x) (the radar's range).
template <class H>
concept SparseJacobianMeasurement = !HidesStructure<H> && requires(const H& h, const typename H::State& x) {
  { H::kJacobianColumns.size() } -> std::convertible_to<std::size_t>;
  {
    h.jacobian_columns(x)
  } -> std::same_as<Mat<typename H::Scalar, H::kMeasDim, static_cast<int>(H::kJacobianColumns.size())>>;
};

/// Model M with its structure hidden from the filters (dense path): the
/// baseline and the test oracle of the structured path. Everything else of
/// M (parameters, layout, helpers) is inherited unchanged.
template <class M>
struct Dense : M {
  static constexpr bool kHideStructure = true;
  Dense() = default;
  explicit Dense(const M& m) : M(m) {}
};

namespace structure {

/// f(std::integral_constant<int, i>{}) for i = kBegin .. kEnd-1, expanded at
/// compile time (a fold, not a loop): the kernels below index fixed-size
/// matrices with constants, so no loop counter or index arithmetic is left
/// at -O2, where GCC leaves nested loops rolled.
template <int kBegin, int kEnd, class F>
constexpr void static_for(F&& f) {
  if constexpr (kBegin < kEnd) {
    [&]<int... i>(std::integer_sequence<int, i...>) {
      (f(std::integral_constant<int, kBegin + i>{}), ...);
    }(std::make_integer_sequence<int, kEnd - kBegin>{});
  }
}

/// F P F^T for block-diagonal F, block by block: the upper blocks only,
/// each diagonal block's upper triangle, the rest mirrored, so the result
/// is exactly symmetric. With a unit upper triangular F1 the structural
/// zeros and ones of F1 are skipped.
template <BlockDiagonalMotion M>
typename M::Cov transform_covariance(const M& motion, const typename M::Cov& P, typename M::Scalar dt) {
  using S = typename M::Scalar;
  constexpr int d = M::kAxisDim;
  constexpr int kAxes = M::kStateDim / d;
  constexpr bool kUnitUpper = UnitUpperAxisTransition<M>;
  const Mat<S, d, d> F1 = motion.axis_transition(dt);
  typename M::Cov out;
  if constexpr (ScalarTraits<S>::kIsFixedPoint) {
    // The same products in rolled loops: in fixed point every product is a
    // call, so unrolling saves little time and costs a Cortex-M0+ image
    // kilobytes of text.
    for (int i = 0; i < kAxes; ++i) {
      for (int j = i; j < kAxes; ++j) {
        Mat<S, d, d> G;
        for (int r = 0; r < d; ++r) {
          for (int c = 0; c < d; ++c) {
            S v = kUnitUpper ? P(i * d + r, j * d + c) : F1(r, r) * P(i * d + r, j * d + c);
            for (int k = kUnitUpper ? r + 1 : 0; k < d; ++k) {
              if (k != r) v += F1(r, k) * P(i * d + k, j * d + c);
            }
            G(r, c) = v;
          }
        }
        for (int r = 0; r < d; ++r) {
          for (int c = i == j ? r : 0; c < d; ++c) {
            S v = kUnitUpper ? G(r, c) : G(r, c) * F1(c, c);
            for (int k = kUnitUpper ? c + 1 : 0; k < d; ++k) {
              if (k != c) v += G(r, k) * F1(c, k);
            }
            out(i * d + r, j * d + c) = v;
            out(j * d + c, i * d + r) = v;
          }
        }
      }
    }
    return out;
  }
  static_for<0, kAxes>([&](auto ia) {
    constexpr int i = decltype(ia)::value;
    static_for<i, kAxes>([&](auto ja) {
      constexpr int j = decltype(ja)::value;
      // G = F1 P_ij.
      Mat<S, d, d> G;
      static_for<0, d>([&](auto ra) {
        constexpr int r = decltype(ra)::value;
        static_for<0, d>([&](auto ca) {
          constexpr int c = decltype(ca)::value;
          S v = kUnitUpper ? P(i * d + r, j * d + c) : F1(r, r) * P(i * d + r, j * d + c);
          static_for<(kUnitUpper ? r + 1 : 0), d>([&](auto ka) {
            constexpr int k = decltype(ka)::value;
            if constexpr (k != r) v += F1(r, k) * P(i * d + k, j * d + c);
          });
          G(r, c) = v;
        });
      });
      // B = G F1^T: the upper triangle of a diagonal block, all of an
      // off-diagonal one; each entry also written to its mirror.
      static_for<0, d>([&](auto ra) {
        constexpr int r = decltype(ra)::value;
        static_for<(i == j ? r : 0), d>([&](auto ca) {
          constexpr int c = decltype(ca)::value;
          S v = kUnitUpper ? G(r, c) : G(r, c) * F1(c, c);
          static_for<(kUnitUpper ? c + 1 : 0), d>([&](auto ka) {
            constexpr int k = decltype(ka)::value;
            if constexpr (k != c) v += G(r, k) * F1(c, k);
          });
          out(i * d + r, j * d + c) = v;
          out(j * d + c, i * d + r) = v;
        });
      });
    });
  });
  return out;
}

/// all_finite() of a square matrix whose lower triangle holds the same
/// values as its upper one (every covariance the kernels here return, and
/// (A + A^T) / 2, since IEEE addition commutes): the upper triangle decides,
/// 21 of 36 coefficients for a 6 x 6, in one reduction as all_finite().
/// With SIMD packets wider than two (float on SSE: four) the ragged column
/// heads cost more than the whole matrix in full packets, so those take
/// all_finite() of everything (docs/performance.md, "The covariance
/// check").
template <class S, int n>
bool all_finite_mirrored(const Mat<S, n, n>& P) {
  if constexpr (std::is_floating_point_v<S> && Eigen::internal::packet_traits<S>::size > 2) {
    return all_finite(P);
  } else if constexpr (std::is_floating_point_v<S>) {
    Vec<S, n> acc = P.col(n - 1) * S(0);
    static_for<0, n - 1>([&](auto ca) {
      constexpr int c = decltype(ca)::value;
      acc.template head<c + 1>() += P.col(c).template head<c + 1>() * S(0);
    });
    return ScalarTraits<S>::is_finite(acc.sum());
  } else {
    return all_finite(P);
  }
}

/// Flattened where GCC optimises for speed: it otherwise may leave a
/// static_for body out of line once the unit holds more code (a call per
/// element of the unrolled fold). A size build (-Os, the boards) keeps
/// GCC's own choice.
#if defined(__OPTIMIZE_SIZE__)
#define KESTREL_FLATTEN_FOR_SPEED
#else
#define KESTREL_FLATTEN_FOR_SPEED [[gnu::flatten]]
#endif

/// P += blkdiag(Q1, ..., Q1) with Q1 = axis_process_noise(dt), symmetrised.
template <BlockDiagonalMotion M>
KESTREL_FLATTEN_FOR_SPEED void add_process_noise(const M& motion, typename M::Cov& P, typename M::Scalar dt) {
  using S = typename M::Scalar;
  constexpr int d = M::kAxisDim;
  constexpr int kAxes = M::kStateDim / d;
  const Mat<S, d, d> Q1 = motion.axis_process_noise(dt);
  static_for<0, d>([&](auto ra) {
    constexpr int r = decltype(ra)::value;
    static_for<r, d>([&](auto ca) {
      constexpr int c = decltype(ca)::value;
      const S q = r == c ? Q1(r, r) : (Q1(r, c) + Q1(c, r)) * S(0.5);
      static_for<0, kAxes>([&](auto ia) {
        constexpr int i = decltype(ia)::value;
        P(i * d + r, i * d + c) += q;
        if constexpr (r != c) P(i * d + c, i * d + r) += q;
      });
    });
  });
}

/// P += kron(M, Q1), Q1 = axis_process_noise(dt): axis block (i, j) of the
/// process noise is M(i, j) Q1 (an adaptive filter's per-axis shaping, e.g.
/// R2-AEKF eq. 18), symmetrised as add_symmetrised() would, upper blocks
/// mirrored.
template <BlockDiagonalMotion M>
KESTREL_FLATTEN_FOR_SPEED void add_mixed_process_noise(const M& motion, typename M::Cov& P, typename M::Scalar dt,
                             const Mat<typename M::Scalar, M::kStateDim / M::kAxisDim, M::kStateDim / M::kAxisDim>& mix) {
  using S = typename M::Scalar;
  constexpr int d = M::kAxisDim;
  constexpr int kAxes = M::kStateDim / d;
  const Mat<S, d, d> Q1 = motion.axis_process_noise(dt);
  Mat<S, d, d> Qs;  // (Q1 + Q1^T) / 2
  static_for<0, d>([&](auto ra) {
    constexpr int r = decltype(ra)::value;
    static_for<r, d>([&](auto ca) {
      constexpr int c = decltype(ca)::value;
      Qs(r, c) = r == c ? Q1(r, r) : (Q1(r, c) + Q1(c, r)) * S(0.5);
      Qs(c, r) = Qs(r, c);
    });
  });
  static_for<0, kAxes>([&](auto ia) {
    constexpr int i = decltype(ia)::value;
    static_for<i, kAxes>([&](auto ja) {
      constexpr int j = decltype(ja)::value;
      const S m = i == j ? mix(i, i) : (mix(i, j) + mix(j, i)) * S(0.5);
      static_for<0, d>([&](auto ra) {
        constexpr int r = decltype(ra)::value;
        static_for<(i == j ? r : 0), d>([&](auto ca) {
          constexpr int c = decltype(ca)::value;
          const S q = m * Qs(r, c);
          P(i * d + r, j * d + c) += q;
          if constexpr (i != j || r != c) P(j * d + c, i * d + r) += q;
        });
      });
    });
  });
}

/// P + (Q + Q^T) / 2 for a full Q (the explicit-Q predict of adaptive filters).
template <class S, int n>
void add_symmetrised(Mat<S, n, n>& P, const Mat<S, n, n>& Q) {
  static_for<0, n>([&](auto ca) {
    constexpr int c = decltype(ca)::value;
    static_for<0, c + 1>([&](auto ra) {
      constexpr int r = decltype(ra)::value;
      const S q = (Q(r, c) + Q(c, r)) * S(0.5);
      P(r, c) += q;
      if constexpr (r != c) P(c, r) += q;
    });
  });
}

/// S = L L^T, L lower triangular.
/// @return false if S is not positive definite.
template <class S, int m>
bool cholesky_lower(const Mat<S, m, m>& Sm, Mat<S, m, m>& L) {
  bool ok = true;
  static_for<0, m>([&](auto ja) {
    constexpr int j = decltype(ja)::value;
    S dj = Sm(j, j);
    static_for<0, j>([&](auto ka) { dj -= L(j, decltype(ka)::value) * L(j, decltype(ka)::value); });
    ok = ok && dj > S(0);
    L(j, j) = ScalarTraits<S>::sqrt(dj > S(0) ? dj : S(1));
    static_for<j + 1, m>([&](auto ia) {
      constexpr int i = decltype(ia)::value;
      S v = Sm(i, j);
      static_for<0, j>([&](auto ka) { v -= L(i, decltype(ka)::value) * L(j, decltype(ka)::value); });
      L(i, j) = v / L(j, j);
    });
  });
  return ok;
}

/// y = L^-1 v for lower triangular L (forward substitution, unrolled).
template <class S, int m>
Vec<S, m> forward_substitute(const Mat<S, m, m>& L, const Vec<S, m>& v) {
  Vec<S, m> y;
  static_for<0, m>([&](auto ia) {
    constexpr int i = decltype(ia)::value;
    S t = v(i);
    static_for<0, i>([&](auto ka) { t -= L(i, decltype(ka)::value) * y(decltype(ka)::value); });
    y(i) = t / L(i, i);
  });
  return y;
}

/// nu^T S^-1 nu = |L^-1 nu|^2 with S = L L^T.
/// @return false if S is not positive definite.
template <class S, int m>
bool nis(const Mat<S, m, m>& Sm, const Vec<S, m>& nu, S& d2) {
  Mat<S, m, m> L = Mat<S, m, m>::Zero();
  if (!cholesky_lower(Sm, L)) return false;
  d2 = forward_substitute(L, nu).squaredNorm();
  return true;
}

/// S = L L^T, L lower triangular, with inv_diag(j) = 1 / L(j, j): the
/// reciprocals let every later substitution multiply instead of divide (a
/// fixed-point division is a 64-step loop; here there are m of them, one
/// per column, instead of one per entry). Used where the diagonal is well
/// scaled: the whitened S_w (diagonal >= 1, so 1 / L(j, j) is in (0, 1])
/// and the factor of R (a sensor's standard deviations).
/// @return false if S is not positive definite (L and inv_diag then hold
///         unit pivots where it failed).
template <class S, int m>
bool cholesky_lower_reciprocal(const Mat<S, m, m>& Sm, Mat<S, m, m>& L, Vec<S, m>& inv_diag) {
  bool ok = true;
  static_for<0, m>([&](auto ja) {
    constexpr int j = decltype(ja)::value;
    S dj = Sm(j, j);
    static_for<0, j>([&](auto ka) { dj -= L(j, decltype(ka)::value) * L(j, decltype(ka)::value); });
    ok = ok && dj > S(0);
    L(j, j) = ScalarTraits<S>::sqrt(dj > S(0) ? dj : S(1));
    inv_diag(j) = S(1) / L(j, j);
    static_for<0, j>([&](auto ka) { L(decltype(ka)::value, j) = S(0); });
    static_for<j + 1, m>([&](auto ia) {
      constexpr int i = decltype(ia)::value;
      S v = Sm(i, j);
      static_for<0, j>([&](auto ka) { v -= L(i, decltype(ka)::value) * L(j, decltype(ka)::value); });
      L(i, j) = v * inv_diag(j);
    });
  });
  return ok;
}

/// y = L^-1 v by forward substitution with the reciprocals of L's diagonal
/// (cholesky_lower_reciprocal()).
template <class S, int m>
Vec<S, m> forward_substitute_reciprocal(const Mat<S, m, m>& L, const Vec<S, m>& inv_diag, const Vec<S, m>& v) {
  Vec<S, m> y;
  static_for<0, m>([&](auto ia) {
    constexpr int i = decltype(ia)::value;
    S t = v(i);
    static_for<0, i>([&](auto ka) { t -= L(i, decltype(ka)::value) * y(decltype(ka)::value); });
    y(i) = t * inv_diag(i);
  });
  return y;
}

/// whitened_gain_factored() with the reciprocals of L's diagonal: U = P H^T
/// L^-T column by column, w = L^-1 nu.
template <class S, int n, int m>
void whitened_gain_reciprocal(const Mat<S, n, m>& PHt, const Mat<S, m, m>& L, const Vec<S, m>& inv_diag,
                              const Vec<S, m>& nu, Mat<S, n, m>& U, Vec<S, m>& w) {
  w = forward_substitute_reciprocal(L, inv_diag, nu);
  static_for<0, m>([&](auto ja) {
    constexpr int j = decltype(ja)::value;
    Vec<S, n> u = PHt.col(j);
    static_for<0, j>([&](auto ka) { u -= U.col(decltype(ka)::value) * L(j, decltype(ka)::value); });
    U.col(j) = u * inv_diag(j);
  });
}

/// whitened_gain() (below) with the factor L of S = L L^T already known
/// (lower triangular, positive diagonal).
template <class S, int n, int m>
void whitened_gain_factored(const Mat<S, n, m>& PHt, const Mat<S, m, m>& L, const Vec<S, m>& nu, Mat<S, n, m>& U,
                            Vec<S, m>& w) {
  w = forward_substitute(L, nu);
  static_for<0, m>([&](auto ja) {
    constexpr int j = decltype(ja)::value;
    Vec<S, n> u = PHt.col(j);
    static_for<0, j>([&](auto ka) { u -= U.col(decltype(ka)::value) * L(j, decltype(ka)::value); });
    U.col(j) = u / L(j, j);
  });
}

/// The measurement update through the Cholesky factor of S = L L^T:
///   w = L^-1 nu,   U = P H^T L^-T,
/// so that, with K = P H^T S^-1 = U L^-1,
///   K nu = U w,   K S K^T = K (P H^T)^T = U U^T,   nu^T S^-1 nu = |w|^2,
/// and the update x + U w, P - U U^T (symmetric_downdate) needs neither
/// S^-1 nor K. U is solved column by column from U L^T = P H^T, each
/// column one vector operation down the n rows.
/// @return false if S is not positive definite (U and w not written).
template <class S, int n, int m>
bool whitened_gain(const Mat<S, n, m>& PHt, const Mat<S, m, m>& Sm, const Vec<S, m>& nu, Mat<S, n, m>& U,
                   Vec<S, m>& w) {
  Mat<S, m, m> L = Mat<S, m, m>::Zero();
  if (!cholesky_lower(Sm, L)) return false;
  whitened_gain_factored(PHt, L, nu, U, w);
  return true;
}

/// P - U U^T on the upper triangle, mirrored (exactly symmetric): the
/// covariance update P - K S K^T = P - P H^T S^-1 H P of whitened_gain().
template <class S, int n, int m>
Mat<S, n, n> symmetric_downdate(const Mat<S, n, n>& P, const Mat<S, n, m>& U) {
  Mat<S, n, n> out;
  if constexpr (ScalarTraits<S>::kIsFixedPoint) {  // rolled: see transform_covariance()
    for (int c = 0; c < n; ++c) {
      for (int r = 0; r <= c; ++r) {
        S v = P(r, c);
        for (int j = 0; j < m; ++j) v -= U(r, j) * U(c, j);
        out(r, c) = v;
        out(c, r) = v;
      }
    }
    return out;
  }
  // Column c, rows 0..c (vectorised down the column), then mirrored into row c.
  static_for<0, n>([&](auto ca) {
    constexpr int c = decltype(ca)::value;
    auto col = out.col(c).template head<c + 1>();
    col = P.col(c).template head<c + 1>();
    static_for<0, m>([&](auto ja) {
      constexpr int j = decltype(ja)::value;
      col -= U.col(j).template head<c + 1>() * U(c, j);
    });
    static_for<0, c>([&](auto ra) { out(c, decltype(ra)::value) = out(decltype(ra)::value, c); });
  });
  return out;
}

/// The non-zero columns of H, and the products the EKF needs from them.
template <SparseJacobianMeasurement H>
struct SparseJacobian {
  using Scalar = typename H::Scalar;
  static constexpr int kMeasDim = H::kMeasDim;
  static constexpr int kStateDim = H::kStateDim;
  static constexpr int kCols = static_cast<int>(H::kJacobianColumns.size());
  using Compact = Mat<Scalar, kMeasDim, kCols>;
  using Cov = Mat<Scalar, kStateDim, kStateDim>;
  using PHt = Mat<Scalar, kStateDim, kMeasDim>;
  using MeasCov = Mat<Scalar, kMeasDim, kMeasDim>;

  Compact Hc;  ///< Column j is column kJacobianColumns[j] of the full H.

  static constexpr int col(int j) { return H::kJacobianColumns[static_cast<std::size_t>(j)]; }

  /// The full H (zeros outside the columns).
  Mat<Scalar, kMeasDim, kStateDim> full() const {
    Mat<Scalar, kMeasDim, kStateDim> out = Mat<Scalar, kMeasDim, kStateDim>::Zero();
    static_for<0, kCols>([&](auto ja) { out.col(col(decltype(ja)::value)) = Hc.col(decltype(ja)::value); });
    return out;
  }

  /// P H^T = P(:, cols) Hc^T (vectorised over the rows of P).
  PHt p_ht(const Cov& P) const {
    PHt out;
    static_for<0, kMeasDim>([&](auto ia) {
      constexpr int i = decltype(ia)::value;
      out.col(i) = P.col(col(0)) * Hc(i, 0);
      static_for<1, kCols>([&](auto ja) {
        constexpr int j = decltype(ja)::value;
        out.col(i) += P.col(col(j)) * Hc(i, j);
      });
    });
    return out;
  }

  /// H P H^T = Hc P(cols, cols) Hc^T, upper triangle mirrored (exactly
  /// symmetric). Depends on the state only through Hc: the EKF caches it.
  MeasCov hpht(const Cov& P) const {
    Mat<Scalar, kMeasDim, kCols> HP;  // Hc P(cols, cols)
    static_for<0, kMeasDim>([&](auto ia) {
      constexpr int i = decltype(ia)::value;
      static_for<0, kCols>([&](auto ba) {
        constexpr int b = decltype(ba)::value;
        Scalar v = Hc(i, 0) * P(col(0), col(b));
        static_for<1, kCols>([&](auto aa) {
          constexpr int a = decltype(aa)::value;
          v += Hc(i, a) * P(col(a), col(b));
        });
        HP(i, b) = v;
      });
    });
    MeasCov out;
    static_for<0, kMeasDim>([&](auto ca) {
      constexpr int c = decltype(ca)::value;
      static_for<0, c + 1>([&](auto ra) {
        constexpr int r = decltype(ra)::value;
        Scalar v = HP(r, 0) * Hc(c, 0);
        static_for<1, kCols>([&](auto ba) {
          constexpr int b = decltype(ba)::value;
          v += HP(r, b) * Hc(c, b);
        });
        out(r, c) = v;
        out(c, r) = v;
      });
    });
    return out;
  }
};

/// A measurement linearised at a state x and covariance P: h(x), the
/// non-zero Jacobian columns and H P H^T. The EKF keeps one, so the gate's
/// innovation() of every candidate in a frame and the update that follows
/// share a single h(x) (an atan2 and a sqrt for the polar radar), Jacobian
/// and H P H^T; any change of x, P or the model invalidates it.
template <SparseJacobianMeasurement H>
struct Linearisation {
  // Zero-initialised: never read while invalid, but a filter copied before
  // its first innovation copies them, and copying indeterminate values is
  // undefined (GCC's -Wmaybe-uninitialized says so).
  typename H::Measurement z_hat = H::Measurement::Zero();             ///< h(x).
  SparseJacobian<H> J{SparseJacobian<H>::Compact::Zero()};             ///< Non-zero columns of dh/dx at x.
  typename SparseJacobian<H>::MeasCov HPHt = SparseJacobian<H>::MeasCov::Zero();  ///< H P H^T (exactly symmetric).
  /// With the model's own R: S = H P H^T + R and its lower Cholesky factor,
  /// shared by the innovation of every plot against this track and by the
  /// update that follows (the per-pair work is then the residual and one
  /// forward substitution); computed on first use (factor_valid).
  typename SparseJacobian<H>::MeasCov S = SparseJacobian<H>::MeasCov::Zero();
  typename SparseJacobian<H>::MeasCov L = SparseJacobian<H>::MeasCov::Zero();
  Status factor_status = Status::kNotInitialised;  ///< kOk, kNonFinite (R, H or S) or kNotPositiveDefinite.
  bool factor_valid = false;                   ///< false: S, L and factor_status to be recomputed.
  bool valid = false;                          ///< false: recompute before use.
};

/// The linearisation of the sequential whitened form (Ekf's header
/// comment): besides h(x), the Jacobian columns and H P H^T, the factor of
/// R = Lr Lr^T (kept until the model changes: R does not depend on x or P),
/// the whitened columns Hw = Lr^-1 Hc and the factor of S_w = Hw P Hw^T + I
/// = Ls Ls^T, with the reciprocals of both diagonals. Folding the whitened
/// channels in one at a time, channel j's divisor is s_j = Ls(j, j)^2 >= 1
/// and its gain column P_j-1 h_j / sqrt(s_j) is column j of U = P Hw^T
/// Ls^-T, so the sequential update is x + U w, P - U U^T with w = Ls^-1
/// Lr^-1 nu, and the NIS is |w|^2: the same factors serve the gate's
/// distance of every plot and the update.
template <SparseJacobianMeasurement H>
struct WhitenedLinearisation {
  using MeasCov = typename SparseJacobian<H>::MeasCov;
  using MeasVec = typename H::Measurement;
  // As in Linearisation<H>, without the batch form's factor L.
  MeasVec z_hat = MeasVec::Zero();                           ///< h(x).
  SparseJacobian<H> J{SparseJacobian<H>::Compact::Zero()};  ///< Non-zero columns of dh/dx at x.
  MeasCov HPHt = MeasCov::Zero();                            ///< H P H^T (exactly symmetric).
  MeasCov S = MeasCov::Zero();                               ///< H P H^T + R with the model's R.
  Status factor_status = Status::kNotInitialised;            ///< Of the factor of S_w.
  bool factor_valid = false;
  bool valid = false;
  MeasCov Lr = MeasCov::Zero();                                     ///< R = Lr Lr^T, lower.
  MeasVec inv_lr = MeasVec::Zero();                                 ///< 1 / Lr(j, j).
  SparseJacobian<H> Jw{SparseJacobian<H>::Compact::Zero()};         ///< Hw = Lr^-1 Hc.
  MeasCov Ls = MeasCov::Zero();                                     ///< S_w = Ls Ls^T, lower, diagonal >= 1.
  MeasVec inv_ls = MeasVec::Zero();                                 ///< 1 / Ls(j, j), in (0, 1].
  Status noise_status = Status::kNotInitialised;                    ///< Of the factor of R.
  bool noise_valid = false;  ///< false: Lr and inv_lr to be recomputed (the model changed).
};

/// Hw = Lr^-1 Hc (rows by forward substitution) and the factor of
/// S_w = Hw P Hw^T + I for the whitened form, given R's factor.
/// @return kOk, kNonFinite (Hw or S_w) or kNotPositiveDefinite (S_w).
template <SparseJacobianMeasurement H>
Status whitened_factor(const SparseJacobian<H>& J, const typename SparseJacobian<H>::MeasCov& Lr,
                       const typename H::Measurement& inv_lr, const typename SparseJacobian<H>::Cov& P,
                       SparseJacobian<H>& Jw, typename SparseJacobian<H>::MeasCov& Ls,
                       typename H::Measurement& inv_ls) {
  using S = typename H::Scalar;
  constexpr int m = H::kMeasDim;
  static_for<0, m>([&](auto ia) {
    constexpr int i = decltype(ia)::value;
    auto row = J.Hc.row(i).eval();
    static_for<0, i>([&](auto ka) { row -= Lr(i, decltype(ka)::value) * Jw.Hc.row(decltype(ka)::value); });
    Jw.Hc.row(i) = row * inv_lr(i);
  });
  typename SparseJacobian<H>::MeasCov Sw = Jw.hpht(P);
  static_for<0, m>([&](auto ja) { Sw(decltype(ja)::value, decltype(ja)::value) += S(1); });
  if (!all_finite(Jw.Hc) || !all_finite(Sw)) return Status::kNonFinite;
  return cholesky_lower_reciprocal(Sw, Ls, inv_ls) ? Status::kOk : Status::kNotPositiveDefinite;
}

/// Placeholder of the cache for a measurement without the structure.
struct NoLinearisation {};

/// Linearisation<H> if H has a sparse Jacobian, NoLinearisation otherwise.
template <class H>
struct LinearisationFor {
  using type = NoLinearisation;
};
template <SparseJacobianMeasurement H>
struct LinearisationFor<H> {
  using type = Linearisation<H>;
};

/// WhitenedLinearisation<H> if H has a sparse Jacobian, NoLinearisation otherwise.
template <class H>
struct WhitenedLinearisationFor {
  using type = NoLinearisation;
};
template <SparseJacobianMeasurement H>
struct WhitenedLinearisationFor<H> {
  using type = WhitenedLinearisation<H>;
};

}  // namespace structure
}  // namespace kestrel
