// SPDX-License-Identifier: Apache-2.0
#include "metrics/track_continuity.hpp"

#include <algorithm>
#include <limits>

namespace kestrel::sim {

TrackContinuity compute_track_continuity(std::span<const OnTargetTracks> steps) {
  TrackContinuity c;
  std::vector<std::uint32_t> seen;
  std::vector<std::uint32_t> off;
  bool confirmed = false;
  for (const OnTargetTracks& s : steps) {
    for (const std::uint32_t id : s.off_ids) {
      if (std::find(off.begin(), off.end(), id) == off.end()) off.push_back(id);
    }
    confirmed = confirmed || !s.ids.empty();
    if (!confirmed) continue;
    ++c.frames_after_confirmation;
    if (s.ids.size() == 1) ++c.held_frames;
    for (const std::uint32_t id : s.ids) {
      if (std::find(seen.begin(), seen.end(), id) == seen.end()) seen.push_back(id);
    }
  }
  c.track_ids_on_target = seen.size();
  c.false_tracks = static_cast<std::size_t>(std::count_if(off.begin(), off.end(), [&](std::uint32_t id) {
    return std::find(seen.begin(), seen.end(), id) == seen.end();
  }));
  c.held_fraction = c.frames_after_confirmation > 0
                        ? static_cast<double>(c.held_frames) / static_cast<double>(c.frames_after_confirmation)
                        : std::numeric_limits<double>::quiet_NaN();
  return c;
}

}  // namespace kestrel::sim
