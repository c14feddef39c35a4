// SPDX-License-Identifier: Apache-2.0
// "Unchanged" for the generic Tracker (tracking/tracker.hpp) in tests and
// fuzz harnesses: two trackers' tables agree in everything observable; and
// the invariants every fuzz harness of a Tracker checks after a step.
#pragma once

#include <cstddef>

#include "kestrel/math/finite.hpp"
#include "kestrel/math/positive_definite.hpp"
#include "kestrel/status.hpp"
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

/// After tracker.step() returned `s` from the state `before`: a refused
/// frame published nothing and changed no track; every report and every
/// initialised track has a finite state and a positive definite P.
/// @return nullptr, or what broke.
template <class Tracker>
const char* step_invariant_broken(const Tracker& tracker, const Tracker& before, Status s) {
  if (s != Status::kOk) {
    if (!tracker.reports().empty()) return "a refused frame published reports";
    if (!same_tracks(tracker, before)) return "a refused frame changed a track";
  }
  for (const auto& rep : tracker.reports()) {
    if (!all_finite(rep.x)) return "a reported state is not finite";
    if (!is_positive_definite(rep.P)) return "a reported covariance is not positive definite";
  }
  for (const std::size_t i : tracker.tracks().active_slots()) {
    const auto& tr = tracker.tracks()[i];
    if (!tr.initialised) continue;
    if (!all_finite(tr.filter.x())) return "a track holds a state that is not finite";
    if (!is_positive_definite(tr.filter.P())) return "a track holds a covariance that is not positive definite";
  }
  return nullptr;
}

}  // namespace kestrel::test
