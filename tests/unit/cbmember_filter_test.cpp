// CBMeMBer with amplitude (cbmember/cbmember_filter.h).
#include <doctest/doctest.h>

#include <cmath>
#include <memory>

#include "alloc_guard.h"
#include "mptrack/cbmember/cbmember_filter.h"
#include "phd_test_scenario.h"

using namespace mptrack;
using ScanD = Scan<double, DefaultCaps::kMaxMeasurements>;

namespace {
const phdtest::Truth kTruth[2] = {{-500.0, 10.0, 0.0, 5.0}, {300.0, -5.0, -400.0, 10.0}};

// One raw component per updated Bernoulli: a target's measurement gated by
// its track and by the birth it seeded one scan earlier already overflows.
struct OneRawCaps : DefaultCaps {
  static constexpr std::size_t kMaxComponentsPerBernoulli = 1;
  static constexpr std::size_t kMaxRawComponentsPerBernoulli = 1;
};
// Four Bernoullis: 40 clutter births per scan overflow the track list.
struct FourTrackCaps : DefaultCaps {
  static constexpr std::size_t kMaxTargets = 4;
};
}

TEST_CASE("CBMeMBer tracks two targets and its cardinality sums to about 2") {
  auto f = std::make_unique<CbMemberFilter<double>>();
  RfsFilterParams<double> p = phdtest::seed001_params();
  p.clutter_mode = ClutterMode::kEstimatedUniform;
  REQUIRE(f->init(p) == Status::kOk);
  auto scan = std::make_unique<ScanD>();
  int good = 0;
  for (int k = 0; k < 40; ++k) {
    phdtest::make_scan(*scan, k, kTruth, 2, 40, 11);
    (void)f->step(*scan);
    if (k < 10) continue;
    const auto& tracks = f->outputs()[0].tracks;
    int hit = 0;
    for (const auto& tr : kTruth) {
      for (const auto& t : tracks) {
        const double dx = t.state(0) - (tr.px + tr.vx * k);
        const double dy = t.state(2) - (tr.py + tr.vy * k);
        if (std::sqrt(dx * dx + dy * dy) < 40.0) {
          ++hit;
          break;
        }
      }
    }
    if (hit == 2 && tracks.size() == 2) ++good;
  }
  CHECK(good >= 20);
  CHECK(f->expected_targets() == doctest::Approx(2.0).epsilon(0.25));
  // SNR estimate of a 20 dB target: varsigma = 101 -> SNR about 100.
  for (const auto& t : f->outputs()[0].tracks) CHECK(t.snr == doctest::Approx(100.0).epsilon(0.5));
}

TEST_CASE("CBMeMBer step() does not allocate and labels are unique per scan") {
  auto f = std::make_unique<CbMemberFilter<double>>();
  REQUIRE(f->init(phdtest::seed001_params()) == Status::kOk);
  auto scan = std::make_unique<ScanD>();
  std::size_t allocs = 0;
  for (int k = 0; k < 15; ++k) {
    phdtest::make_scan(*scan, k, kTruth, 2, 40, 5);
    {
      mptrack::test::NoAllocScope guard;
      (void)f->step(*scan);
      allocs += guard.allocations();
    }
    const auto& tr = f->tracks();
    for (std::size_t a = 0; a < tr.size(); ++a) {
      for (std::size_t b = a + 1; b < tr.size(); ++b) CHECK(tr[a].label != tr[b].label);
    }
  }
  CHECK(allocs == 0);
}

TEST_CASE("CBMeMBer rejects invalid params and out-of-order scans") {
  auto f = std::make_unique<CbMemberFilter<double>>();
  RfsFilterParams<double> p = phdtest::seed001_params();
  p.existence_prune = 0.0;
  CHECK(f->init(p) == Status::kInvalidArgument);
  REQUIRE(f->init(phdtest::seed001_params()) == Status::kOk);
  auto scan = std::make_unique<ScanD>();
  phdtest::make_scan(*scan, 2, kTruth, 2, 5, 1);
  CHECK(f->step(*scan) == Status::kOk);
  CHECK(f->step(*scan) == Status::kOutOfOrder);
}

TEST_CASE("CBMeMBer: the raw-collection cap is a counted truncation, not a capacity error") {
  auto f = std::make_unique<CbMemberFilter<double, OneRawCaps>>();
  REQUIRE(f->init(phdtest::seed001_params()) == Status::kOk);
  auto scan = std::make_unique<ScanD>();
  for (int k = 0; k < 10; ++k) {
    phdtest::make_scan(*scan, k, kTruth, 2, 0, 3);  // no clutter: 2 targets only
    CHECK(f->step(*scan) == Status::kOk);
  }
  CHECK(f->counters().mixture_truncated > 0u);
  CHECK(f->counters().track_cap_hits == 0u);
}

TEST_CASE("CBMeMBer: a full track list leaves out low-existence Bernoullis as a counted truncation") {
  auto f = std::make_unique<CbMemberFilter<double, FourTrackCaps>>();
  REQUIRE(f->init(phdtest::seed001_params()) == Status::kOk);
  auto scan = std::make_unique<ScanD>();
  for (int k = 0; k < 10; ++k) {
    phdtest::make_scan(*scan, k, kTruth, 2, 40, 3);
    CHECK(f->step(*scan) == Status::kOk);
  }
  CHECK(f->tracks().size() == 4u);
  CHECK(f->counters().mixture_truncated > 0u);
  CHECK(f->counters().track_cap_hits == 0u);
}
