#pragma once
// The count of malloc / calloc / realloc calls of wpg_libwpg_tests (the C allocator is
// interposed, or hooked under AddressSanitizer, in test_nmpc_allocation.cpp), and Eigen's
// malloc guard when wpg_core is built with EIGEN_RUNTIME_NO_MALLOC, for the allocation tests
// of the other files of the executable.
namespace wpg_test {

struct Counts {
  long allocations = 0;  // malloc / calloc / realloc calls
};

void startCounting();
Counts stopCounting();
bool counterAvailable();  // false: no counter here (neither glibc nor ASan), skip the test

}  // namespace wpg_test
