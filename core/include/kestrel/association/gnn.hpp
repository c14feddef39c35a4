// SPDX-License-Identifier: Apache-2.0
// Global nearest neighbour (docs/tracking.md, "Association"): the optimal
// assignment of tracks (rows) to measurements (columns) on a bounded cost
// matrix, each track taking at most one measurement and each measurement
// feeding at most one track, minimising the assigned costs plus miss_cost
// per unassigned track; with cost = d2 and miss_cost = the gate's chi-square
// threshold this is the usual GNN. Solved by the Hungarian method in the
// Jonker-Volgenant form (shortest augmenting paths) with a private miss
// column per track, on an Eigen matrix of bounded dynamic size
// (kMaxTracks x kMaxMeasurements) and member arrays: every loop has a
// constant bound, no recursion, no allocation.
#pragma once

#include <cstddef>

#include "kestrel/math/eigen.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"

namespace kestrel {

template <class Scalar, std::size_t kMaxTracks, std::size_t kMaxMeasurements>
class Gnn {
  static_assert(kMaxTracks > 0 && kMaxMeasurements > 0, "a GNN problem needs at least one row and one column");
  static_assert(kMaxTracks + kMaxMeasurements < 32768, "indices are int");
  static constexpr int kMaxRows = static_cast<int>(kMaxTracks);
  static constexpr int kMaxCols = static_cast<int>(kMaxMeasurements);
  static constexpr int kMaxAugmentedCols = kMaxCols + kMaxRows;
  static constexpr std::size_t kArray = kMaxTracks + kMaxMeasurements + 1;

 public:
  /// Tracks x measurements; resize to (rows, cols) within the bounds, no heap.
  using CostMatrix = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, kMaxRows, kMaxCols>;

  /// Solve the assignment for `cost` (rows = tracks, cols = measurements).
  /// @param miss_cost cost of leaving a track unassigned (e.g. the gate threshold).
  /// @param col_of_row out: for each row < cost.rows(), its column or -1.
  /// @param total out: the minimised total cost (assigned pairs + misses).
  /// @return kOk; kOutOfRange (an empty or over-capacity matrix);
  ///         kNonFinite (NaN in cost, -Inf, or a non-finite miss_cost).
  ///         On failure col_of_row and total are unchanged.
  [[nodiscard]] Status solve(const CostMatrix& cost, Scalar miss_cost, int (&col_of_row)[kMaxTracks], Scalar& total) {
    using T = ScalarTraits<Scalar>;
    const int n = static_cast<int>(cost.rows());
    const int m = static_cast<int>(cost.cols());
    if (n < 1 || m < 0 || n > kMaxRows || m > kMaxCols) return Status::kOutOfRange;
    if (!T::is_finite(miss_cost)) return Status::kNonFinite;
    // Forbidden entries get `big`, larger than any assignment that avoids
    // them can cost (all rows missing costs n * miss_cost), so the optimum
    // never uses one; it stays finite so the potentials stay finite.
    Scalar max_abs = T::abs(miss_cost);
    for (int j = 0; j < kMaxCols; ++j) {
      if (j >= m) break;
      for (int i = 0; i < kMaxRows; ++i) {
        if (i >= n) break;
        const Scalar c = cost(i, j);
        if (T::is_finite(c)) {
          if (T::abs(c) > max_abs) max_abs = T::abs(c);
        } else if (!(c > Scalar(0))) {
          return Status::kNonFinite;  // NaN or -Inf (+Inf just forbids the pair)
        }
      }
    }
    big_ = (max_abs + Scalar(1)) * Scalar(2 * (n + 1));
    m_ = m;
    cost_ = &cost;
    miss_ = miss_cost;

    const int cols = m + n;
    for (int j = 0; j <= kMaxAugmentedCols; ++j) {
      v_[j] = Scalar(0);
      p_[j] = 0;
      way_[j] = 0;
    }
    for (int i = 0; i <= kMaxRows; ++i) u_[i] = Scalar(0);

    // Rows are 1-based inside the solver; column 0 is the virtual root.
    for (int row = 1; row <= kMaxRows; ++row) {
      if (row > n) break;
      p_[0] = row;
      int j0 = 0;
      for (int j = 0; j <= kMaxAugmentedCols; ++j) {
        minv_[j] = T::max_value();
        used_[j] = false;
      }
      // Grow the alternating tree until it reaches a free column: each pass
      // adds one column, so at most cols + 1 passes.
      for (int pass = 0; pass <= kMaxAugmentedCols; ++pass) {
        used_[j0] = true;
        const int i0 = p_[j0];
        Scalar delta = T::max_value();
        int j1 = 0;
        for (int j = 1; j <= kMaxAugmentedCols; ++j) {
          if (j > cols) break;
          if (used_[j]) continue;
          const Scalar cur = augmented(i0 - 1, j - 1) - u_[i0] - v_[j];
          if (cur < minv_[j]) {
            minv_[j] = cur;
            way_[j] = j0;
          }
          if (minv_[j] < delta) {
            delta = minv_[j];
            j1 = j;
          }
        }
        for (int j = 0; j <= kMaxAugmentedCols; ++j) {
          if (j > cols) break;
          if (used_[j]) {
            u_[p_[j]] += delta;
            v_[j] -= delta;
          } else {
            minv_[j] -= delta;
          }
        }
        j0 = j1;
        if (p_[j0] == 0) break;
      }
      // Flip the path from the free column back to the root.
      for (int step = 0; step <= kMaxAugmentedCols; ++step) {
        const int j1 = way_[j0];
        p_[j0] = p_[j1];
        j0 = j1;
        if (j0 == 0) break;
      }
    }

    int result[kMaxTracks];
    Scalar sum(0);
    for (int i = 0; i < kMaxRows; ++i) result[i] = -1;
    for (int j = 1; j <= kMaxAugmentedCols; ++j) {
      if (j > cols) break;
      const int row = p_[j];
      if (row == 0) continue;
      if (j <= m) {
        result[row - 1] = j - 1;
        sum += cost(row - 1, j - 1);
      } else {
        sum += miss_cost;
      }
    }
    for (int i = 0; i < kMaxRows; ++i) col_of_row[i] = result[i];
    total = sum;
    return Status::kOk;
  }

 private:
  /// Entry (i, j) of the n x (m + n) problem: real columns, then the misses.
  Scalar augmented(int i, int j) const {
    if (j < m_) {
      const Scalar c = (*cost_)(i, j);
      return ScalarTraits<Scalar>::is_finite(c) && !(c > miss_) ? c : big_;
    }
    return j - m_ == i ? miss_ : big_;
  }

  const CostMatrix* cost_ = nullptr;
  Scalar miss_{};
  Scalar big_{};
  int m_ = 0;
  Scalar u_[kMaxTracks + 1]{};
  Scalar v_[kArray]{};
  Scalar minv_[kArray]{};
  int p_[kArray]{};
  int way_[kArray]{};
  bool used_[kArray]{};
};

}  // namespace kestrel
