// Counts heap allocations of this test executable (alloc_counter.hpp): malloc and friends are
// interposed here and forwarded to glibc's __libc_* functions, so that "no allocation in the
// hot loop" covers everything called (operator new, Eigen's aligned_malloc, Simbody).
//
// Under AddressSanitizer and ThreadSanitizer the sanitizer owns malloc (sanitizer_malloc.hpp
// says why nothing is interposed there). There the count comes from the sanitizer's own
// allocation hook instead, which its allocator calls for every malloc, calloc, realloc,
// memalign and operator new: the tests keep their assertions.
#include <atomic>
#include <cerrno>
#include <cstddef>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "../common/sanitizer_malloc.hpp"
#include "alloc_counter.hpp"

#ifndef WPG_TEST_SANITIZER_OWNS_MALLOC
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* p, std::size_t size);
void* __libc_memalign(std::size_t alignment, std::size_t size);
}
#endif

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

namespace wpg_test {
long allocationCount() { return g_allocations.load(std::memory_order_relaxed); }
}  // namespace wpg_test

#ifdef WPG_TEST_SANITIZER_OWNS_MALLOC
namespace {
void countAllocation(const volatile void*, std::size_t) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
}
void ignoreFree(const volatile void*) {}
// Installed before main(): the tests only compare counts taken inside their bodies.
const int g_hook_installed = __sanitizer_install_malloc_and_free_hooks(countAllocation, ignoreFree);
}  // namespace
#else
extern "C" {
void* malloc(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_calloc(count, size);
}
void* realloc(void* p, std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_realloc(p, size);
}
void* memalign(std::size_t alignment, std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_memalign(alignment, size);
}
void* aligned_alloc(std::size_t alignment, std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_memalign(alignment, size);
}
int posix_memalign(void** out, std::size_t alignment, std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  void* p = __libc_memalign(alignment, size);
  if (p == nullptr) return ENOMEM;
  *out = p;
  return 0;
}
}  // extern "C"
#endif

TEST(AllocationCounter, CountsAllocations) {
#ifdef WPG_TEST_SANITIZER_OWNS_MALLOC
  ASSERT_NE(g_hook_installed, 0) << "the sanitizer refused the allocation hook";
#endif
  const long before = wpg_test::allocationCount();
  auto* v = new std::vector<int>(100);
  Eigen::VectorXd x(1000);
  EXPECT_GE(wpg_test::allocationCount() - before, 3);
  delete v;
  x.setZero();
}
