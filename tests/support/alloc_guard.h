// No-allocation guard for tests (README.md §Conventions a firmware engineer can rely on).
//
// The test support library replaces global operator new/delete (all forms)
// and, on glibc, malloc/calloc/realloc, with versions that count calls made
// while a NoAllocScope is alive. The scope also switches Eigen's run-time
// malloc check off (EIGEN_RUNTIME_NO_MALLOC); Eigen violations are counted
// too. Setup (doctest, fixtures) allocates freely: arm the scope only
// around the core call under test, as Eigen's own nomalloc test does.
//
//   mptrack::test::NoAllocScope guard;
//   CHECK(tracker.step(scan) == mptrack::Status::kOk);
//   CHECK(guard.allocations() == 0);
#pragma once

#include <cstddef>

namespace mptrack::test {

class NoAllocScope {
 public:
  NoAllocScope();
  ~NoAllocScope();
  NoAllocScope(const NoAllocScope&) = delete;
  NoAllocScope& operator=(const NoAllocScope&) = delete;

  /// Heap allocations (operator new, malloc, calloc, realloc) plus Eigen
  /// malloc-check violations seen since construction.
  std::size_t allocations() const;

 private:
  std::size_t start_count_;
};

/// Total counted allocations since the program started counting (diagnostics).
std::size_t counted_allocations();

}  // namespace mptrack::test
