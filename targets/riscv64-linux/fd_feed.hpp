// SPDX-License-Identifier: Apache-2.0
// MeasurementFeed of the riscv64-linux board: wire-format bytes from a file
// descriptor (a stream file, a pipe, or a serial device opened non-blocking
// by the shell, main.cpp) -> hal::FrameAssembler -> frames, so the board
// sees exactly what a host replay of the same bytes sees. poll() never
// blocks: at most one read(2) of kReadChunkBytes per call (a direct system
// call, linux_syscall.hpp), and a descriptor
// with nothing to read (EAGAIN) gives kNoData. End of file is remembered
// (ended()) so the shell can stop when a file is exhausted; a serial device
// never ends.
#pragma once

#include <array>
#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <span>

#include "board_config.hpp"
#include "kestrel/hal/frame.hpp"
#include "kestrel/hal/frame_assembler.hpp"
#include "kestrel/status.hpp"
#include "linux_syscall.hpp"

namespace kestrel::rv64 {

class FdFeed {
 public:
  /// Read from `fd` from now on (-1: no input).
  void attach(int fd) {
    fd_ = fd;
    eof_ = false;
  }

  /// @return kOk (frame filled); kNoData (no complete frame yet, or the
  ///         input ended); kTooManyCandidates (frame filled with its first
  ///         capacity items); or the status of bytes the assembler dropped:
  ///         kBadMagic, kMalformedFrame, kUnsupportedVersion, kUnknownKind,
  ///         kBadCrc.
  [[nodiscard]] Status poll(hal::Frame& frame) {
    const Status buffered = assembler_.next(frame);
    if (buffered != Status::kNoData) return buffered;
    if (taken_ == filled_) {
      if (fd_ < 0 || eof_) return Status::kNoData;
      const long n = sys::read(fd_, chunk_.data(), chunk_.size());
      if (n == 0) {
        eof_ = true;
        return Status::kNoData;
      }
      if (n < 0) {
        if (n != -EAGAIN && n != -EWOULDBLOCK && n != -EINTR) ++read_errors_;
        return Status::kNoData;
      }
      filled_ = static_cast<std::size_t>(n);
      taken_ = 0;
    }
    taken_ += assembler_.push(std::span<const std::uint8_t>(chunk_.data() + taken_, filled_ - taken_));
    return assembler_.next(frame);
  }

  /// The input reached end of file and every byte read has been decoded.
  [[nodiscard]] bool ended() const { return eof_ && taken_ == filled_; }
  /// read(2) failures other than "nothing to read now".
  [[nodiscard]] std::uint32_t read_errors() const { return read_errors_; }
  /// The assembler's per-status counters and skipped-byte count.
  const hal::FrameAssembler<kAssemblerBytes>& assembler() const { return assembler_; }

 private:
  int fd_ = -1;
  bool eof_ = false;
  std::uint32_t read_errors_ = 0;
  std::size_t filled_ = 0;  ///< Bytes in chunk_ from the last read.
  std::size_t taken_ = 0;   ///< Of those, bytes the assembler has taken.
  std::array<std::uint8_t, kReadChunkBytes> chunk_{};
  hal::FrameAssembler<kAssemblerBytes> assembler_{};
};

}  // namespace kestrel::rv64
