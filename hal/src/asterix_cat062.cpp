// SPDX-License-Identifier: Apache-2.0
// CAT062 block writer (asterix_cat062.hpp). Every field is range-checked
// and the whole block's size known before the first byte is written, so a
// refused block leaves `out` untouched. ASTERIX is big-endian.
#include "kestrel/hal/asterix_cat062.hpp"

namespace kestrel::hal::asterix {

namespace {

// FSPEC of the edition 1.19 UAP, FRN -> (octet, bit):
//   octet 1: FRN 1 I062/010 (0x80), FRN 3 I062/015 (0x20), FRN 4 I062/070
//            (0x10), FRN 6 I062/100 (0x04), FRN 7 I062/185 (0x02), FX;
//   octet 2: FRN 12 I062/040 (0x08), FRN 13 I062/080 (0x04), FX;
//   octet 3: none of FRN 15-21, FX;
//   octet 4: FRN 27 I062/500 (0x04).
constexpr std::uint8_t kFspec1 = 0x80u | 0x10u | 0x04u | 0x02u | 0x01u;
constexpr std::uint8_t kFspec1ServiceId = 0x20u;
constexpr std::uint8_t kFspec2 = 0x08u | 0x04u | 0x01u;
constexpr std::uint8_t kFspec3 = 0x01u;
constexpr std::uint8_t kFspec4 = 0x04u;
// I062/080 octet 1: MON (bit 8) = monosensor track, CNF (bit 2), FX clear.
constexpr std::uint8_t kStatusMono = 0x80u;
constexpr std::uint8_t kStatusTentative = 0x02u;
// I062/500 primary subfield: APC only (bit 8), FX clear.
constexpr std::uint8_t kAccuracyApc = 0x80u;

constexpr std::size_t kMaxBlockLen = 0xFFFF;
constexpr std::int32_t kPosLimit = 1 << 23;  // 24-bit two's complement
constexpr std::int32_t kVelLimit = 1 << 15;  // 16-bit two's complement

bool in_range(const Cat062Track& t) {
  return t.tod_128 < kDayTod128 && t.x_half_m >= -kPosLimit && t.x_half_m < kPosLimit &&
         t.y_half_m >= -kPosLimit && t.y_half_m < kPosLimit && t.vx_quarter_mps >= -kVelLimit &&
         t.vx_quarter_mps < kVelLimit && t.vy_quarter_mps >= -kVelLimit && t.vy_quarter_mps < kVelLimit &&
         t.track_number <= 0xFFFFu && t.apc_x_half_m <= 0xFFFFu && t.apc_y_half_m <= 0xFFFFu;
}

// Appends big-endian fields; the caller has checked the total size.
class BigEndianWriter {
 public:
  explicit BigEndianWriter(std::span<std::uint8_t> out) : out_(out) {}
  void u8(std::uint32_t v) { out_[pos_++] = static_cast<std::uint8_t>(v & 0xFFu); }
  // The low `bytes` bytes of v, most significant first; a negative value's
  // two's complement is its low bytes (modular uint32 conversion).
  void field(std::int64_t v, std::size_t bytes) {
    const auto u = static_cast<std::uint32_t>(v);
    for (std::size_t i = bytes; i > 0; --i) u8(u >> (8 * (i - 1)));
  }
  std::size_t size() const { return pos_; }

 private:
  std::span<std::uint8_t> out_;
  std::size_t pos_ = 0;
};

}  // namespace

Status encode_cat062(const Cat062Source& src, std::span<const Cat062Track> tracks, std::span<std::uint8_t> out,
                     std::size_t& written) {
  written = 0;
  const std::size_t record = cat062_record_size(src);
  if (tracks.size() > (kMaxBlockLen - kBlockHeaderSize) / record) return Status::kOutOfRange;
  for (const Cat062Track& t : tracks) {
    if (!in_range(t)) return Status::kOutOfRange;
  }
  const std::size_t len = kBlockHeaderSize + tracks.size() * record;
  if (out.size() < len) return Status::kBufferTooSmall;

  BigEndianWriter w(out);
  w.u8(kCat062);
  w.field(static_cast<std::int64_t>(len), 2);
  for (const Cat062Track& t : tracks) {
    w.u8(kFspec1 | (src.has_service_id ? kFspec1ServiceId : 0u));
    w.u8(kFspec2);
    w.u8(kFspec3);
    w.u8(kFspec4);
    w.u8(src.sac);  // I062/010
    w.u8(src.sic);
    if (src.has_service_id) w.u8(src.service_id);  // I062/015
    w.field(t.tod_128, 3);                         // I062/070
    w.field(t.x_half_m, 3);                        // I062/100
    w.field(t.y_half_m, 3);
    w.field(t.vx_quarter_mps, 2);  // I062/185
    w.field(t.vy_quarter_mps, 2);
    w.field(t.track_number, 2);                                     // I062/040
    w.u8(kStatusMono | (t.tentative ? kStatusTentative : 0u));      // I062/080
    w.u8(kAccuracyApc);                                             // I062/500
    w.field(t.apc_x_half_m, 2);
    w.field(t.apc_y_half_m, 2);
  }
  written = w.size();
  return Status::kOk;
}

}  // namespace kestrel::hal::asterix
