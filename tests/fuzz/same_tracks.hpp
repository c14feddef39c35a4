// "Unchanged" for the generic Tracker (tracking/tracker.hpp) in tests and
// fuzz harnesses: two trackers' tables agree in everything observable.
#pragma once

#include <cstddef>

#include "kestrel/tracking/track.hpp"

namespace kestrel::test {

/// Everything observable about two trackers' tables is the same (status,
/// id, counters, history, time, x and P of every slot).
template <class Tracker>
bool same_tracks(const Tracker& a, const Tracker& b) {
  for (std::size_t i = 0; i < a.tracks().capacity(); ++i) {
    const auto& ta = a.tracks()[i];
    const auto& tb = b.tracks()[i];
    if (ta.status != tb.status || ta.id != tb.id || ta.initialised != tb.initialised || ta.age != tb.age ||
        ta.hits != tb.hits || ta.misses != tb.misses || ta.history != tb.history || ta.t_us != tb.t_us) {
      return false;
    }
    if (ta.status != TrackStatus::kFree && ta.initialised &&
        (ta.filter.x() != tb.filter.x() || ta.filter.P() != tb.filter.P())) {
      return false;
    }
  }
  return true;
}

}  // namespace kestrel::test
