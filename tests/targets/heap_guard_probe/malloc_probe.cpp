// SPDX-License-Identifier: Apache-2.0
// Negative probe: calls malloc and free. The board's link must refuse it
// with "undefined reference to `__wrap_malloc'".
#include <cstdlib>

extern "C" [[noreturn]] void Reset_Handler() {
  void* volatile p = std::malloc(16);
  std::free(p);
  for (;;) {
  }
}
