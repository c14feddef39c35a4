// SPDX-License-Identifier: Apache-2.0
// MemorySink: a TrackSink (hal/sink.hpp) that keeps every report in memory
// for scoring. Its capacity is fixed when it is built and publish() never
// allocates: a full sink refuses with kTableFull, as a board's TX buffer
// would. So a whole run through the Runner stays allocation-free (tests
// assert it) and a run can never grow memory without bound.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "kestrel/status.hpp"

namespace kestrel::host {

template <class Report>
class MemorySink {
 public:
  /// @param capacity reports the sink can hold (allocated here, once).
  explicit MemorySink(std::size_t capacity) { reports_.reserve(capacity); }

  /// @return kOk; kTableFull when the capacity is used up (report dropped).
  [[nodiscard]] Status publish(const Report& report) {
    if (reports_.size() == reports_.capacity()) return Status::kTableFull;
    reports_.push_back(report);
    return Status::kOk;
  }

  std::span<const Report> reports() const { return reports_; }
  std::size_t size() const { return reports_.size(); }
  std::size_t capacity() const { return reports_.capacity(); }
  void clear() { reports_.clear(); }

 private:
  std::vector<Report> reports_;
};

}  // namespace kestrel::host
