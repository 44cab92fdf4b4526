// The tracker contract (core/include/mptrack/tracker_contract.h), run as
// behaviours over every tracker: GNN, MF-BP (online filter and window
// smoother), GM-PHD, GM-CPHD, CBMeMBer. Each TEST_CASE is one rule of the
// contract; the per-tracker fixtures are in tracker_cases.h.
#include <doctest/doctest.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "mptrack/tracker_contract.h"
#include "tracker_cases.h"

using mptrack::Status;
using namespace tracker_cases;

#define MPTRACK_CONTRACT_CASES GnnCase, MfbpCase, MfbpSmootherCase, PhdCase, CphdCase, CbmCase, MultipathCase, MptfCase

namespace {

// Every tracker type in core satisfies the compile-time contract ...
static_assert(mptrack::is_tracker_v<GnnCase::Tracker>);
static_assert(mptrack::is_tracker_v<MfbpCase::Tracker>);
static_assert(mptrack::is_tracker_v<mptrack::MfbpTracker<double, mptrack::DefaultCaps>>);
static_assert(mptrack::is_tracker_v<PhdCase::Tracker>);
static_assert(mptrack::is_tracker_v<CphdCase::Tracker>);
static_assert(mptrack::is_tracker_v<CbmCase::Tracker>);
static_assert(mptrack::is_tracker_v<MultipathCase::Tracker>);
static_assert(mptrack::is_tracker_v<MptfCase::Tracker>);

// ... and the detector is not vacuous: a type missing one member is not a tracker.
struct NoFlush {
  using Scalar = float;
  struct Params {};
  using ScanType = mptrack::Scan<float, 4>;
  using Estimate = mptrack::ScanEstimate<float, 4, 1>;
  using OutputQueue = mptrack::StaticVector<Estimate, 1>;
  static Status validate(const Params&, mptrack::ParamError*) { return Status::kOk; }
  Status init(const Params&) { return Status::kOk; }
  Status step(const ScanType&) { return Status::kOk; }
  const OutputQueue& outputs() const { return q_; }
  const mptrack::TrackerCounters& counters() const { return c_; }
  const Params& params() const { return p_; }
  OutputQueue q_;
  mptrack::TrackerCounters c_;
  Params p_;
};
static_assert(!mptrack::is_tracker_v<NoFlush>);
struct WrongStepResult : NoFlush {
  void step(const ScanType&) {}
  Status flush() { return Status::kOk; }
};
static_assert(!mptrack::is_tracker_v<WrongStepResult>);
struct Complete : NoFlush {
  Status flush() { return Status::kOk; }
};
static_assert(mptrack::is_tracker_v<Complete>);

/// Every compile-time cap counter of TrackerCounters.
std::uint64_t cap_hits(const mptrack::TrackerCounters& c) {
  return c.track_cap_hits + c.clutter_cap_hits + c.measurements_over_cap + c.association_cap_hits;
}

/// The scan times listed by outputs() (the scans just finalised).
template <class Tracker>
void collect_times(const Tracker& t, std::vector<std::uint64_t>& times) {
  for (const auto& e : t.outputs()) times.push_back(e.time_us);
}

template <class Case>
std::vector<mptrack::Measurement<float>> grid_scan(int n) {
  std::vector<mptrack::Measurement<float>> ms;
  for (int i = 0; i < n; ++i) ms.push_back(Case::grid(i));
  return ms;
}

}  // namespace

TEST_CASE_TEMPLATE("contract: validate() names the offending field", Case, MPTRACK_CONTRACT_CASES) {
  using Tracker = typename Case::Tracker;
  auto p = Case::params();
  mptrack::ParamError where;
  REQUIRE(Tracker::validate(p, &where) == Status::kOk);
  p.max_gap_s = -1.0f;  // a field every tracker has, in the same unit
  CHECK(Tracker::validate(p, &where) == Status::kInvalidArgument);
  CHECK(std::string(where.field) == "max_gap_s");
  auto t = std::make_unique<Tracker>();
  CHECK(t->init(p) == Status::kInvalidArgument);
  CHECK(t->step(scan_at<Case>(0, {Case::target()})) == Status::kNotInitialized);
}

TEST_CASE_TEMPLATE("contract: before init() step() and flush() are refused", Case, MPTRACK_CONTRACT_CASES) {
  auto t = std::make_unique<typename Case::Tracker>();
  CHECK(t->step(scan_at<Case>(0, {Case::target()})) == Status::kNotInitialized);
  CHECK(t->flush() == Status::kNotInitialized);
  CHECK(t->outputs().empty());
  CHECK(t->counters().scans_rejected == 1);
  CHECK(t->counters().scans == 0);
}

