// What a filter says about one measurement before (and after) using it: the
// innovation, its covariance, the normalised squared distance, and per-channel
// diagnostics in the spirit of PX4's aid-source fields (innovation, variance,
// test ratio, fused/rejected). Shared by every filter and by the gate.
#pragma once

#include "kestrel/math/eigen.hpp"
#include "kestrel/status.hpp"

namespace kestrel {

template <class Scalar, int kMeasDim>
struct Innovation {
  static constexpr int kDim = kMeasDim;
  Vec<Scalar, kMeasDim> nu;           ///< z - h(x_pred), angles wrapped.
  Mat<Scalar, kMeasDim, kMeasDim> S;  ///< Innovation covariance H P H^T + R.
  Scalar d2;                          ///< nu^T S^-1 nu (NIS), unitless.
  Status status;                      ///< kOk, kNonFinite or kNotPositiveDefinite.
};

/// The normalised distance of one plot from a track's predicted measurement:
/// all a gate and an associator need per track-plot pair (the innovation
/// itself is formed only for the plot a track takes).
template <class Scalar>
struct PlotDistance {
  Scalar d2;      ///< nu^T S^-1 nu, unitless.
  Status status;  ///< kOk, kNonFinite or kNotPositiveDefinite.
};

/// Last fusion attempt of a filter, readable after each update.
template <class Scalar, int kMeasDim>
struct FusionDiagnostics {
  Vec<Scalar, kMeasDim> innovation;           ///< nu of the last update.
  Vec<Scalar, kMeasDim> innovation_variance;  ///< diag(S) of the last update.
  Scalar nis;                                 ///< nu^T S^-1 nu of the last update.
  bool fused;                                 ///< true if the state was changed.
  Status status;                              ///< Outcome of the last update.
};

}  // namespace kestrel
