// SPDX-License-Identifier: Apache-2.0
#include "metrics/track_continuity.hpp"

#include <algorithm>
#include <limits>

namespace kestrel::sim {

TrackContinuity compute_track_continuity(std::span<const OnTargetTracks> steps) {
  TrackContinuity c;
  std::vector<std::uint32_t> seen;
  bool confirmed = false;
  for (const OnTargetTracks& s : steps) {
    confirmed = confirmed || !s.ids.empty();
    if (!confirmed) continue;
    ++c.frames_after_confirmation;
    if (s.ids.size() == 1) ++c.held_frames;
    for (const std::uint32_t id : s.ids) {
      if (std::find(seen.begin(), seen.end(), id) == seen.end()) seen.push_back(id);
    }
  }
  c.track_ids_on_target = seen.size();
  c.held_fraction = c.frames_after_confirmation > 0
                        ? static_cast<double>(c.held_frames) / static_cast<double>(c.frames_after_confirmation)
                        : std::numeric_limits<double>::quiet_NaN();
  return c;
}

}  // namespace kestrel::sim
