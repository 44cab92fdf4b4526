// Input validation at every tracker's public entry points (reliability
// issue; docs/reliability.md has the table of bad inputs and statuses).
// Same checks for GNN, MF-BP (online filter), GM-PHD, GM-CPHD, CBMeMBer:
//   - each bad measurement is skipped: step() returns kPartial, it counts in
//     measurements_invalid, and the valid measurements of the scan are used;
//   - a scan whose time does not increase is refused whole (kOutOfOrder,
//     scans_rejected) and leaves no trace: a twin tracker that never saw it
//     reports the same bits afterwards;
//   - step() before init() is kNotInitialized; 1000 empty scans keep
//     everything finite and the tracker still picks up a target afterwards.
#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "alloc_guard.h"
#include "tracker_cases.h"

using mptrack::Status;

using namespace tracker_cases;


TEST_CASE_TEMPLATE("validation: each bad measurement is skipped, counted and reported as kPartial",
                   Case, MPTRACK_TRACKER_CASES) {
  const auto good = Case::target();
  struct Bad {
    const char* what;
    mptrack::Measurement<float> m;
    bool amplitude;  // only meaningful for trackers that use amplitude
  };
  const Bad bad[] = {
      {"NaN range", meas(kNaN, good.azimuth_rad, good.amplitude), false},
      {"+Inf range", meas(kInf, good.azimuth_rad, good.amplitude), false},
      {"-Inf azimuth", meas(good.range_m, -kInf, good.amplitude), false},
      {"NaN azimuth", meas(good.range_m, kNaN, good.amplitude), false},
      {"range outside region", meas(Case::kOutsideRange, good.azimuth_rad, good.amplitude), false},
      {"azimuth outside region", meas(good.range_m, Case::kOutsideAz, good.amplitude), false},
      // (at 0.9 x range: an exact copy of the good position is a duplicate, F11)
      {"NaN amplitude", meas(good.range_m * 0.9f, good.azimuth_rad, kNaN), true},
      {"+Inf amplitude", meas(good.range_m * 0.9f, good.azimuth_rad, kInf), true},
      {"negative amplitude", meas(good.range_m * 0.9f, good.azimuth_rad, -3.0f), true},
      {"zero amplitude", meas(good.range_m * 0.9f, good.azimuth_rad, 0.0f), true},
  };
  for (const Bad& b : bad) {
    auto t = make_tracker<Case>();
    const Status s = t->step(scan_at<Case>(0, {good, b.m}));
    const bool expect_rejected = !b.amplitude || Case::kChecksAmplitude;
    const std::string line = std::string(Case::kName) + ": " + b.what + " -> " + mptrack::to_string(s);
    MESSAGE(line);
    CHECK(s == (expect_rejected ? Status::kPartial : Status::kOk));
    CHECK(t->counters().measurements_in == 2);
    CHECK(t->counters().measurements_invalid == (expect_rejected ? 1u : 0u));
    CHECK(t->counters().scans == 1);
    CHECK(outputs_finite(*t));
  }
}

TEST_CASE_TEMPLATE("validation: valid measurements of a partly bad scan still make a track", Case,
                   MPTRACK_TRACKER_CASES) {
  auto t = make_tracker<Case>();
  const auto good = Case::target();
  std::size_t reported = 0;
  for (std::uint64_t k = 0; k < 15; ++k) {
    const Status s = t->step(scan_at<Case>(
        k, {meas(kNaN, 0.0f, 5.0f), good, meas(Case::kOutsideRange, good.azimuth_rad, 5.0f)}));
    CHECK(s == Status::kPartial);
    for (const auto& e : t->outputs()) reported = e.tracks.size();
  }
  CHECK(t->counters().measurements_invalid == 30);
  CHECK(t->counters().measurements_in == 45);
  REQUIRE(reported >= 1);
  const auto& r = t->outputs()[t->outputs().size() - 1].tracks[0];
  // The track sits on the valid measurement (index 1 of each scan).
  CHECK(r.measurement_index == 1);
  CHECK(outputs_finite(*t));
}

