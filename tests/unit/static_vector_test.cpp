#include <doctest/doctest.h>

#include <vector>

#include "alloc_guard.h"
#include "mptrack/static_vector.h"

using mptrack::Status;
using mptrack::StaticVector;

TEST_CASE("push_back reports overflow and keeps what was stored") {
  StaticVector<int, 3> v;
  CHECK(v.push_back(1) == Status::kOk);
  CHECK(v.push_back(2) == Status::kOk);
  CHECK(v.push_back(3) == Status::kOk);
  CHECK(v.full());
  CHECK(v.push_back(4) == Status::kCapacityExceeded);
  REQUIRE(v.size() == 3);
  CHECK(v[0] == 1);
  CHECK(v[2] == 3);
}

TEST_CASE("erase keeps the order of the remaining elements") {
  StaticVector<int, 5> v;
  for (int i = 0; i < 5; ++i) CHECK(v.push_back(10 * i) == Status::kOk);
  CHECK(v.erase(1) == Status::kOk);
  REQUIRE(v.size() == 4);
  CHECK(v[0] == 0);
  CHECK(v[1] == 20);
  CHECK(v[3] == 40);
  CHECK(v.erase(4) == Status::kInvalidArgument);
  CHECK(v.size() == 4);
}

TEST_CASE("pop_back on empty and resize beyond capacity are refused") {
  StaticVector<int, 2> v;
  CHECK(v.pop_back() == Status::kBufferEmpty);
  CHECK(v.resize(3) == Status::kCapacityExceeded);
  CHECK(v.empty());
  CHECK(v.resize(2) == Status::kOk);
  CHECK(v[1] == 0);
}

TEST_CASE("matches std::vector on a pseudo-random operation sequence") {
  StaticVector<unsigned, 16> ours;
  std::vector<unsigned> ref;
  unsigned state = 12345u;
  for (int step = 0; step < 2000; ++step) {
    state = state * 1103515245u + 12345u;
    const unsigned op = (state >> 16) % 4u;
    if (op <= 1) {
      const Status s = ours.push_back(state);
      if (ref.size() < 16) {
        CHECK(s == Status::kOk);
        ref.push_back(state);
      } else {
        CHECK(s == Status::kCapacityExceeded);
      }
    } else if (op == 2 && !ref.empty()) {
      const std::size_t i = (state >> 8) % ref.size();
      CHECK(ours.erase(i) == Status::kOk);
      ref.erase(ref.begin() + static_cast<std::ptrdiff_t>(i));
    } else if (!ref.empty()) {
      CHECK(ours.pop_back() == Status::kOk);
      ref.pop_back();
    }
    REQUIRE(ours.size() == ref.size());
    for (std::size_t i = 0; i < ref.size(); ++i) CHECK(ours[i] == ref[i]);
  }
}

TEST_CASE("StaticVector operations never touch the heap") {
  StaticVector<double, 64> v;
  mptrack::test::NoAllocScope guard;
  for (int i = 0; i < 100; ++i) static_cast<void>(v.push_back(i));
  static_cast<void>(v.erase(3));
  CHECK(guard.allocations() == 0);
  CHECK(v.size() == 63);
}
