// SPDX-License-Identifier: Apache-2.0
// Stream files: wire frames back to back (hal/frame_format.hpp), encoded
// with hal::encode, the same function a sensor front end would use. This is
// the byte stream StreamFileFeed reads back.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "kestrel/hal/frame.hpp"
#include "scenarios/scenario.hpp"

namespace kestrel::sim {

/// Append `wire`, encoded with hal::encode, to `bytes`: the one encoder of
/// every sensor kind's stream. Throws std::runtime_error (naming the frame's
/// time) if it cannot be encoded.
void append_encoded(const hal::Frame& wire, std::vector<std::uint8_t>& bytes);

/// Quantise and encode every radar frame, in order (append_encoded).
std::vector<std::uint8_t> encode_stream(const std::vector<MeasurementFrame>& frames);

/// Write bytes to a file (created or truncated). Throws std::runtime_error.
void write_bytes(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes);

/// Decode a whole stream back to SI frames, one per frame the feed yields
/// (so indices match the Runner's frame count): a frame that did not decode
/// becomes a placeholder with t_s = NaN and no plots, and is counted in
/// `skipped`. Used by `replay --stream` for the measurement columns.
std::vector<MeasurementFrame> decode_stream(const std::vector<std::uint8_t>& bytes, std::size_t& skipped);

}  // namespace kestrel::sim
