// SPDX-License-Identifier: Apache-2.0
// What a filter says about one measurement before (and after) using it: the
// innovation, its covariance, the normalised squared distance, and per-channel
// diagnostics in the spirit of PX4's aid-source fields (innovation, variance,
// test ratio, fused/rejected). Shared by every filter and by the gate.
#pragma once

#include "kestrel/filters/channels.hpp"
#include "kestrel/math/eigen.hpp"
#include "kestrel/status.hpp"

namespace kestrel {

template <class Scalar, int kMeasDim>
struct Innovation {
  static constexpr int kDim = kMeasDim;
  Vec<Scalar, kMeasDim> nu = Vec<Scalar, kMeasDim>::Zero();                 ///< z - h(x_pred), angles wrapped.
  Mat<Scalar, kMeasDim, kMeasDim> S = Mat<Scalar, kMeasDim, kMeasDim>::Zero();  ///< Innovation covariance H P H^T + R.
  Scalar d2{};                                     ///< nu^T S^-1 nu (NIS), unitless.
  Status status = Status::kNotInitialised;         ///< kOk, kNonFinite or kNotPositiveDefinite.
};

/// The normalised distance of one plot from a track's predicted measurement:
/// all a gate and an associator need per track-plot pair (the innovation
/// itself is formed only for the plot a track takes).
template <class Scalar>
struct PlotDistance {
  Scalar d2;      ///< nu^T S^-1 nu, unitless.
  Status status;  ///< kOk, kNonFinite or kNotPositiveDefinite.
};

/// What the last update attempt said about each channel: one record for
/// every filter and sensor kind (PX4's aid-source fields: innovation, its
/// variance, test ratio, fused or rejected). A filter that fuses the whole
/// measurement marks every channel present and fused and leaves test_ratio
/// at 0; a channel gate (ChannelGatedEkf) fills it and the masks per channel.
template <class Scalar, int kMeasDim>
struct FusionDiagnostics {
  static_assert(kMeasDim <= 32, "a ChannelMask holds 32 channels");
  static constexpr ChannelMask kAllChannels = all_channels(kMeasDim);
  Vec<Scalar, kMeasDim> innovation = Vec<Scalar, kMeasDim>::Zero();           ///< nu_i of present channels, 0 elsewhere.
  Vec<Scalar, kMeasDim> innovation_variance = Vec<Scalar, kMeasDim>::Zero();  ///< S_ii of present channels, 0 elsewhere.
  Vec<Scalar, kMeasDim> test_ratio = Vec<Scalar, kMeasDim>::Zero();  ///< The channel's gate test (> 1 fails); 0 where none ran.
  ChannelMask present = 0;         ///< Channels the measurement carried.
  ChannelMask rejected = 0;        ///< Channels a gate dropped.
  ChannelMask fused_channels = 0;  ///< Channels that went into the update.
  Scalar nis{};                    ///< nu^T S^-1 nu over the fused channels (0 if none).
  bool fused = false;              ///< true if x and P were updated.
  Status status = Status::kNotInitialised;  ///< Outcome of the last update.

  /// Record an update that fused every channel.
  void fused_all(const Vec<Scalar, kMeasDim>& nu, const Vec<Scalar, kMeasDim>& s_ii, Scalar d2) {
    innovation = nu;
    innovation_variance = s_ii;
    test_ratio.setZero();
    present = kAllChannels;
    rejected = 0;
    fused_channels = kAllChannels;
    nis = d2;
    fused = true;
    status = Status::kOk;
  }
};

}  // namespace kestrel
