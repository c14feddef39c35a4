// SPDX-License-Identifier: Apache-2.0
// A static table of tracks with compile-time capacity (docs/tracking.md). Slots
// are reused; a track's id is stable for its life and ids are not reused
// until the 32-bit counter wraps. Every loop is over kCapacity. A bitmask of
// the allocated slots lets the tracker visit the active tracks only
// (active_slots()), so a frame with one track does not pay for scanning the
// whole capacity five times.
#pragma once

#include <bit>
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

 private:
  static constexpr std::size_t kWords = (kCapacity + 63) / 64;
  static constexpr std::uint64_t bit(std::size_t i) { return std::uint64_t{1} << (i % 64); }
  /// The bits of word w that are slots (all but in a last, partial word).
  static constexpr std::uint64_t slots_in_word(std::size_t w) {
    return (w + 1 < kWords || kCapacity % 64 == 0) ? ~std::uint64_t{0} : (std::uint64_t{1} << (kCapacity % 64)) - 1u;
  }

 public:
  /// Take a free slot for a new tentative track with the next id.
  /// @return the slot index, or kCapacity when the table is full.
  /// The lowest free slot, found in the occupancy words (a full table costs
  /// kWords tests, not kCapacity).
  std::size_t allocate(const TrackT& prototype) {
    for (std::size_t w = 0; w < kWords; ++w) {
      const std::uint64_t free = ~mask_[w] & slots_in_word(w);
      if (free == 0) continue;
      const std::size_t i = w * 64 + static_cast<std::size_t>(std::countr_zero(free));
      slots_[i] = prototype;
      slots_[i].status = TrackStatus::kTentative;
      slots_[i].id = next_id_;
      next_id_ = next_id_ == UINT32_MAX ? 1u : next_id_ + 1u;
      mask_[w] |= bit(i);
      return i;
    }
    return kCapacity;
  }

  /// Give the track in slot i the next id (a restart: the same slot, a new track).
  void renew_id(std::size_t i) {
    slots_[i].id = next_id_;
    next_id_ = next_id_ == UINT32_MAX ? 1u : next_id_ + 1u;
  }

  void release(std::size_t i) {
    slots_[i].status = TrackStatus::kFree;
    mask_[i / 64] &= ~bit(i);
  }

  bool active(std::size_t i) const { return slots_[i].status != TrackStatus::kFree; }
  TrackT& operator[](std::size_t i) { return slots_[i]; }
  const TrackT& operator[](std::size_t i) const { return slots_[i]; }

  std::size_t size() const {
    std::size_t n = 0;
    for (std::size_t w = 0; w < kWords; ++w) n += static_cast<std::size_t>(std::popcount(mask_[w]));
    return n;
  }
  static constexpr std::size_t capacity() { return kCapacity; }

  void clear() {
    for (std::size_t i = 0; i < kCapacity; ++i) slots_[i].status = TrackStatus::kFree;
    for (std::size_t w = 0; w < kWords; ++w) mask_[w] = 0;
  }

  /// Forward iterator over the allocated slot indices, increasing. Each
  /// 64-slot word is copied when the iteration reaches it: releasing the
  /// current slot (or an earlier one) during the loop is safe; releasing a
  /// later slot or allocating during the loop is not supported.
  class SlotIterator {
   public:
    struct End {};
    explicit SlotIterator(const std::uint64_t* words) : words_(words), bits_(words[0]) { skip_empty(); }
    std::size_t operator*() const { return word_ * 64 + static_cast<std::size_t>(std::countr_zero(bits_)); }
    SlotIterator& operator++() {
      bits_ &= bits_ - 1;  // drop the lowest set bit
      skip_empty();
      return *this;
    }
    // One word (every capacity up to 64): the loop ends when its copy is
    // empty, and there is no next word to look for.
    bool operator!=(End) const {
      if constexpr (kWords == 1) {
        return bits_ != 0;
      } else {
        return word_ < kWords;
      }
    }

   private:
    void skip_empty() {
      if constexpr (kWords > 1) {
        while (bits_ == 0 && word_ < kWords) {  // at most kWords steps
          ++word_;
          bits_ = word_ < kWords ? words_[word_] : 0;
        }
      }
    }
    const std::uint64_t* words_;
    std::size_t word_ = 0;
    std::uint64_t bits_;
  };
  struct SlotRange {
    const std::uint64_t* words;
    SlotIterator begin() const { return SlotIterator(words); }
    typename SlotIterator::End end() const { return {}; }
  };

  /// The active slots, in increasing index order (for (std::size_t i : table.active_slots())).
  SlotRange active_slots() const { return SlotRange{mask_}; }

 private:
  TrackT slots_[kCapacity]{};
  std::uint64_t mask_[kWords] = {};  ///< Bit i % 64 of word i / 64: slot i allocated.
  std::uint32_t next_id_ = 1;
};

}  // namespace kestrel
