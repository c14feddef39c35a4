// SPDX-License-Identifier: Apache-2.0
// Time of arrival with multipath at a set of beacons (paper 003 eq. 1, 6 and
// 7; docs/models.md, "TOA with multipath"): each beacon hears the target on
// the direct path and on the seabed-reflected one, modelled by the image
// source mirrored across the seabed at depth D (depth z positive downward).
// The measurement vector holds every channel the model can know,
// channel(i, path) = 2 i + path, so its size is fixed at 2 * kMaxBeacons; a
// frame carries a subset and the channel-gated EKF updates with exactly
// that. The reflected Jacobian row's depth entry has the opposite sign to
// the direct one (the image moves up when the target moves down), which is
// what makes depth observable with every beacon at the surface
// (docs/sonar.md).
#pragma once

#include <cstddef>
#include <cstdint>

#include "kestrel/math/eigen.hpp"
#include "kestrel/scalar/scalar_traits.hpp"

namespace kestrel {

/// Arrival path of a TOA; values match hal::ToaPath on the wire.
enum class ArrivalPath : std::uint8_t {
  kDirect = 0,     ///< Straight line from the target to the beacon.
  kReflected = 1,  ///< Seabed-reflected (image source below the seabed).
};

/// Beacon geometry, seabed and noise of a multipath TOA sensor.
template <class S, int kMaxBeacons>
struct MultipathToaConfig {
  static_assert(kMaxBeacons > 0, "at least one beacon");
  Vec<S, 3> beacons_m[static_cast<std::size_t>(kMaxBeacons)]{};  ///< Beacon positions [x, y, depth], m; depth down.
  std::uint8_t beacon_count = 0;       ///< Beacons in use (entries 0 .. beacon_count-1).
  S seabed_depth_m{};                  ///< D, depth of the flat seabed, m (> every beacon and target depth).
  S sigma_toa_s{};                     ///< Standard deviation of one arrival time, s.
};

template <class Motion, int kMaxBeacons>
struct MultipathToa {
  using Scalar = typename Motion::Scalar;
  using Config = MultipathToaConfig<Scalar, kMaxBeacons>;
  static constexpr int kStateDim = Motion::kStateDim;
  static constexpr int kBeacons = kMaxBeacons;
  static constexpr int kMeasDim = 2 * kMaxBeacons;  ///< Direct and reflected channel per beacon.

  using State = Vec<Scalar, kStateDim>;
  using Measurement = Vec<Scalar, kMeasDim>;  ///< Arrival times, s, by channel().
  using Jacobian = Mat<Scalar, kMeasDim, kStateDim>;
  using NoiseCov = Mat<Scalar, kMeasDim, kMeasDim>;
  using Position = Vec<Scalar, 3>;

  Config config{};

  /// Index of (beacon, path) in a measurement vector.
  static constexpr int channel(int beacon, ArrivalPath path) {
    return 2 * beacon + static_cast<int>(path);
  }
  static constexpr int beacon_of(int ch) { return ch / 2; }
  static constexpr ArrivalPath path_of(int ch) {
    return (ch % 2) == 0 ? ArrivalPath::kDirect : ArrivalPath::kReflected;
  }
  /// true if the channel belongs to a configured beacon.
  bool channel_valid(int ch) const {
    return ch >= 0 && ch < kMeasDim && beacon_of(ch) < static_cast<int>(config.beacon_count);
  }

  /// Source position a channel sees: p itself (direct) or its image across
  /// the seabed [x, y, 2D - z] (reflected).
  Position source(const Position& p, ArrivalPath path) const {
    if (path == ArrivalPath::kDirect) return p;
    return Position(p(0), p(1), Scalar(2) * config.seabed_depth_m - p(2));
  }

  /// Path length of one channel, m, and its gradient with respect to p.
  /// @param ch a valid channel (see channel_valid()).
  Scalar path_length(const Position& p, int ch, Position* grad_p = nullptr) const {
    const Position d = source(p, path_of(ch)) - config.beacons_m[beacon_of(ch)];
    const Scalar len = ScalarTraits<Scalar>::sqrt(d.squaredNorm());
    if (grad_p != nullptr) {
      *grad_p = d / len;
      // d(2D - z)/dz = -1: the image moves opposite to the target.
      if (path_of(ch) == ArrivalPath::kReflected) (*grad_p)(2) = -(*grad_p)(2);
    }
    return len;
  }

  /// h(X): arrival time of every channel, s; 0 for beacons not configured.
  Measurement predict(const State& x) const {
    const Position p = position(x);
    const Scalar c = x(Motion::Layout::kC);
    Measurement z = Measurement::Zero();
    for (int ch = 0; ch < kMeasDim; ++ch) {
      if (!channel_valid(ch)) continue;
      z(ch) = path_length(p, ch) / c;
    }
    return z;
  }

  /// dh/dX, rows by channel (header comment); zero rows for beacons not
  /// configured. A target on a beacon (or its image on one) gives a
  /// non-finite row, and the filter refuses the update with kNonFinite.
  Jacobian jacobian(const State& x) const {
    const Position p = position(x);
    const Scalar c = x(Motion::Layout::kC);
    Jacobian H = Jacobian::Zero();
    for (int ch = 0; ch < kMeasDim; ++ch) {
      if (!channel_valid(ch)) continue;
      Position g;
      const Scalar len = path_length(p, ch, &g);
      H(ch, Motion::Layout::kX) = g(0) / c;
      H(ch, Motion::Layout::kY) = g(1) / c;
      H(ch, Motion::Layout::kZ) = g(2) / c;
      H(ch, Motion::Layout::kC) = -len / (c * c);
    }
    return H;
  }

  /// R = sigma_toa^2 I (arrivals independent, equal noise on both paths).
  NoiseCov noise() const { return NoiseCov::Identity() * (config.sigma_toa_s * config.sigma_toa_s); }

  /// z - z_hat: times need no wrapping.
  Measurement residual(const Measurement& z, const Measurement& z_hat) const { return z - z_hat; }

  static Position position(const State& x) {
    return Position(x(Motion::Layout::kX), x(Motion::Layout::kY), x(Motion::Layout::kZ));
  }
};

}  // namespace kestrel