TEST_CASE_TEMPLATE("validation: a scan with an equal or earlier time is refused and leaves no trace",
                   Case, MPTRACK_TRACKER_CASES) {
  auto a = make_tracker<Case>();
  auto b = make_tracker<Case>();  // twin: never sees the refused scans
  const auto good = Case::target();
  for (std::uint64_t k = 0; k < 12; ++k) {
    const auto s = scan_at<Case>(k, {good, meas(good.range_m * 0.9f, good.azimuth_rad, 4.0f)});
    const Status sa = a->step(s);
    const Status sb = b->step(s);
    CHECK(sa == sb);
    CHECK(all_outputs_identical(*a, *b));
    if (k == 5 || k == 8) {
      // equal time, then 0.5 s back, each with plausible measurements
      auto same = scan_at<Case>(k, {good, meas(good.range_m * 1.01f, good.azimuth_rad, 9.0f)});
      CHECK(a->step(same) == Status::kOutOfOrder);
      auto back = same;
      back.time_us -= 500000;
      CHECK(a->step(back) == Status::kOutOfOrder);
    }
  }
  CHECK(a->counters().scans_rejected == 4);
  CHECK(a->counters().scans == 12);
  CHECK(a->counters().measurements_in == b->counters().measurements_in);
}

TEST_CASE_TEMPLATE("validation: step() before init() is kNotInitialized and counted", Case,
                   MPTRACK_TRACKER_CASES) {
  auto t = std::make_unique<typename Case::Tracker>();
  CHECK(t->step(scan_at<Case>(0, {Case::target()})) == Status::kNotInitialized);
  CHECK(t->counters().scans_rejected == 1);
  CHECK(t->counters().measurements_in == 0);
  CHECK(t->flush() == Status::kNotInitialized);
}

TEST_CASE_TEMPLATE("validation: 1000 empty scans keep the tracker finite and it still finds a target",
                   Case, MPTRACK_TRACKER_CASES) {
  auto t = make_tracker<Case>();
  const auto good = Case::target();
  for (std::uint64_t k = 0; k < 10; ++k) REQUIRE(ok(t->step(scan_at<Case>(k, {good}))));
  std::size_t max_reported_late = 0;
  for (std::uint64_t k = 10; k < 1010; ++k) {
    mptrack::test::NoAllocScope guard;
    const Status s = t->step(scan_at<Case>(k, {}));
    CHECK(guard.allocations() == 0);
    REQUIRE(s == Status::kOk);
    if (k > 100) {
      for (const auto& e : t->outputs()) {
        if (e.tracks.size() > max_reported_late) max_reported_late = e.tracks.size();
      }
    }
  }
  CHECK(max_reported_late == 0);  // the target's track is gone long before scan 100
  CHECK(outputs_finite(*t));
  std::size_t reported = 0;
  for (std::uint64_t k = 1010; k < 1025; ++k) {
    REQUIRE(ok(t->step(scan_at<Case>(k, {good}))));
    for (const auto& e : t->outputs()) reported = e.tracks.size();
  }
  CHECK(reported == 1);
  CHECK(outputs_finite(*t));
}

// Trackers that take scans through ScanClock and the shared duplicate
// rule (measurement.h): all of them.
#define MPTRACK_CLOCKED_CASES GnnCase, MfbpCase, PhdCase, CphdCase, CbmCase

TEST_CASE_TEMPLATE("F11: an exact duplicate is dropped, counted, and the target gets one track", Case,
                   MPTRACK_CLOCKED_CASES) {
  auto t = make_tracker<Case>();
  const auto good = Case::target();
  auto other_amp = good;  // same range and azimuth bits, another amplitude: still a duplicate
  other_amp.amplitude = good.amplitude * 1.5f;
  std::size_t reported = 0;
  std::int32_t index = -2;
  for (std::uint64_t k = 0; k < 20; ++k) {
    REQUIRE(t->step(scan_at<Case>(k, {good, good, other_amp})) == Status::kPartial);
    for (const auto& e : t->outputs()) {
      reported = e.tracks.size();
      if (reported > 0) index = e.tracks[0].measurement_index;
    }
  }
  CHECK(reported == 1);
  CHECK(index == 0);  // the first copy is the one kept
  CHECK(t->counters().measurements_duplicate == 40);
  CHECK(t->counters().measurements_invalid == 0);
  CHECK(t->counters().measurements_in == 60);
  CHECK(outputs_finite(*t));
}

