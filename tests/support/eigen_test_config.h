// Force-included (-include) in every test translation unit, before Eigen.
//
// EIGEN_RUNTIME_NO_MALLOC makes Eigen check set_is_malloc_allowed() on each
// heap request, but it reports through eigen_assert, which NDEBUG (Release)
// compiles out. Route eigen_assert to a hook that never compiles out, so an
// Eigen allocation inside a NoAllocScope is counted in Release test builds too.
#pragma once

#define EIGEN_RUNTIME_NO_MALLOC 1

namespace mptrack::test {
void eigen_assert_failed(const char* condition, const char* file, int line);
}

#define eigen_assert(x) \
  ((x) ? static_cast<void>(0) : ::mptrack::test::eigen_assert_failed(#x, __FILE__, __LINE__))
