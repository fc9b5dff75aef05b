#pragma once
/// @file AllocationCounter.h
/// Counts heap allocations, for the tests that prove the per-ray path allocates nothing.
///
/// Linking the object library rt_test_allocation_counter into a test program replaces the global
/// operator new of that whole program with one that counts every call (and otherwise behaves as
/// usual); allocationCount() reads the count. Every stage's "no allocation" test uses this one
/// helper.

namespace rt::testing {

/// How many times the global operator new (any form) has been called in this program so far.
long allocationCount() noexcept;

/// The allocations made while f runs.
template <typename F>
long allocationsDuring(F&& f) {
  const long before = allocationCount();
  f();
  return allocationCount() - before;
}

}  // namespace rt::testing
