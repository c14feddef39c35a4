// SPDX-License-Identifier: Apache-2.0
// Allocation guard: counts every operator new and malloc made while a guard
// is alive and forbids Eigen allocations (EIGEN_RUNTIME_NO_MALLOC), so a test
// can assert that a tracker step touched no heap at all.
//
//   AllocationGuard guard;
//   REQUIRE(tracker.step(scan) == Status::kOk);
//   REQUIRE(guard.allocations() == 0);
#pragma once

#include <cstddef>

namespace kestrel::test {

class AllocationGuard {
 public:
  AllocationGuard();
  ~AllocationGuard();
  AllocationGuard(const AllocationGuard&) = delete;
  AllocationGuard& operator=(const AllocationGuard&) = delete;

  /// Heap allocations (operator new, malloc, calloc, realloc) since construction.
  std::size_t allocations() const;

 private:
  std::size_t start_;
};

/// Total allocations counted since the program started (for self-tests).
std::size_t allocation_count();
/// true when malloc itself is interposed (not under sanitizers, which own malloc).
bool malloc_is_counted();

}  // namespace kestrel::test
