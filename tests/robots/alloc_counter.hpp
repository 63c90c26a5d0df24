#pragma once
// Heap allocation counter for the no-allocation tests: test_allocation_counter.cpp interposes
// malloc and friends in the wpg_robots_tests executable (so every library is covered).
namespace wpg_test {
long allocationCount();
}  // namespace wpg_test
