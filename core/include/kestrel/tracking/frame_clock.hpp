// SPDX-License-Identifier: Apache-2.0
// The clock of a tracker's accepted frames and its time-fault rules, one
// copy for every tracker (Tracker, SonarTracker):
//   - a frame earlier than the last accepted one is refused
//     (kTimeWentBackwards), and one later by more than max_forward_jump_us
//     is refused (kTimeJumpedForward): a single corrupted time blocks
//     nothing;
//   - a sensor whose clock really moved (a reset, a long stall) sends a run
//     of frames consistent with each other (each at or after the previous,
//     within max_forward_jump_us of it); after resync_frames of them the
//     tracker may take the new clock (0: never).
// Differences are taken without overflow for any int64 frame times
// (elapsed_us).
#pragma once

#include <cstdint>

#include "kestrel/status.hpp"
#include "kestrel/tracking/elapsed.hpp"

namespace kestrel {

class FrameClock {
 public:
  FrameClock() = default;
  FrameClock(std::int64_t max_forward_jump_us, std::uint8_t resync_frames)
      : max_forward_jump_us_(max_forward_jump_us), resync_frames_(resync_frames) {}

  /// A frame time against the last accepted one: kOk (or no clock yet),
  /// kTimeWentBackwards or kTimeJumpedForward.
  Status check(std::int64_t t_us) const {
    if (!have_time_) return Status::kOk;
    if (t_us < last_t_us_) return Status::kTimeWentBackwards;
    if (elapsed_us(t_us, last_t_us_) > max_forward_jump_us_) return Status::kTimeJumpedForward;
    return Status::kOk;
  }

  /// Count a well-formed frame refused for its time. Consecutive ones on one
  /// consistent clock add up; one that is not consistent with the previous
  /// starts the count again.
  /// @return true when the count reaches resync_frames: the caller may take
  ///   this frame's clock (accept(t_us, true)).
  bool off_clock(std::int64_t t_us) {
    const bool consistent = off_clock_count_ > 0 && t_us >= off_clock_t_us_ &&
                            elapsed_us(t_us, off_clock_t_us_) <= max_forward_jump_us_;
    off_clock_count_ = consistent ? static_cast<std::uint8_t>(off_clock_count_ < UINT8_MAX ? off_clock_count_ + 1 : off_clock_count_)
                                  : std::uint8_t{1};
    off_clock_t_us_ = t_us;
    return resync_frames_ > 0 && off_clock_count_ >= resync_frames_;
  }

  /// Take t_us as the time of the last accepted frame; `resynced`: it
  /// replaced the old clock by the resync rule (counted in resyncs()).
  void accept(std::int64_t t_us, bool resynced = false) {
    last_t_us_ = t_us;
    have_time_ = true;
    off_clock_count_ = 0;
    if (resynced) ++resyncs_;
  }

  bool has_time() const { return have_time_; }
  /// Time of the last accepted frame, us (valid when has_time()).
  std::int64_t last_us() const { return last_t_us_; }
  /// Clock changes taken by the resync rule so far.
  std::uint32_t resyncs() const { return resyncs_; }

 private:
  std::int64_t max_forward_jump_us_ = 600'000'000;
  std::uint8_t resync_frames_ = 3;
  std::int64_t last_t_us_ = 0;
  bool have_time_ = false;
  std::int64_t off_clock_t_us_ = 0;   ///< Time of the last frame refused for its time.
  std::uint8_t off_clock_count_ = 0;  ///< Consecutive consistent ones.
  std::uint32_t resyncs_ = 0;
};

}  // namespace kestrel
