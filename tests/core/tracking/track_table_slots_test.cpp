// SPDX-License-Identifier: Apache-2.0
// TrackTable::active_slots() (the bitmask the tracker iterates instead of
// scanning the capacity) against a std::set model, for a one-word and a
// three-word table, including releasing the current slot inside the loop.
#include <catch2/catch.hpp>
#include <cstddef>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

#include "kestrel/tracking/track_table.hpp"

namespace {

struct Item {
  std::uint32_t id = 0;
  kestrel::TrackStatus status = kestrel::TrackStatus::kFree;
};

template <std::size_t kCapacity>
void check_against_model(std::uint32_t seed) {
  kestrel::TrackTable<Item, kCapacity> table;
  std::set<std::size_t> model;
  std::mt19937 rng(seed);
  for (int op = 0; op < 3000; ++op) {
    if (rng() % 5 < 3) {
      const std::size_t slot = table.allocate(Item{});
      // The lowest free slot, or kCapacity when full (found in the mask words).
      std::size_t lowest = 0;
      while (model.count(lowest) != 0) ++lowest;
      REQUIRE(slot == lowest);
      if (slot < kCapacity) model.insert(slot);
    } else if (!model.empty()) {
      auto it = model.begin();
      std::advance(it, static_cast<long>(rng() % model.size()));
      table.release(*it);
      model.erase(it);
    }
    std::vector<std::size_t> seen;
    for (const std::size_t i : table.active_slots()) seen.push_back(i);
    REQUIRE(seen == std::vector<std::size_t>(model.begin(), model.end()));
    REQUIRE(table.size() == model.size());
  }
  WHEN("every other slot is released inside the loop") {
    std::vector<std::size_t> visited;
    bool drop = false;
    for (const std::size_t i : table.active_slots()) {
      visited.push_back(i);
      if (drop) {
        table.release(i);
        model.erase(i);
      }
      drop = !drop;
    }
    THEN("the loop still visits each slot active at its start, once, in order, and the rest stay active") {
      std::vector<std::size_t> after;
      for (const std::size_t i : table.active_slots()) after.push_back(i);
      CHECK(after == std::vector<std::size_t>(model.begin(), model.end()));
      CHECK(std::set<std::size_t>(visited.begin(), visited.end()).size() == visited.size());
    }
  }
  WHEN("the table is cleared") {
    table.clear();
    std::size_t n = 0;
    for (const std::size_t i : table.active_slots()) n += i + 1;
    CHECK(n == 0);
    CHECK(table.size() == 0);
  }
}

}  // namespace

SCENARIO("active_slots() lists exactly the allocated slots, in order") {
  GIVEN("a table of 16 (one mask word)") { check_against_model<16>(7); }
  GIVEN("a table of 130 (three mask words, the last partial)") { check_against_model<130>(11); }
  GIVEN("a table of 64 (exactly one full word)") { check_against_model<64>(13); }
}
