// SPDX-License-Identifier: Apache-2.0
// A track table or a scan with capacity 0 must not compile.
#include "kestrel/tracking/measurement_scan.hpp"
#include "kestrel/tracking/track_table.hpp"

struct Item {
  unsigned id = 0;
  kestrel::TrackStatus status = kestrel::TrackStatus::kFree;
};

int main() {
#ifdef KESTREL_SHOULD_FAIL
  kestrel::TrackTable<Item, 0> table;
#else
  kestrel::TrackTable<Item, 1> table;
#endif
  return static_cast<int>(table.size());
}
