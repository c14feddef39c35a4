// SPDX-License-Identifier: Apache-2.0
// TrackTable against a std::map model: random allocate/release sequences
// agree on occupancy, ids, and "full".
#include <catch2/catch.hpp>
#include <map>
#include <random>

#include "kestrel/tracking/track_table.hpp"

namespace {
struct Item {
  std::uint32_t id = 0;
  kestrel::TrackStatus status = kestrel::TrackStatus::kFree;
  int payload = 0;
};
}  // namespace

SCENARIO("the track table behaves like a std::map of slots", "[track_table]") {
  kestrel::TrackTable<Item, 5> table;
  std::map<std::size_t, std::uint32_t> model;  // slot -> id
  std::uint32_t next_id = 1;
  std::mt19937 rng(42);
  for (int op = 0; op < 2000; ++op) {
    if (rng() % 3 != 0) {
      Item proto;
      proto.payload = op;
      const std::size_t slot = table.allocate(proto);
      if (model.size() == 5) {
        REQUIRE(slot == 5);  // full: refused
      } else {
        // The lowest free slot is taken, with the next id.
        std::size_t expect = 0;
        while (model.count(expect) != 0) ++expect;
        REQUIRE(slot == expect);
        REQUIRE(table[slot].id == next_id);
        REQUIRE(table[slot].status == kestrel::TrackStatus::kTentative);
        REQUIRE(table[slot].payload == op);
        model[slot] = next_id++;
      }
    } else if (!model.empty()) {
      auto it = model.begin();
      std::advance(it, static_cast<long>(rng() % model.size()));
      table.release(it->first);
      model.erase(it);
    }
    REQUIRE(table.size() == model.size());
    for (const auto& [slot, id] : model) {
      REQUIRE(table.active(slot));
      REQUIRE(table[slot].id == id);
    }
  }
  CHECK(next_id > 100);  // ids are never reused
}
