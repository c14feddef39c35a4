// SPDX-License-Identifier: Apache-2.0
// TrackRow: one track report flattened to plain doubles in SI units, whatever
// the filter's scalar and state layout. It is the row of the track CSV
// (docs/host_sim.md) and what kestrel-sim scores, so both read a report the same
// way. Quantities the motion model does not carry (acceleration in a CV
// model) are NaN and written as empty CSV cells.
#pragma once

#include <cstdint>
#include <limits>

#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/tracking/track.hpp"

namespace kestrel::host {

struct TrackRow {
  double time_s = 0.0;          ///< Frame time, s (sensor clock).
  std::uint32_t track_id = 0;   ///< Stable track id.
  bool confirmed = false;       ///< Confirmed (else tentative).
  std::uint16_t age = 0;        ///< Frames since the track started.
  std::uint16_t hits = 0;       ///< Measurements associated in total.
  std::uint16_t misses = 0;     ///< Consecutive misses.
  bool associated = false;      ///< Updated by a measurement in this frame.
  std::int16_t measurement_index = -1;  ///< Index of that measurement in the frame, -1 if none.
  double nis = 0.0;             ///< NIS of this frame's association (NaN if not associated).
  double x_m = 0.0;             ///< Position east of the sensor, m.
  double y_m = 0.0;             ///< Position north of the sensor, m.
  double vx_mps = 0.0;          ///< Velocity, m/s.
  double vy_mps = 0.0;          ///< Velocity, m/s.
  double ax_mps2 = std::numeric_limits<double>::quiet_NaN();  ///< Acceleration if modelled, m/s^2.
  double ay_mps2 = std::numeric_limits<double>::quiet_NaN();  ///< Acceleration if modelled, m/s^2.
  double p_xx = 0.0;            ///< Position covariance, m^2.
  double p_xy = 0.0;            ///< Position covariance, m^2.
  double p_yy = 0.0;            ///< Position covariance, m^2.
};

/// Flatten a core report. The state is read by the filter's named layout
/// (Layout::kX, kVx, ...), so every filter on a 2D motion model fits.
template <class Filter>
TrackRow to_track_row(const TrackReport<Filter>& r) {
  using L = typename Filter::Layout;
  using T = ScalarTraits<typename Filter::Scalar>;
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  TrackRow row;
  row.time_s = static_cast<double>(r.t_us) * 1e-6;
  row.track_id = r.track_id;
  row.confirmed = r.status == TrackStatus::kConfirmed;
  row.age = r.age;
  row.hits = r.hits;
  row.misses = r.misses;
  row.associated = r.associated;
  row.measurement_index = r.measurement_index;
  row.nis = r.associated ? T::to_double(r.nis) : kNaN;
  row.x_m = T::to_double(r.x(L::kX));
  row.y_m = T::to_double(r.x(L::kY));
  row.vx_mps = T::to_double(r.x(L::kVx));
  row.vy_mps = T::to_double(r.x(L::kVy));
  if constexpr (requires { L::kAx; L::kAy; }) {
    row.ax_mps2 = T::to_double(r.x(L::kAx));
    row.ay_mps2 = T::to_double(r.x(L::kAy));
  }
  row.p_xx = T::to_double(r.P(L::kX, L::kX));
  row.p_xy = T::to_double(r.P(L::kX, L::kY));
  row.p_yy = T::to_double(r.P(L::kY, L::kY));
  return row;
}

}  // namespace kestrel::host
