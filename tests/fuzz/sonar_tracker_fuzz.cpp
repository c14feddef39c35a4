// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: arbitrary bytes as sonar frames into the sonar
// (TOA) tracker in double and float (sonar_tracker_invariants.hpp); a
// broken invariant aborts with its description. tests/fuzz/CMakeLists.txt builds
// it with clang, CTest runs it briefly (label `fuzz`); docs/fuzzing.md
// gives the long run.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>

#include "sonar_tracker_invariants.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const char* why = kestrel::test::check_sonar_tracker_invariants(std::span<const std::uint8_t>(data, size));
  if (why != nullptr) {
    std::fprintf(stderr, "sonar tracker invariant broken: %s\n", why);
    std::abort();
  }
  return 0;
}
