#include <doctest/doctest.h>

#include <chrono>
#include <thread>

#include "mptrack/platform/cycle_counter.h"

using mptrack::platform::CycleCounter;

TEST_CASE("host stamps are nanoseconds and follow a known sleep") {
  CycleCounter::enable();
  REQUIRE(CycleCounter::unit() == mptrack::platform::StampUnit::kNanoseconds);
  const auto t0 = CycleCounter::now();
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  const auto t1 = CycleCounter::now();
  const double us = CycleCounter::to_us(t1 - t0);
  CHECK(us >= 20000.0);
  CHECK(us < 2e6);  // generous upper bound: a loaded CI machine or qemu
}

TEST_CASE("to_us converts nanosecond ticks exactly") {
  CHECK(CycleCounter::to_us(1500) == doctest::Approx(1.5));
}
