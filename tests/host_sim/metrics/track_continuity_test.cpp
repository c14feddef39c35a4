// SPDX-License-Identifier: Apache-2.0
// The track-continuity figures on hand-made sequences: frames before the
// first on-target track are not counted, a frame with none or two tracks
// on the target is not held, and every distinct id counts once.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "metrics/track_continuity.hpp"

using namespace kestrel::sim;  // NOLINT(google-build-using-namespace)

SCENARIO("Track continuity counts held frames from the first confirmation", "[host_sim][metrics][continuity]") {
  GIVEN("two frames without a track, then one track held for three frames") {
    const std::vector<OnTargetTracks> steps{{{}, {}}, {{}, {}}, {{7}, {}}, {{7}, {}}, {{7}, {}}};
    const TrackContinuity c = compute_track_continuity(steps);
    THEN("all three frames after confirmation are held by one id") {
      CHECK(c.frames_after_confirmation == 3);
      CHECK(c.held_frames == 3);
      CHECK(c.held_fraction == 1.0);
      CHECK(c.track_ids_on_target == 1);
    }
  }
  GIVEN("a track that is lost for a frame and restarted under a new id") {
    const std::vector<OnTargetTracks> steps{{{3}, {}}, {{3}, {}}, {{}, {}}, {{4}, {}}};
    const TrackContinuity c = compute_track_continuity(steps);
    THEN("the lost frame is not held and two ids were on the target") {
      CHECK(c.frames_after_confirmation == 4);
      CHECK(c.held_frames == 3);
      CHECK(c.held_fraction == 0.75);
      CHECK(c.track_ids_on_target == 2);
    }
  }
  GIVEN("a split: two confirmed tracks on the target in one frame") {
    const std::vector<OnTargetTracks> steps{{{1}, {}}, {{1, 2}, {}}, {{1}, {}}, {{1}, {}}};
    const TrackContinuity c = compute_track_continuity(steps);
    THEN("that frame is not held") {
      CHECK(c.held_frames == 3);
      CHECK(c.held_fraction == 0.75);
      CHECK(c.track_ids_on_target == 2);
    }
  }
  GIVEN("confirmed tracks beyond L: one that later reaches the target, one that never does") {
    const std::vector<OnTargetTracks> steps{{{}, {5, 6}}, {{1}, {5, 6}}, {{5}, {6}}, {{5}, {}}};
    const TrackContinuity c = compute_track_continuity(steps);
    THEN("only the one never on the target is false, counted once") {
      CHECK(c.false_tracks == 1);
      CHECK(c.track_ids_on_target == 2);
    }
  }
  GIVEN("no track ever on the target") {
    const std::vector<OnTargetTracks> steps{{{}, {}}, {{}, {}}};
    const TrackContinuity c = compute_track_continuity(steps);
    THEN("nothing is counted and the fraction is NaN") {
      CHECK(c.frames_after_confirmation == 0);
      CHECK(std::isnan(c.held_fraction));
      CHECK(c.track_ids_on_target == 0);
    }
  }
}
