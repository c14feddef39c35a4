// SPDX-License-Identifier: Apache-2.0
// Negative probe of the per-function stack budget: an 8 KiB local array.
// Compiled with -Wstack-usage=4096 -Werror (what kestrel_board_evidence's
// FRAME_BUDGET adds to a board's code generation), it must not compile.
#include <cstddef>

int frame_probe(int seed) {
  volatile unsigned char big[8192];
  for (std::size_t i = 0; i < sizeof big; ++i) big[i] = static_cast<unsigned char>(seed + static_cast<int>(i));
  return big[static_cast<std::size_t>(seed) % sizeof big];
}
