// SPDX-License-Identifier: Apache-2.0
// ASTERIX recordings on the host: scenario plots written as CAT048 data
// blocks back to back (the .ast form `replay --asterix` reads), and such a
// recording read back to SI frames with the board's own feed
// (host::AsterixFileFeed over hal's CAT048 reader). Units are converted by
// hal/asterix_units.hpp only: RHO 1/256 NM, THETA 2^-16 turn clockwise from
// north, time of day 1/128 s, Doppler CAL 1 m/s.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "kestrel/host/asterix_file_feed.hpp"
#include "scenarios/scenario.hpp"

namespace kestrel::sim {

/// One CAT048 data block per frame, one record per plot: I048/010 (SAC =
/// `sac`, SIC = the plot's sensor_id), I048/140, I048/020 (single PSR),
/// I048/040 and, for a plot with a range rate, I048/120 CAL.
/// Throws std::out_of_range for a value CAT048 cannot carry: a time outside
/// [0, 86400) s after rounding to 1/128 s, a range over 65535/256 NM
/// (474.1 km), a range rate outside [-512, 511] m/s after rounding to 1 m/s;
/// and std::invalid_argument for a frame that is not radar.
std::vector<std::uint8_t> encode_cat048_stream(const std::vector<MeasurementFrame>& frames, std::uint8_t sac);

/// What reading a recording found (host::AsterixFileFeed's tallies and its
/// CAT048 reader's).
struct AsterixReadCounts {
  host::AsterixFeedCounters feed;
  hal::asterix::Cat048Counters reader;
};

/// Read a recording back to SI frames, one per poll of the feed (so indices
/// match the Runner's frame count): a poll that dropped bytes (unknown
/// category, malformed, truncated) becomes a placeholder with t_s = NaN and
/// no plots, counted in `skipped`.
std::vector<MeasurementFrame> decode_cat048_stream(const std::vector<std::uint8_t>& bytes, std::size_t& skipped,
                                                   AsterixReadCounts& counts);

}  // namespace kestrel::sim
