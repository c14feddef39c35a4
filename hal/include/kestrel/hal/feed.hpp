// MeasurementFeed: where frames come from (UART ring buffer on a board, a
// stream file on the host, a scripted fake in tests). poll() never blocks:
// it returns kNoData when no complete frame is available yet.
#pragma once

#include <concepts>

#include "kestrel/hal/frame.hpp"
#include "kestrel/status.hpp"

namespace kestrel::hal {

/// poll(frame) -> kOk (frame filled), kNoData (nothing yet, frame untouched),
/// or a decode status (kBadCrc, kTruncated, ...) for a frame that was read
/// and dropped; the feed has then already skipped past it.
template <class F>
concept MeasurementFeed = requires(F& feed, Frame& frame) {
  { feed.poll(frame) } -> std::same_as<Status>;
};

}  // namespace kestrel::hal
