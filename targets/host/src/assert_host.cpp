// SPDX-License-Identifier: Apache-2.0
// Host definition of the core's assertion hook: say where, then abort.
#include <cstdio>
#include <cstdlib>

#include "kestrel/assert.hpp"

extern "C" [[noreturn]] void kestrel_assert_failed(const char* file, int line, const char* expr) {
  std::fprintf(stderr, "%s:%d: KESTREL_ASSERT(%s) failed\n", file, line, expr);
  std::abort();
}
