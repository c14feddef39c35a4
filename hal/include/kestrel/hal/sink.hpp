// SPDX-License-Identifier: Apache-2.0
// TrackSink: where track reports go (UART/CAN on a board, CSV/JSON files on
// the host, a recording fake in tests). publish() must not block for long:
// a board sink copies into a TX buffer and returns kTableFull when it is full.
#pragma once

#include <concepts>

#include "kestrel/status.hpp"

namespace kestrel::hal {

/// Report is the core's TrackReport for the tracker being driven.
template <class S, class Report>
concept TrackSink = requires(S& sink, const Report& report) {
  { sink.publish(report) } -> std::same_as<Status>;
};

}  // namespace kestrel::hal
