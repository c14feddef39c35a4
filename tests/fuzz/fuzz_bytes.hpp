// SPDX-License-Identifier: Apache-2.0
// Reading fuzz input bytes as a stream of frames, shared by the tracker
// fuzz harnesses (radar_tracker_invariants.hpp, pcl_tracker_invariants.hpp,
// sonar_tracker_invariants.hpp): a reader that yields zeros once the
// bytes are used up, so every input is a valid stream, and the time step
// that opens every frame, and a tally of what a run met.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>

namespace kestrel::test {

class ByteReader {
 public:
  explicit ByteReader(std::span<const std::uint8_t> in) : in_(in) {}
  bool empty() const { return pos_ >= in_.size(); }
  std::uint8_t u8() { return pos_ < in_.size() ? in_[pos_++] : 0; }
  template <class T>
  T read() {
    std::uint8_t b[sizeof(T)] = {};
    for (auto& x : b) x = u8();
    T v;
    std::memcpy(&v, b, sizeof(T));
    return v;
  }

 private:
  std::span<const std::uint8_t> in_;
  std::size_t pos_ = 0;
};

/// Moves the frame clock by the choice in bits 0-1 of a frame's op byte,
/// reading the operand from `r`: 0 one sensor period; 1 a signed step of up
/// to +-32 s (int16 ms); 2 any int64 time; 3 a gap of up to 49 days
/// (uint32 ms).
/// @param period_us the sensor's frame period, us.
inline void step_time(ByteReader& r, std::uint8_t op, std::int64_t period_us, std::int64_t& t_us) {
  // Steps wrap around the int64 range as a sensor's counter would.
  const auto advance = [&t_us](std::int64_t step) {
    t_us = static_cast<std::int64_t>(static_cast<std::uint64_t>(t_us) + static_cast<std::uint64_t>(step));
  };
  switch (op & 3u) {
    case 0: advance(period_us); break;
    case 1: advance(static_cast<std::int64_t>(r.read<std::int16_t>()) * 1000); break;
    case 2: t_us = r.read<std::int64_t>(); break;
    default: advance(static_cast<std::int64_t>(r.read<std::uint32_t>()) * 1000); break;
  }
}

/// What a harness run met, summed over its scalars: lets the regression
/// test check that the corpus reaches the paths the invariants guard.
struct FuzzTally {
  int frames = 0;     ///< Frames stepped.
  int refused = 0;    ///< Steps the tracker refused.
  int truncated = 0;  ///< Frames the adapter cut to the scan capacity.
  int reports = 0;    ///< Reports published.
};

}  // namespace kestrel::test
