// SPDX-License-Identifier: Apache-2.0
// A TrackSink (hal/sink.hpp) that publishes every track report as an
// ASTERIX CAT062 data block (EUROCONTROL ASTERIX Part 9, edition 1.19) of
// one record, written whole to a byte transmitter: a UART ring on a board,
// a file or buffer on the host. A board picks it in board.hpp instead of
// its KTRK sink (`using Sink = Cat062Sink<...>`). One block per report
// keeps publish() stateless and its latency one report, at 3 bytes of block
// header per record. No heap, no exceptions; the block is built on the
// stack and handed over whole or not at all.
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>

#include "kestrel/hal/asterix_cat062.hpp"
#include "kestrel/status.hpp"
#include "kestrel/tracking/track.hpp"

namespace kestrel::hal::asterix {

/// Something that takes a run of bytes whole or not at all:
/// write(bytes) -> kOk (all taken) or another status (none taken, e.g.
/// kTableFull when a transmit ring has no room).
template <class T>
concept ByteTx = requires(T& tx, std::span<const std::uint8_t> bytes) {
  { tx.write(bytes) } -> std::same_as<Status>;
};

/// Tallies of a Cat062Sink since construction.
struct Cat062SinkCounters {
  std::uint32_t blocks = 0;      ///< Blocks the transmitter took.
  std::uint32_t refused = 0;     ///< Reports to_cat062/encode_cat062 refused (out of range, non-finite).
  std::uint32_t tx_dropped = 0;  ///< Blocks the transmitter did not take (full).
};

/// @tparam Tx a ByteTx; held by value (a board's is a reference to its ring).
template <ByteTx Tx>
class Cat062Sink {
 public:
  /// Largest block this sink writes: header and one record with I062/015.
  static constexpr std::size_t kMaxBlockBytes = kBlockHeaderSize + 28;

  /// @param source SAC/SIC (and optional service id) of every block.
  explicit Cat062Sink(Tx tx, Cat062Source source = {}) : tx_(std::move(tx)), source_(source) {}

  /// Publish one report as one CAT062 data block.
  /// @return kOk; kOutOfRange or kNonFinite (the report cannot be written in
  ///         CAT062: t_us outside one day, an id over 65535, a position,
  ///         velocity or accuracy outside its item; nothing sent); the
  ///         transmitter's status when it did not take the block.
  template <class Filter>
  [[nodiscard]] Status publish(const TrackReport<Filter>& report) {
    Cat062Track track;
    Status s = to_cat062(report, track);
    std::array<std::uint8_t, kMaxBlockBytes> block{};
    std::size_t written = 0;
    if (s == Status::kOk) s = encode_cat062(source_, std::span<const Cat062Track>(&track, 1), block, written);
    if (s != Status::kOk) {
      ++counters_.refused;
      return s;
    }
    s = tx_.write(std::span<const std::uint8_t>(block.data(), written));
    if (s != Status::kOk) {
      ++counters_.tx_dropped;
      return s;
    }
    ++counters_.blocks;
    return Status::kOk;
  }

  [[nodiscard]] const Cat062SinkCounters& counters() const { return counters_; }
  [[nodiscard]] const Cat062Source& source() const { return source_; }
  [[nodiscard]] Tx& tx() { return tx_; }
  [[nodiscard]] const Tx& tx() const { return tx_; }

 private:
  Tx tx_;
  Cat062Source source_;
  Cat062SinkCounters counters_{};
};

}  // namespace kestrel::hal::asterix
