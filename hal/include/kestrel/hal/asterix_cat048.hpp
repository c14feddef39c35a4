// SPDX-License-Identifier: Apache-2.0
// Reader of ASTERIX CAT048 (monoradar target reports, EUROCONTROL ASTERIX
// Part 4, edition 1.31 UAP) into Kestrel radar frames. A data block is
// CAT (1 byte), LEN (2 bytes, big-endian, the whole block) and records; a
// record is an FSPEC (FX-extended) and the items it announces in UAP order.
// Every item of the UAP is skipped by its length (fixed, FX-extended,
// repetitive, compound, explicit); I048/010, /140, /040 and /120 CAL are
// decoded. Consecutive plots of one block with the same SAC/SIC and time of
// day become one frame (docs/asterix.md). No heap; every loop is bounded by
// the block's length; malformed input is a status, never a read past it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "kestrel/hal/asterix_units.hpp"
#include "kestrel/hal/frame.hpp"
#include "kestrel/status.hpp"

namespace kestrel::hal::asterix {

inline constexpr std::uint8_t kCat048 = 48;

/// What one CAT048 record says that a radar frame can carry; the other
/// items are checked for length and skipped. Fields in ASTERIX units.
struct Cat048Record {
  bool has_source = false;        ///< I048/010 present.
  std::uint8_t sac = 0;           ///< System area code.
  std::uint8_t sic = 0;           ///< System identification code.
  bool has_time = false;          ///< I048/140 present.
  std::uint32_t tod_128 = 0;      ///< Time of day, 1/128 s since midnight.
  bool has_polar = false;         ///< I048/040 present.
  std::uint16_t rho_256nm = 0;    ///< Slant range, 1/256 NM.
  std::uint16_t theta = 0;        ///< Azimuth, clockwise from north, 2^16 per turn.
  bool has_track_number = false;  ///< I048/161 present.
  std::uint16_t track_number = 0; ///< Radar's track number, 12 bits.
  bool has_doppler = false;       ///< I048/120 subfield CAL present and D (doubtful) clear.
  std::int16_t doppler_mps = 0;   ///< Calculated Doppler speed, m/s, 10-bit two's complement.
};

/// Decode one record from the start of `in` (the rest of its data block).
/// @param consumed the record's length in bytes on kOk, else 0.
/// @return kOk; kMalformedFrame (FSPEC or an item runs past `in`, FSPEC
///         longer than the UAP, a compound item announcing subfields the
///         edition does not define, an explicit length of 0, an empty input).
[[nodiscard]] Status decode_cat048_record(std::span<const std::uint8_t> in, Cat048Record& rec,
                                          std::size_t& consumed);

/// Tallies of a reader since construction, for a board's health counters.
struct Cat048Counters {
  std::uint32_t blocks = 0;             ///< Blocks opened (kOk from open()).
  std::uint32_t records = 0;            ///< Records decoded.
  std::uint32_t plots = 0;              ///< Plots placed in frames.
  std::uint32_t skipped_no_plot = 0;    ///< Records without I048/140 or I048/040.
  std::uint32_t dropped_over_capacity = 0;  ///< Plots beyond kMaxRadarPlots in a group.
};

/// Turns CAT048 data blocks into radar frames, one block at a time:
/// open() a block, then call next() until it returns kNoData or an error.
/// The reader refers to the caller's bytes between open() and the last
/// next(); it copies nothing.
class Cat048Reader {
 public:
  /// Start reading the data block at the start of `bytes`.
  /// @param block_len LEN of the block when its header is readable and
  ///        LEN >= 3 (the caller can skip that many bytes after any status
  ///        but kTruncated), else 0.
  /// @return kOk; kTruncated (fewer than 3 bytes, or fewer than LEN: wait
  ///         for more); kMalformedFrame (LEN < 3: the length cannot be real,
  ///         so the block cannot be skipped); kUnknownKind (CAT is not 48:
  ///         skip block_len bytes).
  [[nodiscard]] Status open(std::span<const std::uint8_t> bytes, std::size_t& block_len);

  /// The next frame of the open block: the following plot records with the
  /// same SAC/SIC and time of day (records without time or position are
  /// skipped and counted).
  /// @param out a radar frame with at least one plot on kOk and
  ///        kTooManyCandidates; count 0 after any other status.
  /// @return kOk; kNoData (block finished, or none open); kTooManyCandidates
  ///         (the group held more than kMaxRadarPlots plots: `out` holds the
  ///         first ones and is usable, the rest were dropped and counted);
  ///         kMalformedFrame (a record is malformed: records after it cannot
  ///         be found, so the rest of the block is dropped; plots of the
  ///         same group read before it were returned by the previous call).
  [[nodiscard]] Status next(Frame& out);

  [[nodiscard]] const Cat048Counters& counters() const { return counters_; }

 private:
  std::span<const std::uint8_t> records_{};  ///< Unread records of the open block.
  bool malformed_ = false;                   ///< A malformed record waits to be reported.
  Cat048Counters counters_{};
};

}  // namespace kestrel::hal::asterix
