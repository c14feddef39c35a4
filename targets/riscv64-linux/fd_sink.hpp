// SPDX-License-Identifier: Apache-2.0
// TrackSink of the riscv64-linux board: each report becomes one KTRK v2
// record (targets/common/include/kestrel/board/ktrk_record.hpp, the record
// every board emits) in a fixed buffer of kSinkRecords records, written to a
// file descriptor (a file, stdout, a pipe or the serial device) by flush(),
// which the loop calls once per frame. publish() never waits: with the
// buffer full it flushes first, and if the descriptor takes nothing (a
// non-blocking device that is full) it drops the report and returns
// kTableFull (the runner counts publish_failures). Bytes the descriptor
// does not take stay buffered, in order, so the stream never loses part of
// a record.
#pragma once

#include <array>
#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <span>

#include "board_config.hpp"
#include "kestrel/board/ktrk_record.hpp"
#include "kestrel/status.hpp"
#include "kestrel/tracking/track.hpp"
#include "linux_syscall.hpp"

namespace kestrel::rv64 {

class FdTrackSink {
 public:
  /// Write to `fd` from now on (-1: discard every report, counting none as dropped).
  void attach(int fd) { fd_ = fd; }

  template <class Filter>
  [[nodiscard]] Status publish(const TrackReport<Filter>& report) {
    if (fd_ < 0) return Status::kOk;
    if (buffer_.size() - used_ < board::report_record::kSize) flush();
    if (buffer_.size() - used_ < board::report_record::kSize) {
      ++dropped_;
      return Status::kTableFull;
    }
    board::encode_track_record(report,
                               std::span<std::uint8_t, board::report_record::kSize>(buffer_.data() + used_,
                                                                                    board::report_record::kSize));
    used_ += board::report_record::kSize;
    return Status::kOk;
  }

  /// Write the buffered records; what the descriptor does not take now
  /// stays buffered for the next call.
  void flush() {
    std::size_t written = 0;
    while (fd_ >= 0 && written < used_) {
      const long n = sys::write(fd_, buffer_.data() + written, used_ - written);
      if (n > 0) {
        written += static_cast<std::size_t>(n);
        continue;
      }
      if (n == -EINTR) continue;
      if (n != -EAGAIN && n != -EWOULDBLOCK) ++write_errors_;
      break;
    }
    for (std::size_t i = written; i < used_; ++i) buffer_[i - written] = buffer_[i];
    used_ -= written;
  }

  [[nodiscard]] std::uint32_t dropped() const { return dropped_; }
  [[nodiscard]] std::uint32_t write_errors() const { return write_errors_; }
  [[nodiscard]] std::size_t pending_bytes() const { return used_; }

 private:
  int fd_ = -1;
  std::size_t used_ = 0;
  std::uint32_t dropped_ = 0;
  std::uint32_t write_errors_ = 0;
  std::array<std::uint8_t, kSinkRecords * board::report_record::kSize> buffer_{};
};

}  // namespace kestrel::rv64
