// SPDX-License-Identifier: Apache-2.0
// Sets of measurement channels: bit i is channel i of a measurement vector.
// A frame says which channels it carries (an underwater frame: which beacon
// and path arrived) and a gate may drop more; a filter fuses exactly the
// channels left (Ekf::update with a mask), and its diagnostics say per
// channel what happened.
#pragma once

#include <cstdint>

namespace kestrel {

/// Set of channels of a measurement vector: bit i is channel i.
using ChannelMask = std::uint32_t;

/// Mask with channels 0 .. n-1 set.
constexpr ChannelMask all_channels(int n) {
  return n >= 32 ? ~ChannelMask{0} : ((ChannelMask{1} << n) - 1u);
}
constexpr bool has_channel(ChannelMask m, int ch) { return ((m >> ch) & 1u) != 0u; }
constexpr ChannelMask with_channel(ChannelMask m, int ch) { return m | (ChannelMask{1} << ch); }
constexpr ChannelMask without_channel(ChannelMask m, int ch) { return m & ~(ChannelMask{1} << ch); }
/// Number of set bits (bounded loop over the 32 bits).
constexpr int channel_count(ChannelMask m) {
  int n = 0;
  for (int i = 0; i < 32; ++i) n += static_cast<int>((m >> i) & 1u);
  return n;
}

}  // namespace kestrel
