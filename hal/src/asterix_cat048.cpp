// SPDX-License-Identifier: Apache-2.0
// CAT048 record and block reader (asterix_cat048.hpp). Each item's length
// comes from the UAP table below before any of its bytes is read, and every
// length is checked against what is left of the record's block, so a wrong
// length can only produce kMalformedFrame. Loops run over FSPEC octets
// (at most 4), FRNs (28), subfields (at most 7) or the block's bytes.
#include "kestrel/hal/asterix_cat048.hpp"

#include <array>

#include "kestrel/hal/asterix_units.hpp"

namespace kestrel::hal::asterix {

namespace {

// Shapes of the ASTERIX item structures (Part 1, section 4.3).
enum class Shape : std::uint8_t {
  kFixed,        ///< `size` bytes.
  kExtended,     ///< Octets until one with FX (bit 1) clear.
  kRepetitive,   ///< REP (1 byte), then REP x `size` bytes.
  kExplicit,     ///< LEN (1 byte, counting itself), then LEN - 1 bytes.
  kCompound130,  ///< I048/130 subfields.
  kCompound120,  ///< I048/120 subfields.
};

struct ItemSpec {
  Shape shape;
  std::uint8_t size;
};

// CAT048 edition 1.31 UAP, index = FRN - 1.
constexpr std::size_t kUapItems = 28;
constexpr std::array<ItemSpec, kUapItems> kUap{{
    {Shape::kFixed, 2},         // 1  I048/010 data source identifier
    {Shape::kFixed, 3},         // 2  I048/140 time of day
    {Shape::kExtended, 0},      // 3  I048/020 target report descriptor
    {Shape::kFixed, 4},         // 4  I048/040 measured position, polar
    {Shape::kFixed, 2},         // 5  I048/070 Mode-3/A code
    {Shape::kFixed, 2},         // 6  I048/090 flight level
    {Shape::kCompound130, 0},   // 7  I048/130 radar plot characteristics
    {Shape::kFixed, 3},         // 8  I048/220 aircraft address
    {Shape::kFixed, 6},         // 9  I048/240 aircraft identification
    {Shape::kRepetitive, 8},    // 10 I048/250 BDS register data
    {Shape::kFixed, 2},         // 11 I048/161 track number
    {Shape::kFixed, 4},         // 12 I048/042 calculated position, Cartesian
    {Shape::kFixed, 4},         // 13 I048/200 calculated track velocity, polar
    {Shape::kExtended, 0},      // 14 I048/170 track status
    {Shape::kFixed, 4},         // 15 I048/210 track quality
    {Shape::kExtended, 0},      // 16 I048/030 warning/error conditions
    {Shape::kFixed, 2},         // 17 I048/080 Mode-3/A code confidence
    {Shape::kFixed, 4},         // 18 I048/100 Mode-C code and confidence
    {Shape::kFixed, 2},         // 19 I048/110 height measured by 3D radar
    {Shape::kCompound120, 0},   // 20 I048/120 radial Doppler speed
    {Shape::kFixed, 2},         // 21 I048/230 communications/ACAS capability
    {Shape::kFixed, 7},         // 22 I048/260 ACAS resolution advisory
    {Shape::kFixed, 1},         // 23 I048/055 Mode-1 code
    {Shape::kFixed, 2},         // 24 I048/050 Mode-2 code
    {Shape::kFixed, 1},         // 25 I048/065 Mode-1 code confidence
    {Shape::kFixed, 2},         // 26 I048/060 Mode-2 code confidence
    {Shape::kExplicit, 0},      // 27 SP special purpose field
    {Shape::kExplicit, 0},      // 28 RE reserved expansion field
}};
constexpr std::size_t kFrn010 = 1;
constexpr std::size_t kFrn140 = 2;
constexpr std::size_t kFrn040 = 4;
constexpr std::size_t kFrn161 = 11;
constexpr std::size_t kFrn120 = 20;
// 7 FRNs per FSPEC octet (bit 1 is FX): 28 FRNs need 4 octets.
constexpr std::size_t kMaxFspecOctets = (kUapItems + 6) / 7;
// LEN is 16 bits: no block, record or item is longer.
constexpr std::size_t kMaxBlockLen = 0xFFFF;

// A compound item's subfields in primary-subfield bit order (bit 8 first);
// a subfield of size 0 is repetitive with element size `rep`.
struct Subfield {
  std::uint8_t size;
  std::uint8_t rep;
};
// I048/130: SRL, SRR, SAM, PRL, PAM, RPD, APD, one octet each.
constexpr std::array<Subfield, 7> kSub130{{{1, 0}, {1, 0}, {1, 0}, {1, 0}, {1, 0}, {1, 0}, {1, 0}}};
// I048/120: CAL (2 octets), RDS (repetitive, 6 octets each); bits 6-2 spare.
constexpr std::array<Subfield, 2> kSub120{{{2, 0}, {0, 6}}};

constexpr std::size_t kNoFit = 0;  // "malformed" from the length functions.

// Length of an FX-extended field at the start of `in`, or kNoFit.
std::size_t extended_length(std::span<const std::uint8_t> in) {
  for (std::size_t i = 0; i < in.size() && i < kMaxBlockLen; ++i) {
    if ((in[i] & 0x01u) == 0) return i + 1;
  }
  return kNoFit;
}

// Length of a repetitive field (REP byte and REP elements), or kNoFit.
std::size_t repetitive_length(std::span<const std::uint8_t> in, std::size_t element) {
  if (in.empty()) return kNoFit;
  const std::size_t len = 1 + static_cast<std::size_t>(in[0]) * element;
  return len <= in.size() ? len : kNoFit;
}

// Length of a compound item whose primary subfield is one octet defining
// `subs` (spare bits and FX must be clear: further subfields have no
// length this edition defines), or kNoFit.
template <std::size_t kN>
std::size_t compound_length(std::span<const std::uint8_t> in, const std::array<Subfield, kN>& subs) {
  if (in.empty()) return kNoFit;
  const std::uint8_t primary = in[0];
  const auto defined = static_cast<std::uint8_t>(0xFFu << (8 - kN));
  if ((primary & static_cast<std::uint8_t>(~defined)) != 0) return kNoFit;
  std::size_t len = 1;
  for (std::size_t i = 0; i < kN; ++i) {
    if ((primary & (0x80u >> i)) == 0) continue;
    const std::span<const std::uint8_t> rest = in.subspan(len);
    const std::size_t sub = subs[i].size != 0 ? subs[i].size : repetitive_length(rest, subs[i].rep);
    if (sub == kNoFit || sub > rest.size()) return kNoFit;
    len += sub;
  }
  return len;
}

// Length of the item at the start of `in`, or kNoFit when it does not fit.
std::size_t item_length(const ItemSpec& spec, std::span<const std::uint8_t> in) {
  switch (spec.shape) {
    case Shape::kFixed: return spec.size <= in.size() ? spec.size : kNoFit;
    case Shape::kExtended: return extended_length(in);
    case Shape::kRepetitive: return repetitive_length(in, spec.size);
    case Shape::kExplicit: return (!in.empty() && in[0] != 0 && in[0] <= in.size()) ? in[0] : kNoFit;
    case Shape::kCompound130: return compound_length(in, kSub130);
    case Shape::kCompound120: return compound_length(in, kSub120);
  }
  return kNoFit;
}

std::uint16_t be16(std::span<const std::uint8_t> b, std::size_t at) {
  return static_cast<std::uint16_t>((b[at] << 8) | b[at + 1]);
}

// The fields a radar frame carries; `item` has the length item_length gave.
void decode_item(std::size_t frn, std::span<const std::uint8_t> item, Cat048Record& rec) {
  switch (frn) {
    case kFrn010:
      rec.has_source = true;
      rec.sac = item[0];
      rec.sic = item[1];
      return;
    case kFrn140:
      rec.has_time = true;
      rec.tod_128 = (static_cast<std::uint32_t>(item[0]) << 16) | (static_cast<std::uint32_t>(item[1]) << 8) | item[2];
      return;
    case kFrn040:
      rec.has_polar = true;
      rec.rho_256nm = be16(item, 0);
      rec.theta = be16(item, 2);
      return;
    case kFrn161:
      rec.has_track_number = true;
      rec.track_number = static_cast<std::uint16_t>(be16(item, 0) & 0x0FFFu);
      return;
    case kFrn120:
      // CAL is the first subfield when bit 8 of the primary is set: D (bit
      // 16) marks it doubtful, the value is 10-bit two's complement.
      if ((item[0] & 0x80u) != 0) {
        const std::uint16_t cal = be16(item, 1);
        rec.has_doppler = (cal & 0x8000u) == 0;
        const auto raw = static_cast<std::int16_t>(cal & 0x03FFu);
        rec.doppler_mps = static_cast<std::int16_t>(raw >= 512 ? raw - 1024 : raw);
      }
      return;
    default: return;
  }
}

}  // namespace

Status decode_cat048_record(std::span<const std::uint8_t> in, Cat048Record& rec, std::size_t& consumed) {
  consumed = 0;
  rec = Cat048Record{};
  std::array<std::uint8_t, kMaxFspecOctets> fspec{};
  std::size_t pos = 0;
  for (std::size_t i = 0; i < kMaxFspecOctets; ++i) {
    if (pos >= in.size()) return Status::kMalformedFrame;
    fspec[i] = in[pos++];
    if ((fspec[i] & 0x01u) == 0) break;
    if (i + 1 == kMaxFspecOctets) return Status::kMalformedFrame;  // FX past the UAP's last FRN
  }
  for (std::size_t frn = 1; frn <= kUapItems; ++frn) {
    const std::size_t octet = (frn - 1) / 7;
    const auto bit = static_cast<std::uint8_t>(0x80u >> ((frn - 1) % 7));
    if ((fspec[octet] & bit) == 0) continue;
    const std::span<const std::uint8_t> rest = in.subspan(pos);
    const std::size_t len = item_length(kUap[frn - 1], rest);
    if (len == kNoFit || len > rest.size()) return Status::kMalformedFrame;
    decode_item(frn, rest.first(len), rec);
    pos += len;
  }
  consumed = pos;
  return Status::kOk;
}

Status Cat048Reader::open(std::span<const std::uint8_t> bytes, std::size_t& block_len) {
  block_len = 0;
  records_ = {};
  malformed_ = false;
  if (bytes.size() < kBlockHeaderSize) return Status::kTruncated;
  const std::size_t len = be16(bytes, 1);
  if (len < kBlockHeaderSize) return Status::kMalformedFrame;
  block_len = len;
  if (bytes.size() < len) return Status::kTruncated;
  if (bytes[0] != kCat048) return Status::kUnknownKind;
  records_ = bytes.subspan(kBlockHeaderSize, len - kBlockHeaderSize);
  ++counters_.blocks;
  return Status::kOk;
}

Status Cat048Reader::next(Frame& out) {
  out.kind = FrameKind::kRadar;
  out.count = 0;
  out.t_us = 0;
  if (malformed_) {
    malformed_ = false;
    records_ = {};
    return Status::kMalformedFrame;
  }
  Cat048Record first{};
  bool over_capacity = false;
  // Each pass consumes one record (at least one FSPEC byte), so the block's
  // length bounds the loop.
  for (std::size_t i = 0; i < kMaxBlockLen && !records_.empty(); ++i) {
    Cat048Record rec{};
    std::size_t used = 0;
    if (decode_cat048_record(records_, rec, used) != Status::kOk) {
      if (out.count == 0) {
        records_ = {};
        return Status::kMalformedFrame;
      }
      malformed_ = true;  // deliver the plots read so far first
      break;
    }
    if (!rec.has_time || !rec.has_polar) {
      ++counters_.records;
      ++counters_.skipped_no_plot;
      records_ = records_.subspan(used);
      continue;
    }
    if (out.count != 0 && (rec.tod_128 != first.tod_128 || rec.sac != first.sac || rec.sic != first.sic ||
                           rec.has_source != first.has_source)) {
      break;  // the record starts the next frame; leave it unread
    }
    ++counters_.records;
    records_ = records_.subspan(used);
    if (out.count == 0) {
      first = rec;
      out.t_us = t_us_from_time_of_day(rec.tod_128);
    }
    if (out.count >= kMaxRadarPlots) {
      over_capacity = true;
      ++counters_.dropped_over_capacity;
      continue;
    }
    RadarPlot& p = out.radar[out.count++];
    p.range_mm = range_mm_from_rho(rec.rho_256nm);
    p.bearing_bam = bearing_bam_from_azimuth(rec.theta);
    p.range_rate_mmps = rec.has_doppler ? static_cast<std::int32_t>(rec.doppler_mps) * 1000 : 0;
    p.snr_cdb = 0;  // CAT048 carries amplitudes (I048/130), not an SNR
    p.has_range_rate = static_cast<std::uint8_t>(rec.has_doppler ? 1 : 0);
    p.sensor_id = rec.sic;
    ++counters_.plots;
  }
  if (out.count == 0) return Status::kNoData;
  return over_capacity ? Status::kTooManyCandidates : Status::kOk;
}

}  // namespace kestrel::hal::asterix
