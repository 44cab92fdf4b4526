// The guard itself must detect allocations, or every "allocates nothing"
// test built on it could not fail.
#include <doctest/doctest.h>

#include <Eigen/Core>
#include <cstdlib>
#include <memory>
#include <vector>

#include "alloc_guard.h"

TEST_CASE("NoAllocScope counts operator new") {
  mptrack::test::NoAllocScope guard;
  auto p = std::make_unique<int>(7);
  CHECK(guard.allocations() >= 1);
  CHECK(*p == 7);
}

TEST_CASE("NoAllocScope counts std::vector growth") {
  mptrack::test::NoAllocScope guard;
  std::vector<double> v(100, 1.0);
  CHECK(guard.allocations() >= 1);
  CHECK(v.size() == 100);
}

TEST_CASE("NoAllocScope counts a dynamic Eigen matrix") {
  mptrack::test::NoAllocScope guard;
  Eigen::MatrixXd m(8, 8);
  m.setZero();
  CHECK(guard.allocations() >= 1);
}

TEST_CASE("NoAllocScope sees nothing for fixed-size Eigen arithmetic") {
  Eigen::Matrix4d a = Eigen::Matrix4d::Identity();
  Eigen::Matrix4d b;
  mptrack::test::NoAllocScope guard;
  b = a * a.transpose() + a;
  CHECK(guard.allocations() == 0);
  CHECK(b(0, 0) == doctest::Approx(2.0));
}

TEST_CASE("allocations outside a scope are not counted") {
  const std::size_t before = mptrack::test::counted_allocations();
  auto p = std::make_unique<int>(1);
  CHECK(mptrack::test::counted_allocations() == before);
  CHECK(*p == 1);
}