TEST_CASE_TEMPLATE("contract: a refused scan empties outputs() and is counted", Case,
                   MPTRACK_CONTRACT_CASES) {
  auto t = make_tracker<Case>();
  bool had_outputs = false;
  for (std::uint64_t k = 0; k < 8; ++k) {
    REQUIRE(t->step(scan_at<Case>(k, {Case::target()})) == Status::kOk);
    had_outputs = had_outputs || !t->outputs().empty();
  }
  REQUIRE(had_outputs);
  REQUIRE(!t->outputs().empty());  // scan 7 finalised something for every case
  CHECK(t->step(scan_at<Case>(7, {Case::target()})) == Status::kOutOfOrder);
  CHECK(t->outputs().empty());
  CHECK(t->counters().scans_rejected == 1);
  CHECK(t->counters().scans == 8);
}

TEST_CASE_TEMPLATE("contract: every accepted scan is finalised exactly once, in order", Case,
                   MPTRACK_CONTRACT_CASES) {
  auto t = make_tracker<Case>();
  std::vector<std::uint64_t> accepted;
  std::vector<std::uint64_t> finalised;
  for (std::uint64_t k = 0; k < 23; ++k) {
    const auto scan = scan_at<Case>(k, {Case::target()});
    if (k == 11) {  // a refused scan in the middle finalises nothing
      REQUIRE(t->step(scan_at<Case>(9, {})) == Status::kOutOfOrder);
    }
    REQUIRE(t->step(scan) == Status::kOk);
    accepted.push_back(scan.time_us);
    collect_times(*t, finalised);
  }
  REQUIRE(t->flush() == Status::kOk);
  collect_times(*t, finalised);
  CHECK(finalised == accepted);
}

TEST_CASE_TEMPLATE("contract: flush() then later scans continue the run", Case, MPTRACK_CONTRACT_CASES) {
  auto t = make_tracker<Case>();
  std::vector<std::uint64_t> finalised;
  for (std::uint64_t k = 0; k < 5; ++k) {
    REQUIRE(t->step(scan_at<Case>(k, {Case::target()})) == Status::kOk);
    collect_times(*t, finalised);
  }
  REQUIRE(t->flush() == Status::kOk);
  collect_times(*t, finalised);
  CHECK(finalised.size() == 5);
  REQUIRE(t->flush() == Status::kOk);  // nothing held: a second flush finalises nothing
  CHECK(t->outputs().empty());
  for (std::uint64_t k = 5; k < 10; ++k) {
    REQUIRE(t->step(scan_at<Case>(k, {Case::target()})) == Status::kOk);
    collect_times(*t, finalised);
  }
  REQUIRE(t->flush() == Status::kOk);
  collect_times(*t, finalised);
  CHECK(finalised.size() == 10);
  CHECK(t->counters().scans == 10);
}

TEST_CASE_TEMPLATE("contract: a cap hit returns kCapacityExceeded and is counted, never kOk", Case,
                   MPTRACK_CONTRACT_CASES) {
  // 40 well-separated targets for 16 track slots (SmallBoardCaps).
  auto t = make_tracker<Case>();
  const auto ms = grid_scan<Case>(40);
  int capacity_steps = 0;
  for (std::uint64_t k = 0; k < 8; ++k) {
    const std::uint64_t before = cap_hits(t->counters());
    const Status s = t->step(scan_at<Case>(k, ms));
    const bool hit = cap_hits(t->counters()) > before;
    CAPTURE(k);
    CHECK(hit == (s == Status::kCapacityExceeded));
    if (s != Status::kCapacityExceeded) CHECK(s == Status::kOk);
    capacity_steps += hit ? 1 : 0;
  }
  CHECK(capacity_steps > 0);
}

TEST_CASE_TEMPLATE("contract: counters add up", Case, MPTRACK_CONTRACT_CASES) {
  auto t = make_tracker<Case>();
  std::uint64_t offered = 0;
  std::uint64_t calls = 0;
  for (std::uint64_t k = 0; k < 12; ++k) {
    auto ms = grid_scan<Case>(3);
    if (k % 4 == 1) ms.push_back(meas(kNaN, 0.0f, 5.0f));  // one invalid measurement
    (void)t->step(scan_at<Case>(k, ms));
    ++calls;
    offered += ms.size();
    if (k % 5 == 2) {  // a repeated time: refused whole, its measurements are not offered
      (void)t->step(scan_at<Case>(k, ms));
      ++calls;
    }
  }
  const auto& c = t->counters();
  CHECK(c.scans + c.scans_rejected == calls);
  CHECK(c.scans_rejected == 2);
  CHECK(c.measurements_in == offered);
  CHECK(c.measurements_invalid == 3);
  CHECK(c.tracks_confirmed <= c.tracks_born);
  CHECK(c.tracks_deleted <= c.tracks_born);
}
