// SPDX-License-Identifier: Apache-2.0
// Test-side ASTERIX bytes: CAT048 records and data blocks built item by
// item from the specification's layouts (EUROCONTROL Part 4, ed. 1.31), for
// the reader's tests, the seeded mutation test and the tshark check's pcap
// writer. Host code: it may use std::vector.
#pragma once

#include <cstdint>
#include <vector>

namespace kestrel::test {

using Bytes = std::vector<std::uint8_t>;

/// One CAT048 plot in ASTERIX units; the optional items are written when set.
struct Cat048PlotSpec {
  std::uint8_t sac = 0;
  std::uint8_t sic = 1;
  std::uint32_t tod_128 = 0;     ///< I048/140, 1/128 s.
  std::uint16_t rho_256nm = 0;   ///< I048/040 RHO, 1/256 NM.
  std::uint16_t theta = 0;       ///< I048/040 THETA, 2^16 per turn, clockwise from north.
  bool with_track_number = false;
  std::uint16_t track_number = 0;  ///< I048/161, 12 bits.
  bool with_doppler = false;
  std::int16_t doppler_mps = 0;  ///< I048/120 CAL, m/s, -512..511.
  bool doppler_doubtful = false; ///< I048/120 CAL D bit.
};

inline void put_be(Bytes& b, std::uint32_t v, int bytes) {
  for (int i = bytes - 1; i >= 0; --i) b.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

/// An FSPEC for the given FRNs (1-based, any order), FX set on all but the
/// last octet.
inline Bytes fspec(const std::vector<int>& frns) {
  int max_frn = 1;
  for (int f : frns) max_frn = f > max_frn ? f : max_frn;
  Bytes out(static_cast<std::size_t>((max_frn + 6) / 7), 0);
  for (int f : frns) out[static_cast<std::size_t>((f - 1) / 7)] |= static_cast<std::uint8_t>(0x80u >> ((f - 1) % 7));
  for (std::size_t i = 0; i + 1 < out.size(); ++i) out[i] |= 0x01u;
  return out;
}

/// A CAT048 record: I048/010, /140, /020 (one octet: single PSR), /040 and
/// the optional /161 and /120 (CAL), in UAP order.
inline Bytes cat048_record(const Cat048PlotSpec& p) {
  std::vector<int> frns{1, 2, 3, 4};
  if (p.with_track_number) frns.push_back(11);
  if (p.with_doppler) frns.push_back(20);
  Bytes r = fspec(frns);
  r.push_back(p.sac);
  r.push_back(p.sic);
  put_be(r, p.tod_128, 3);
  r.push_back(0x20);  // I048/020: TYP = 1 (single PSR detection), FX clear
  put_be(r, p.rho_256nm, 2);
  put_be(r, p.theta, 2);
  if (p.with_track_number) put_be(r, p.track_number, 2);
  if (p.with_doppler) {
    r.push_back(0x80);  // I048/120 primary: CAL only
    const std::uint32_t cal = (static_cast<std::uint32_t>(p.doppler_mps) & 0x03FFu) | (p.doppler_doubtful ? 0x8000u : 0u);
    put_be(r, cal, 2);
  }
  return r;
}

/// A data block of category `cat` around already built records.
inline Bytes asterix_block(std::uint8_t cat, const std::vector<Bytes>& records) {
  Bytes body;
  for (const Bytes& rec : records) body.insert(body.end(), rec.begin(), rec.end());
  Bytes b{cat};
  put_be(b, static_cast<std::uint32_t>(body.size() + 3), 2);
  b.insert(b.end(), body.begin(), body.end());
  return b;
}

inline Bytes cat048_block(const std::vector<Cat048PlotSpec>& plots) {
  std::vector<Bytes> records;
  for (const Cat048PlotSpec& p : plots) records.push_back(cat048_record(p));
  return asterix_block(48, records);
}

}  // namespace kestrel::test
