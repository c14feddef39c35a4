// A static table of tracks with compile-time capacity (SPEC section 7). Slots
// are reused; a track's id is stable for its life and ids are not reused
// until the 32-bit counter wraps. Every loop is over kCapacity.
#pragma once

#include <cstddef>
#include <cstdint>

namespace kestrel {

/// Life-cycle state of a table slot.
enum class TrackStatus : std::uint8_t {
  kFree = 0,    ///< Slot unused.
  kTentative,   ///< Started, not yet confirmed by M-of-N.
  kConfirmed,   ///< Confirmed; reported.
};

template <class TrackT, std::size_t kCapacity>
class TrackTable {
  static_assert(kCapacity > 0, "a track table needs at least one slot");

 public:
  static constexpr std::size_t kMaxTracks = kCapacity;

  /// Take a free slot for a new tentative track with the next id.
  /// @return the slot index, or kCapacity when the table is full.
  std::size_t allocate(const TrackT& prototype) {
    for (std::size_t i = 0; i < kCapacity; ++i) {
      if (slots_[i].status == TrackStatus::kFree) {
        slots_[i] = prototype;
        slots_[i].status = TrackStatus::kTentative;
        slots_[i].id = next_id_;
        next_id_ = next_id_ == UINT32_MAX ? 1u : next_id_ + 1u;
        return i;
      }
    }
    return kCapacity;
  }

  void release(std::size_t i) { slots_[i].status = TrackStatus::kFree; }

  bool active(std::size_t i) const { return slots_[i].status != TrackStatus::kFree; }
  TrackT& operator[](std::size_t i) { return slots_[i]; }
  const TrackT& operator[](std::size_t i) const { return slots_[i]; }

  std::size_t size() const {
    std::size_t n = 0;
    for (std::size_t i = 0; i < kCapacity; ++i) n += active(i) ? 1u : 0u;
    return n;
  }
  static constexpr std::size_t capacity() { return kCapacity; }

  void clear() {
    for (std::size_t i = 0; i < kCapacity; ++i) slots_[i].status = TrackStatus::kFree;
  }

 private:
  TrackT slots_[kCapacity]{};
  std::uint32_t next_id_ = 1;
};

}  // namespace kestrel