TEST_CASE_TEMPLATE("F11: measurements that differ in one bit are not duplicates", Case,
                   MPTRACK_CLOCKED_CASES) {
  auto t = make_tracker<Case>();
  const auto good = Case::target();
  auto near = good;
  near.range_m = std::nextafter(good.range_m, 2.0f * good.range_m);
  CHECK(t->step(scan_at<Case>(0, {good, near})) == Status::kOk);
  CHECK(t->counters().measurements_duplicate == 0);
  CHECK(mptrack::same_position(good, good));
  CHECK_FALSE(mptrack::same_position(good, near));
}

TEST_CASE_TEMPLATE("F1: a scan after a gap beyond max_gap_s drops every track and starts a new run",
                   Case, MPTRACK_CLOCKED_CASES) {
  auto t = make_tracker<Case>();
  const auto good = Case::target();
  std::uint64_t k = 0;
  for (; k < 15; ++k) REQUIRE(ok(t->step(scan_at<Case>(k, {good}))));
  REQUIRE(t->outputs()[0].tracks.size() == 1);
  const std::uint32_t old_id = t->outputs()[0].tracks[0].id;
  // 58 s late (59.25 s after the previous scan at most): inside the default
  // max_gap_s = 60 s, nothing is reset
  auto s = scan_at<Case>(k, {good});
  s.time_us += 58000000u;
  REQUIRE(ok(t->step(s)));
  CHECK(t->counters().gap_resets == 0);
  // 2000 s later (F1: the float CV covariance is singular by then)
  s.time_us += 2000000000u;
  REQUIRE(ok(t->step(s)));
  CHECK(t->counters().gap_resets == 1);
  for (const auto& e : t->outputs()) {
    for (const auto& r : e.tracks) CHECK(r.id != old_id);
  }
  CHECK(outputs_finite(*t));
  // the target is picked up again as a new track
  std::size_t reported = 0;
  std::uint32_t new_id = old_id;
  for (int j = 0; j < 15; ++j) {
    s.time_us += Case::kDtUs;
    REQUIRE(ok(t->step(s)));
    for (const auto& e : t->outputs()) {
      reported = e.tracks.size();
      if (reported > 0) new_id = e.tracks[0].id;
    }
  }
  CHECK(reported == 1);
  CHECK(new_id != old_id);
  CHECK(t->counters().gap_resets == 1);
  CHECK(outputs_finite(*t));
}

TEST_CASE_TEMPLATE("F1: max_gap_s is validated", Case, MPTRACK_CLOCKED_CASES) {
  auto t = std::make_unique<typename Case::Tracker>();
  auto p = Case::params();
  p.max_gap_s = 0.0f;
  CHECK(t->init(p) == Status::kInvalidArgument);
  p.max_gap_s = kNaN;
  CHECK(t->init(p) == Status::kInvalidArgument);
  p.max_gap_s = 2e6f;
  CHECK(t->init(p) == Status::kInvalidArgument);
  p.max_gap_s = 3600.0f;
  CHECK(t->init(p) == Status::kOk);
}

TEST_CASE_TEMPLATE("F4: amplitudes above max_amplitude are invalid", Case, MfbpCase, CphdCase) {
  auto t = make_tracker<Case>();
  const auto good = Case::target();
  auto loud = meas(good.range_m * 0.8f, good.azimuth_rad, 2e4f);  // default max_amplitude 1e4
  CHECK(t->step(scan_at<Case>(0, {good, loud})) == Status::kPartial);
  CHECK(t->counters().measurements_invalid == 1);
  loud.amplitude = 9e3f;
  CHECK(t->step(scan_at<Case>(1, {good, loud})) == Status::kOk);
  CHECK(t->counters().measurements_invalid == 1);
}
