// SPDX-License-Identifier: Apache-2.0
// The allocation guard must see allocations, or every zero-allocation check
// in this suite would pass vacuously.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <memory>

#include "support/alloc_guard.hpp"

namespace {
// The optimiser may delete a malloc/free pair whose memory is never used;
// publishing the pointer through a volatile keeps the call.
void* volatile g_sink = nullptr;
}  // namespace

SCENARIO("the allocation guard counts heap use", "[support][alloc]") {
  GIVEN("a guard") {
    std::size_t counted_new = 0;
    std::size_t counted_malloc = 0;
    {
      kestrel::test::AllocationGuard guard;
      auto p = std::make_unique<int>(3);
      g_sink = p.get();
      counted_new = guard.allocations();
      g_sink = std::malloc(16);
      counted_malloc = guard.allocations() - counted_new;
      std::free(g_sink);
    }
    THEN("operator new is counted") { CHECK(counted_new >= 1); }
    THEN("malloc is counted where it is interposed") {
      if (kestrel::test::malloc_is_counted()) {
        CHECK(counted_malloc >= 1);
      } else {
        WARN("malloc is not interposed in this build (sanitizer); only operator new is counted");
      }
    }
  }
}
