// SPDX-License-Identifier: Apache-2.0
// A lock-free single-producer / single-consumer byte ring: the UART receive
// interrupt pushes bytes, the main loop pops them into a FrameAssembler.
// Indices are free-running counters (bytes ever written / read) masked by a
// power-of-two capacity, so all kCapacity bytes are usable and full/empty
// need no extra flag. Each index has exactly one writer, and no
// read-modify-write atomic is used, so the ring works on cores without
// LDREX/STREX (Cortex-M0+) as long as aligned word loads and stores are
// atomic, which they are on every supported core.
//
// Ordering: the producer writes the byte, then stores head_ with release;
// the consumer loads head_ with acquire before reading bytes, and stores
// tail_ with release after it has read them, which the producer loads with
// acquire before reusing the slots.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <span>

namespace kestrel::hal {

template <std::size_t kCapacity>
class ByteRingBuffer {
  static_assert(kCapacity >= 2, "ByteRingBuffer: capacity must be at least 2");
  static_assert((kCapacity & (kCapacity - 1)) == 0, "ByteRingBuffer: capacity must be a power of two");

 public:
  /// Bytes the ring holds when full.
  static constexpr std::size_t capacity() { return kCapacity; }

  // ------------------------------------------------ producer side (ISR) --

  /// Append one byte.
  /// @return true if stored; false if the ring was full (the byte is lost
  ///         and overflow_count() goes up by one, so an ISR may ignore
  ///         the result).
  bool push(std::uint8_t byte) {
    const std::size_t head = head_.load(std::memory_order_relaxed);
    const std::size_t tail = tail_.load(std::memory_order_acquire);
    if (head - tail >= kCapacity) {
      count_overflow(1);
      return false;
    }
    data_[head & kMask] = byte;
    head_.store(head + 1, std::memory_order_release);
    return true;
  }

  /// Append as many of `bytes` as fit, in order; the rest are lost and
  /// each lost byte counts one overflow.
  /// @return number of bytes stored.
  std::size_t push(std::span<const std::uint8_t> bytes) {
    const std::size_t head = head_.load(std::memory_order_relaxed);
    const std::size_t tail = tail_.load(std::memory_order_acquire);
    const std::size_t room = kCapacity - (head - tail);
    const std::size_t n = bytes.size() < room ? bytes.size() : room;
    for (std::size_t i = 0; i < n; ++i) data_[(head + i) & kMask] = bytes[i];
    head_.store(head + n, std::memory_order_release);
    if (n < bytes.size()) count_overflow(bytes.size() - n);
    return n;
  }

  // ----------------------------------------- consumer side (main loop) --

  /// Bytes currently stored (a snapshot; the producer may add more).
  [[nodiscard]] std::size_t size() const {
    return head_.load(std::memory_order_acquire) - tail_.load(std::memory_order_acquire);
  }
  [[nodiscard]] bool empty() const { return size() == 0; }

  /// Copy up to out.size() of the oldest bytes into `out` without removing them.
  /// @return number of bytes copied.
  std::size_t peek(std::span<std::uint8_t> out) const {
    const std::size_t tail = tail_.load(std::memory_order_relaxed);
    const std::size_t head = head_.load(std::memory_order_acquire);
    const std::size_t avail = head - tail;
    const std::size_t n = out.size() < avail ? out.size() : avail;
    for (std::size_t i = 0; i < n; ++i) out[i] = data_[(tail + i) & kMask];
    return n;
  }

  /// Copy up to out.size() of the oldest bytes into `out` and remove them.
  /// @return number of bytes moved.
  std::size_t pop(std::span<std::uint8_t> out) {
    const std::size_t n = peek(out);
    tail_.store(tail_.load(std::memory_order_relaxed) + n, std::memory_order_release);
    return n;
  }

  /// Remove the oldest byte into `byte`.
  /// @return false (byte untouched) if the ring is empty.
  [[nodiscard]] bool pop(std::uint8_t& byte) { return pop(std::span<std::uint8_t>(&byte, 1)) == 1; }

  /// Remove up to `n` of the oldest bytes without reading them.
  /// @return number of bytes removed.
  std::size_t drop(std::size_t n) {
    const std::size_t tail = tail_.load(std::memory_order_relaxed);
    const std::size_t avail = head_.load(std::memory_order_acquire) - tail;
    const std::size_t k = n < avail ? n : avail;
    tail_.store(tail + k, std::memory_order_release);
    return k;
  }

  /// Bytes lost because the ring was full, since construction (wraps at 2^32).
  [[nodiscard]] std::uint32_t overflow_count() const { return overflows_.load(std::memory_order_relaxed); }

 private:
  static constexpr std::size_t kMask = kCapacity - 1;

  // Only the producer writes overflows_, so a load and a store suffice.
  void count_overflow(std::size_t n) {
    overflows_.store(overflows_.load(std::memory_order_relaxed) + static_cast<std::uint32_t>(n),
                     std::memory_order_relaxed);
  }

  std::array<std::uint8_t, kCapacity> data_{};
  std::atomic<std::size_t> head_{0};  ///< Bytes ever written; written by the producer only.
  std::atomic<std::size_t> tail_{0};  ///< Bytes ever read; written by the consumer only.
  std::atomic<std::uint32_t> overflows_{0};
};

}  // namespace kestrel::hal
