// SPDX-License-Identifier: Apache-2.0
// KESTREL_ASSERT: for programmer error only (a broken invariant inside core),
// never for feed data, which gets a Status. On the host it aborts with a
// message; on a board it calls kestrel_assert_failed(), which the board
// defines (typically a breakpoint and reset), so no printf or stdio is linked.
// Eigen's own eigen_assert is routed here by kestrel/math/eigen.hpp.
#pragma once

extern "C" [[noreturn]] void kestrel_assert_failed(const char* file, int line, const char* expr);

#if defined(KESTREL_DISABLE_ASSERT)
#define KESTREL_ASSERT(cond) static_cast<void>(0)
#else
#define KESTREL_ASSERT(cond) \
  ((cond) ? static_cast<void>(0) : kestrel_assert_failed(__FILE__, __LINE__, #cond))
#endif
