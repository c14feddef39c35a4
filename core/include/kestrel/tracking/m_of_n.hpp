// SPDX-License-Identifier: Apache-2.0
// M-of-N track management: a tentative track is confirmed once M of its
// first N frames brought a measurement (the frame that started it counts as
// the first), and deleted as soon as M can no longer be reached within
// those N frames; a confirmed track is deleted after more than
// max_coast_misses frames in a row without one. Parameters: confirm_m,
// confirm_n and max_coast_misses of TrackerConfig.
#pragma once

#include <bit>
#include <cstdint>

#include "kestrel/tracking/track.hpp"

namespace kestrel {

template <class Scalar>
class MOfN {
 public:
  /// hit() ignores the innovation: the tracker computes none for it.
  static constexpr bool kScoresInnovations = false;

  template <class Config>
  void configure(const Config& c) {
    m_ = c.confirm_m;
    n_ = c.confirm_n;
    max_coast_misses_ = c.max_coast_misses;
  }

  /// A track starts (M-of-N keeps its evidence in Track::history).
  template <class TrackT>
  void start(TrackT&) const {}

  /// A measurement was folded into the track (counted by history).
  template <class TrackT, class Innov>
  void hit(TrackT&, const Innov&) const {}

  /// The frame's verdict, after the tracker has shifted `hit` into
  /// tr.history and counted tr.age and tr.misses.
  template <class TrackT>
  TrackVerdict judge(TrackT& tr, bool /*hit*/) const {
    if (tr.status == TrackStatus::kTentative) {
      // The window is anchored at the track's start: hits so far + frames
      // left < M means M is out of reach.
      const std::uint8_t window = static_cast<std::uint8_t>(n_ >= 8 ? 0xFFu : (1u << n_) - 1u);
      const int recent = std::popcount(static_cast<unsigned>(tr.history & window));
      const int frames_so_far = tr.age + 1;
      const int frames_left = frames_so_far >= n_ ? 0 : n_ - frames_so_far;
      if (recent >= m_) return TrackVerdict::kConfirm;
      if (recent + frames_left < m_) return TrackVerdict::kDelete;
      return TrackVerdict::kKeep;
    }
    return tr.misses > max_coast_misses_ ? TrackVerdict::kDelete : TrackVerdict::kKeep;
  }

 private:
  std::uint8_t m_ = 2;
  std::uint8_t n_ = 3;
  std::uint16_t max_coast_misses_ = 5;
};

}  // namespace kestrel
