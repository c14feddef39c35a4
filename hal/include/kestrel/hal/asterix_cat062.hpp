// SPDX-License-Identifier: Apache-2.0
// Writer of ASTERIX CAT062 (system track data, EUROCONTROL ASTERIX Part 9,
// edition 1.19 UAP): one data block of track records from core
// TrackReports. Items, in FRN order: I062/010 SAC/SIC, I062/015 service
// identification (optional), I062/070 time of track information, I062/100
// Cartesian position, I062/185 Cartesian velocity, I062/040 track number,
// I062/080 track status, I062/500 estimated accuracies (APC). Cartesian
// axes are Kestrel's (x east, y north, radar at the origin), which is the
// CAT062 system plane when the radar is the system reference point.
// Out-of-range values are refused (kOutOfRange), never clamped or wrapped.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>

#include "kestrel/hal/asterix_units.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "kestrel/status.hpp"
#include "kestrel/tracking/track.hpp"

namespace kestrel::hal::asterix {

inline constexpr std::uint8_t kCat062 = 62;

/// One CAT062 track record in the items' units. encode_cat062 checks each
/// field against its item's range.
struct Cat062Track {
  std::uint32_t tod_128 = 0;        ///< I062/070, 1/128 s since midnight, < 86400 x 128.
  std::int32_t x_half_m = 0;        ///< I062/100 X, 0.5 m, 24-bit two's complement range.
  std::int32_t y_half_m = 0;        ///< I062/100 Y, 0.5 m, 24-bit two's complement range.
  std::int32_t vx_quarter_mps = 0;  ///< I062/185 Vx, 0.25 m/s, 16-bit two's complement range.
  std::int32_t vy_quarter_mps = 0;  ///< I062/185 Vy, 0.25 m/s, 16-bit two's complement range.
  std::uint32_t track_number = 0;   ///< I062/040, 0..65535.
  bool tentative = false;           ///< I062/080 CNF: 1 = tentative, 0 = confirmed.
  std::uint32_t apc_x_half_m = 0;   ///< I062/500 APC X (position sigma), 0.5 m, 0..65535.
  std::uint32_t apc_y_half_m = 0;   ///< I062/500 APC Y (position sigma), 0.5 m, 0..65535.
};

/// Who sends the block: the same for every record.
struct Cat062Source {
  std::uint8_t sac = 0;            ///< I062/010 system area code.
  std::uint8_t sic = 0;            ///< I062/010 system identification code.
  bool has_service_id = false;     ///< Write I062/015.
  std::uint8_t service_id = 0;     ///< I062/015 service identification.
};

/// Bytes of one record: FSPEC 4, 010 2, [015 1], 070 3, 100 6, 185 4,
/// 040 2, 080 1, 500 5.
constexpr std::size_t cat062_record_size(const Cat062Source& src) { return src.has_service_id ? 28u : 27u; }

/// Write one data block (CAT 62, LEN, one record per track) into `out`.
/// @param written bytes written on kOk, else 0 (nothing is written then).
/// @return kOk; kOutOfRange (a field outside its item's range, or a block
///         longer than LEN's 65535 bytes); kBufferTooSmall.
[[nodiscard]] Status encode_cat062(const Cat062Source& src, std::span<const Cat062Track> tracks,
                                   std::span<std::uint8_t> out, std::size_t& written);

namespace detail {
// Round v / lsb to an integer when it lies within [lo, hi]; false otherwise
// (non-finite included), so no value is ever converted out of range.
inline bool to_units(double v, double lsb, std::int64_t lo, std::int64_t hi, std::int64_t& units) {
  if (!std::isfinite(v)) return false;
  const double scaled = std::nearbyint(v / lsb);
  if (scaled < static_cast<double>(lo) || scaled > static_cast<double>(hi)) return false;
  units = static_cast<std::int64_t>(scaled);
  return true;
}
}  // namespace detail

/// Fill a CAT062 record from a tracker's report (Filter::MotionModel has a
/// Layout with kX, kY, kVx, kVy, in m and m/s).
/// @param report its t_us is microseconds since midnight (the CAT048
///        reader's frame time); APC is sqrt of P's x and y variances.
/// @return kOk; kOutOfRange (t_us outside [0, 1 day), track id over 65535,
///         position, velocity or accuracy outside its item's range; `out`
///         untouched); kNonFinite (a NaN/Inf value or negative variance).
template <class Filter>
[[nodiscard]] Status to_cat062(const TrackReport<Filter>& report, Cat062Track& out) {
  using Layout = typename Filter::MotionModel::Layout;
  using T = ScalarTraits<typename Filter::Scalar>;
  if (report.t_us < 0 || report.t_us >= kDayUs) return Status::kOutOfRange;
  if (report.track_id > 0xFFFFu) return Status::kOutOfRange;
  const double x = T::to_double(report.x(Layout::kX));
  const double y = T::to_double(report.x(Layout::kY));
  const double vx = T::to_double(report.x(Layout::kVx));
  const double vy = T::to_double(report.x(Layout::kVy));
  const double pxx = T::to_double(report.P(Layout::kX, Layout::kX));
  const double pyy = T::to_double(report.P(Layout::kY, Layout::kY));
  if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(vx) || !std::isfinite(vy) ||
      !std::isfinite(pxx) || !std::isfinite(pyy) || pxx < 0.0 || pyy < 0.0) {
    return Status::kNonFinite;
  }
  constexpr std::int64_t kPos = std::int64_t{1} << 23;
  constexpr std::int64_t kVel = std::int64_t{1} << 15;
  std::int64_t ux = 0, uy = 0, uvx = 0, uvy = 0, ax = 0, ay = 0;
  if (!detail::to_units(x, 0.5, -kPos, kPos - 1, ux) || !detail::to_units(y, 0.5, -kPos, kPos - 1, uy) ||
      !detail::to_units(vx, 0.25, -kVel, kVel - 1, uvx) || !detail::to_units(vy, 0.25, -kVel, kVel - 1, uvy) ||
      !detail::to_units(std::sqrt(pxx), 0.5, 0, 0xFFFF, ax) || !detail::to_units(std::sqrt(pyy), 0.5, 0, 0xFFFF, ay)) {
    return Status::kOutOfRange;
  }
  // The last 3.9 ms of a day round up to 86400 s, which is not a time of day.
  const std::uint32_t tod = time_of_day_from_t_us(report.t_us);
  if (tod >= kDayTod128) return Status::kOutOfRange;
  out.tod_128 = tod;
  out.x_half_m = static_cast<std::int32_t>(ux);
  out.y_half_m = static_cast<std::int32_t>(uy);
  out.vx_quarter_mps = static_cast<std::int32_t>(uvx);
  out.vy_quarter_mps = static_cast<std::int32_t>(uvy);
  out.track_number = report.track_id;
  out.tentative = report.status != TrackStatus::kConfirmed;
  out.apc_x_half_m = static_cast<std::uint32_t>(ax);
  out.apc_y_half_m = static_cast<std::uint32_t>(ay);
  return Status::kOk;
}

}  // namespace kestrel::hal::asterix
