// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: arbitrary bytes into decode() and into a FrameAssembler,
// checking the invariants of frame_invariants.hpp; a broken invariant aborts
// with its description. Build with -DKESTREL_FUZZ=ON and clang, then e.g.
//   build/fuzz/tests/hal/kestrel_hal_frame_fuzz -max_total_time=60 -max_len=9000
// Seeding the corpus with a few valid frames (kestrel-sim output, or
// tests/hal's golden bytes) gets past the CRC much sooner.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>

#include "frame_invariants.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> in(data, size);
  const char* why = kestrel::test::check_decode_invariants(in);
  if (why == nullptr) {
    const std::uint32_t seed = size == 0 ? 1u : static_cast<std::uint32_t>(data[0]) * 2654435761u;
    why = kestrel::test::check_assembler_invariants(in, seed);
  }
  if (why != nullptr) {
    std::fprintf(stderr, "frame invariant broken: %s\n", why);
    std::abort();
  }
  return 0;
}
