// SPDX-License-Identifier: Apache-2.0
// Counting of every heap allocation the tests make. Three ways, chosen at
// compile time:
//  - glibc, no sanitizer: malloc/calloc/realloc interposed through glibc's
//    __libc_* entry points, and operator new replaced;
//  - AddressSanitizer: ASan owns malloc and every operator new/delete (and
//    checks that each allocation is freed by its matching function), so
//    nothing is replaced; its allocator hook counts every allocation;
//  - otherwise: operator new replaced only.
#include "support/alloc_guard.hpp"

#include <Eigen/Core>
#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<std::size_t> g_allocations{0};
}

#if defined(__SANITIZE_ADDRESS__)
#define KESTREL_TEST_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define KESTREL_TEST_UNDER_ASAN 1
#endif
#endif
#ifndef KESTREL_TEST_UNDER_ASAN
#define KESTREL_TEST_UNDER_ASAN 0
#endif

#if !KESTREL_TEST_UNDER_ASAN && defined(__GLIBC__)
#define KESTREL_TEST_INTERPOSE_MALLOC 1
#else
#define KESTREL_TEST_INTERPOSE_MALLOC 0
#endif

#if KESTREL_TEST_UNDER_ASAN
// The sanitizer runtime's hook interface (sanitizer/allocator_interface.h,
// which GCC does not install): called on every allocation and free.
extern "C" int __sanitizer_install_malloc_and_free_hooks(void (*malloc_hook)(const volatile void*, std::size_t),
                                                         void (*free_hook)(const volatile void*));
namespace {
void count_allocation(const volatile void*, std::size_t) { g_allocations.fetch_add(1, std::memory_order_relaxed); }
void ignore_free(const volatile void*) {}
[[maybe_unused]] const int g_hooks_installed = __sanitizer_install_malloc_and_free_hooks(count_allocation, ignore_free);
}  // namespace
#else

#if KESTREL_TEST_INTERPOSE_MALLOC
extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void* malloc(std::size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_malloc(n);
}
void* calloc(std::size_t n, std::size_t s) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_calloc(n, s);
}
void* realloc(void* p, std::size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_realloc(p, n);
}
}
#endif

// operator new: counted here; under interposition the malloc it calls is
// counted too, so count it only when malloc is not interposed.
void* operator new(std::size_t n) {
  if (!KESTREL_TEST_INTERPOSE_MALLOC) g_allocations.fetch_add(1, std::memory_order_relaxed);
  void* p = std::malloc(n == 0 ? 1 : n);
  if (p == nullptr) throw std::bad_alloc();
  return p;
}
void* operator new[](std::size_t n) { return operator new(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

#endif  // KESTREL_TEST_UNDER_ASAN

namespace kestrel::test {

AllocationGuard::AllocationGuard() : start_(g_allocations.load()) {
  Eigen::internal::set_is_malloc_allowed(false);
}
AllocationGuard::~AllocationGuard() { Eigen::internal::set_is_malloc_allowed(true); }
std::size_t AllocationGuard::allocations() const { return g_allocations.load() - start_; }
std::size_t allocation_count() { return g_allocations.load(); }
bool malloc_is_counted() { return KESTREL_TEST_INTERPOSE_MALLOC != 0 || KESTREL_TEST_UNDER_ASAN != 0; }

}  // namespace kestrel::test
