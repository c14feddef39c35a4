// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: arbitrary bytes as radar frames into the radar tracker
// in double, float and Q31.32 (radar_tracker_invariants.hpp); a broken
// invariant aborts with its description. tests/fuzz/CMakeLists.txt builds
// it with clang and runs it briefly under CTest (label
// `fuzz`); docs/fuzzing.md gives the long run.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>

#include "radar_tracker_invariants.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const char* why = kestrel::test::check_radar_tracker_invariants(std::span<const std::uint8_t>(data, size));
  if (why != nullptr) {
    std::fprintf(stderr, "radar tracker invariant broken: %s\n", why);
    std::abort();
  }
  return 0;
}
