#include <doctest/doctest.h>

#include "mptrack/scan_clock.h"

using mptrack::ScanClock;
using mptrack::Status;
using mptrack::TrackerCounters;

TEST_CASE("a scan before init is refused and counted") {
  ScanClock clock;
  TrackerCounters c;
  CHECK(clock.admit(false, 1000, c) == Status::kNotInitialized);
  CHECK(c.scans_rejected == 1);
}

TEST_CASE("time must increase strictly; refusals leave the clock where it was") {
  ScanClock clock;
  TrackerCounters c;
  REQUIRE(clock.admit(true, 2'000'000, c) == Status::kOk);
  clock.advance(2'000'000);
  CHECK(clock.admit(true, 2'000'000, c) == Status::kOutOfOrder);
  CHECK(clock.admit(true, 1'000'000, c) == Status::kOutOfOrder);
  CHECK(c.scans_rejected == 2);
  CHECK(clock.last_time_us() == 2'000'000);
  CHECK(clock.admit(true, 2'000'001, c) == Status::kOk);
}

TEST_CASE("elapsed time is the gap to the last accepted scan, or the default first") {
  ScanClock clock;
  CHECK(clock.elapsed_s(5'000'000, 1.25) == 1.25);
  clock.advance(5'000'000);
  CHECK(clock.elapsed_s(6'250'000, 1.25) == doctest::Approx(1.25));
  CHECK(clock.elapsed_s(5'500'000, 1.25f) == doctest::Approx(0.5));
  clock.reset();
  CHECK_FALSE(clock.has_time());
}

TEST_CASE("max-gap rule: only a gap longer than max_gap_s is flagged, and restart forgets the time") {
  ScanClock clock;
  clock.advance(1'000'000);
  CHECK_FALSE(clock.gap_exceeded(1'000'000'000'000));  // no rule installed yet
  clock.set_max_gap_s(60.0f);
  CHECK_FALSE(clock.gap_exceeded(61'000'000));  // exactly 60 s: not beyond
  CHECK(clock.gap_exceeded(61'000'001));
  CHECK_FALSE(clock.gap_exceeded(500'000));  // earlier times are admit()'s business
  clock.restart();
  CHECK_FALSE(clock.has_time());
  CHECK_FALSE(clock.gap_exceeded(1'000'000'000'000));  // first scan of a new run
  CHECK(clock.elapsed_s(2'000'000, 1.25) == 1.25);
  clock.reset();  // keeps the rule
  clock.advance(0);
  CHECK(clock.gap_exceeded(60'000'001));
}
