// SPDX-License-Identifier: Apache-2.0
// Pure encode/decode of frames to and from the versioned wire format of
// frame_format.hpp. No I/O, no allocation; every malformed input yields a
// status (host-tested and fuzzed), never a crash or a partial write to `out`
// beyond what the status documents.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "kestrel/hal/frame.hpp"
#include "kestrel/status.hpp"

namespace kestrel::hal {

/// Encode `frame` into `out`.
/// @param written bytes written on kOk, 0 otherwise.
/// @return kOk; kUnknownKind; kTooManyCandidates (count over the kind's
///         capacity); kMalformedFrame (a field decode would refuse:
///         has_range_rate not 0/1, path not a ToaPath); kBufferTooSmall.
[[nodiscard]] Status encode(const Frame& frame, std::span<std::uint8_t> out, std::size_t& written);

/// Decode one frame from the start of `in`.
/// @param consumed bytes the caller should drop from its input: the whole
///        frame when its header was readable (even if it then failed CRC or
///        content checks), 1 for kBadMagic and for a header whose payload_len
///        exceeds wire::kMaxPayloadBytes (kMalformedFrame: the length cannot
///        be real, so resynchronise byte by byte rather than skip it), 0 for
///        kTruncated (wait for more bytes).
/// @return kOk; kTruncated; kBadMagic; kUnsupportedVersion; kUnknownKind;
///         kMalformedFrame (length inconsistent with count, bad enum value,
///         reserved bits set); kBadCrc; kTooManyCandidates (count over
///         capacity: `out` holds the first capacity items and is usable).
[[nodiscard]] Status decode(std::span<const std::uint8_t> in, Frame& out, std::size_t& consumed);

}  // namespace kestrel::hal
