// SPDX-License-Identifier: Apache-2.0
// MeasurementFeed: where frames come from (UART ring buffer on a board, a
// stream file on the host, a scripted fake in tests). poll() never blocks:
// it returns kNoData when no complete frame is available yet.
#pragma once

#include <concepts>

#include "kestrel/hal/frame.hpp"
#include "kestrel/status.hpp"

namespace kestrel::hal {

/// poll(frame) -> kOk (frame filled); kTooManyCandidates (frame filled with
/// its first capacity items: usable, the excess dropped); kNoData (nothing
/// yet, frame untouched); or a decode status (kBadCrc, kBadMagic, ...) for
/// bytes that were read and dropped: the feed has already skipped past them.
template <class F>
concept MeasurementFeed = requires(F& feed, Frame& frame) {
  { feed.poll(frame) } -> std::same_as<Status>;
};

}  // namespace kestrel::hal
