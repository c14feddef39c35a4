// SPDX-License-Identifier: Apache-2.0
// Track management for one labelled target (the sonar, paper 003): the
// track is confirmed when it starts (a multilateration fix is already the
// evidence M-of-N would wait for) and never deleted for missing data; a
// long dropout is the tracker's stale rule. Instead it is restarted when
// lost: a frame that carried at least min_arrivals channels but whose
// update fused at most half of them means the gate has locked onto a wrong
// estimate and throws the data away (a track on the target drops a good
// channel with probability about 0.05 at k = 2). After lost_frames such
// frames in a row the verdict is TrackVerdict::kRestart: the tracker starts
// the track again from that frame's plot and keeps the start if it fuses
// more of it.
#pragma once

#include <cstdint>

#include "kestrel/filters/channels.hpp"
#include "kestrel/tracking/track.hpp"

namespace kestrel {

struct ReacquireWhenLostParams {
  std::uint8_t min_arrivals = 4;    ///< Frames with fewer channels never count as lost.
  std::uint16_t lost_frames = 3;    ///< Lost frames in a row that restart the track (0: never).
};

template <class Scalar>
class ReacquireWhenLost {
 public:
  static constexpr bool kScoresInnovations = false;

  ReacquireWhenLost() = default;
  explicit ReacquireWhenLost(const ReacquireWhenLostParams& p) : params_(p) {}

  template <class Config>
  void configure(const Config&) const {}

  template <class TrackT>
  void start(TrackT& tr) const {
    tr.lost_frames = 0;
  }

  template <class TrackT, class Innov>
  void hit(TrackT&, const Innov&) const {}

  template <class TrackT>
  TrackVerdict judge(TrackT& tr, bool /*hit*/) const {
    if (tr.status == TrackStatus::kTentative) return TrackVerdict::kConfirm;
    if (tr.measurement_index < 0) return TrackVerdict::kKeep;  // nothing offered this frame
    const auto& d = tr.filter.diagnostics();
    const int arrivals = channel_count(d.present);
    const int fused = channel_count(d.fused_channels);
    if (arrivals < static_cast<int>(params_.min_arrivals) || 2 * fused > arrivals) {
      tr.lost_frames = 0;
      return TrackVerdict::kKeep;
    }
    if (tr.lost_frames < UINT16_MAX) ++tr.lost_frames;
    if (params_.lost_frames > 0 && tr.lost_frames >= params_.lost_frames) return TrackVerdict::kRestart;
    return TrackVerdict::kKeep;
  }

  const ReacquireWhenLostParams& params() const { return params_; }

 private:
  ReacquireWhenLostParams params_{};
};

}  // namespace kestrel
