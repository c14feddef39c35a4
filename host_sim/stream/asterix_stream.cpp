// SPDX-License-Identifier: Apache-2.0
#include "stream/asterix_stream.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "kestrel/hal/asterix_units.hpp"
#include "stream/feed_frames.hpp"
#include "stream/quantise.hpp"

namespace kestrel::sim {

namespace {

namespace ax = hal::asterix;

void put_be(std::vector<std::uint8_t>& b, std::uint32_t v, int bytes) {
  for (int i = bytes - 1; i >= 0; --i) b.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

std::string at(const MeasurementFrame& f) { return "frame at t = " + std::to_string(f.t_s) + " s: "; }

std::uint32_t tod_of(const MeasurementFrame& f) {
  const std::int64_t t_us = to_wire_time_us(f.t_s);
  // The last 3.9 ms of a day round to 86400 s, which is no time of day.
  if (t_us < 0 || t_us >= ax::kDayUs || ax::time_of_day_from_t_us(t_us) >= ax::kDayTod128) {
    throw std::out_of_range(at(f) + "CAT048 I048/140 carries a time of day, [0, 86400) s");
  }
  return ax::time_of_day_from_t_us(t_us);
}

std::uint16_t rho_of(const MeasurementFrame& f, double range_m) {
  const std::uint32_t mm = to_wire_range_mm(range_m);
  const std::uint64_t rho = (static_cast<std::uint64_t>(mm) * 256u + 926'000u) / 1'852'000u;
  if (rho > 0xFFFFu) {
    throw std::out_of_range(at(f) + "range " + std::to_string(range_m) +
                            " m is beyond CAT048 I048/040 RHO, 65535/256 NM = 474119.0 m");
  }
  return ax::rho_from_range_mm(mm);
}

std::uint32_t cal_of(const MeasurementFrame& f, double range_rate_mps) {
  const double cal = std::nearbyint(range_rate_mps);
  if (!std::isfinite(cal) || cal < -512.0 || cal > 511.0) {
    throw std::out_of_range(at(f) + "range rate " + std::to_string(range_rate_mps) +
                            " m/s is outside CAT048 I048/120 CAL, [-512, 511] m/s");
  }
  // 10-bit two's complement in the low bits, D (doubtful) and spares clear.
  return static_cast<std::uint32_t>(static_cast<std::int32_t>(cal)) & 0x03FFu;
}

}  // namespace

std::vector<std::uint8_t> encode_cat048_stream(const std::vector<MeasurementFrame>& frames, std::uint8_t sac) {
  std::vector<std::uint8_t> out;
  for (const MeasurementFrame& f : frames) {
    if (f.kind != hal::FrameKind::kRadar) throw std::invalid_argument(at(f) + "only radar plots have a CAT048 form");
    const std::uint32_t tod = tod_of(f);
    std::vector<std::uint8_t> body;
    for (const RadarPlotSi& p : f.radar) {
      const std::uint16_t rho = rho_of(f, p.range_m);
      const std::uint16_t theta = ax::azimuth_from_bearing_bam(to_wire_bearing_bam(p.bearing_rad));
      if (p.range_rate_mps.has_value()) {
        // FRNs 1, 2, 3, 4 and 20: three FSPEC octets, FX on the first two.
        body.insert(body.end(), {0xF1, 0x01, 0x04});
      } else {
        body.push_back(0xF0);  // FRNs 1, 2, 3, 4
      }
      body.push_back(sac);
      body.push_back(p.sensor_id);  // SIC: the reader makes it the plot's sensor_id
      put_be(body, tod, 3);
      body.push_back(0x20);  // I048/020: TYP = 1, single PSR detection; FX clear
      put_be(body, rho, 2);
      put_be(body, theta, 2);
      if (p.range_rate_mps.has_value()) {
        body.push_back(0x80);  // I048/120 primary subfield: CAL only
        put_be(body, cal_of(f, *p.range_rate_mps), 2);
      }
    }
    if (body.size() + ax::kBlockHeaderSize > 0xFFFFu) throw std::out_of_range(at(f) + "block longer than 65535 bytes");
    out.push_back(ax::kCat048);
    put_be(out, static_cast<std::uint32_t>(body.size() + ax::kBlockHeaderSize), 2);
    out.insert(out.end(), body.begin(), body.end());
  }
  return out;
}

std::vector<MeasurementFrame> decode_cat048_stream(const std::vector<std::uint8_t>& bytes, std::size_t& skipped,
                                                   AsterixReadCounts& counts) {
  host::AsterixFileFeed feed(bytes);
  std::vector<MeasurementFrame> frames = frames_of_feed(feed, skipped);
  counts.feed = feed.counters();
  counts.reader = feed.reader_counters();
  return frames;
}

}  // namespace kestrel::sim
