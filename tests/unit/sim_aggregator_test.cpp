// The harness's evaluator with a chosen (c, p), the run record's scan
// mapping and the aggregator (means, statuses, counters, latency, checksum),
// each on hand-computed values.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "eval/aggregator.h"
#include "eval/scan_evaluator.h"
#include "mptrack/scenario/builtin.h"
#include "run/run_loop.h"
#include "run/run_record.h"
#include "run/scan_source.h"
#include "run/truncate.h"
#include "sim_test_truth.h"
#include "writers.h"

using namespace mptrack::sim;
using mptrack::Status;
using mptrack::TrackerCounters;
namespace sc = mptrack::scenario;
using sim_test::truth_at;

namespace {

TrackOut track_at(std::uint32_t id, double x, double y, bool confirmed) {
  TrackOut t;
  t.id = id;
  t.px = x;
  t.py = y;
  t.confirmed = confirmed;
  return t;
}

/// A scan with `n_meas` measurements (ranges 1, 2, ...) and no truth.
sc::SimScan scan_with(std::uint32_t k, std::size_t n_meas) {
  sc::SimScan s;
  s.scan = k;
  for (std::size_t i = 0; i < n_meas; ++i) {
    sc::SimMeasurement m;
    m.range_m = static_cast<double>(i + 1);
    s.measurements.push_back(m);
  }
  return s;
}

ScanMetrics metrics(double ospa, std::uint32_t truths, std::uint32_t confirmed, std::uint32_t false_tracks) {
  ScanMetrics m;
  m.ospa = ospa;
  m.gospa = 2.0 * ospa;
  m.truths = truths;
  m.confirmed = confirmed;
  m.false_tracks = false_tracks;
  return m;
}

/// Run record over 3 scans with empty estimates.
RunRecord record(std::uint32_t run, std::vector<std::uint32_t> delivered, std::vector<double> latency_us) {
  RunRecord r;
  r.run = run;
  r.delivered = std::move(delivered);
  r.latency_us = std::move(latency_us);
  r.by_scan.resize(3);
  for (std::uint32_t k = 1; k <= 3; ++k) r.by_scan[k - 1].scan = k;
  return r;
}

/// Every TrackerCounters field, in declaration order.
constexpr std::uint64_t TrackerCounters::*kCounterFields[] = {
    &TrackerCounters::scans,           &TrackerCounters::scans_rejected,   &TrackerCounters::measurements_in,
    &TrackerCounters::measurements_invalid, &TrackerCounters::measurements_over_cap, &TrackerCounters::tracks_born,
    &TrackerCounters::tracks_confirmed, &TrackerCounters::tracks_deleted,  &TrackerCounters::track_cap_hits,
    &TrackerCounters::clutter_born,    &TrackerCounters::clutter_deleted,  &TrackerCounters::clutter_cap_hits,
    &TrackerCounters::bp_not_converged, &TrackerCounters::numerical_repairs, &TrackerCounters::gap_resets,
    &TrackerCounters::measurements_duplicate, &TrackerCounters::association_cap_hits,
    &TrackerCounters::tentative_evicted, &TrackerCounters::mixture_truncated};
static_assert(sizeof(kCounterFields) / sizeof(kCounterFields[0]) * sizeof(std::uint64_t) == sizeof(TrackerCounters),
              "a TrackerCounters field is missing from kCounterFields");

/// TrackerCounters with field i (0-based, declaration order) = scale * (i + 1).
TrackerCounters numbered_counters(std::uint64_t scale) {
  TrackerCounters c;
  std::uint64_t i = 0;
  for (auto f : kCounterFields) c.*f = scale * ++i;
  return c;
}

}  // namespace

TEST_CASE("sim evaluator: GOSPA components and OSPA with a chosen cutoff and order") {
  // c = 10 m, p = 2. Truth 1 has a confirmed track 5 m away; truth 2 none.
  sc::SimScan scan;
  scan.scan = 1;
  scan.truth = {truth_at(1, 0.0, 0.0, -1), truth_at(2, 1000.0, 0.0, -1)};
  EstimateOut est;
  est.tracks = {track_at(7, 3.0, 4.0, true), track_at(8, 1000.0, 0.0, false)};  // the tentative one is ignored
  ScanEvaluator ev(10.0, 2.0);
  const ScanMetrics m = ev.evaluate(scan, est);
  CHECK(m.gospa_localisation == doctest::Approx(25.0));   // 5^2
  CHECK(m.gospa_missed == doctest::Approx(50.0));         // c^p / 2 for truth 2
  CHECK(m.gospa_false == 0.0);
  CHECK(m.gospa_num_missed == 1);
  CHECK(m.gospa_num_false == 0);
  CHECK(m.gospa == doctest::Approx(std::sqrt(75.0)));
  CHECK(m.ospa == doctest::Approx(std::sqrt((25.0 + 100.0) / 2.0)));  // one cut-off term of c^p over max(m, n) = 2
  CHECK(m.false_tracks == 0);
  CHECK_THROWS_AS(ScanEvaluator(10.0, 0.5), std::runtime_error);
}

TEST_CASE("sim run record: the estimate of tracker step i lands on the i-th delivered scan") {
  // Scan 2 was dropped: the tracker's second step consumed scan 3.
  std::vector<EstimateOut> finals(3);
  finals[0].scan = 1;
  finals[0].tracks = {track_at(1, 0, 0, true)};
  finals[1].scan = 2;
  finals[1].tracks = {track_at(2, 0, 0, true)};
  finals[2].scan = 3;  // beyond the delivered steps: dropped
  const std::vector<EstimateOut> by_scan = estimates_by_scan(finals, {1, 3}, 3);
  REQUIRE(by_scan.size() == 3);
  CHECK(by_scan[0].scan == 1);
  CHECK(by_scan[0].tracks.at(0).id == 1);
  CHECK(by_scan[1].scan == 2);
  CHECK(by_scan[1].tracks.empty());
  CHECK(by_scan[2].scan == 3);
  CHECK(by_scan[2].tracks.at(0).id == 2);
}

TEST_CASE("sim aggregator: every TrackerCounters field is summed and written, gap_resets and measurements_duplicate too") {
  Aggregator agg(SummaryHeader{"s", "t", 2, 3, 1, 1.0, 1, 3, TrackScoringParams{}});
  const std::vector<sc::SimScan> scans = {scan_with(1, 0), scan_with(2, 0), scan_with(3, 0)};
  const std::vector<ScanMetrics> m(3);
  RunRecord a = record(0, {1, 2, 3}, {1, 1, 1});
  a.counters = numbered_counters(1);
  RunRecord b = record(1, {1, 2, 3}, {1, 1, 1});
  b.counters = numbered_counters(100);
  agg.add_run(scans, a, m);
  agg.add_run(scans, b, m);
  const Summary s = agg.summary();
  std::uint64_t i = 0;
  for (auto f : kCounterFields) CHECK(s.counters.*f == 101 * ++i);
  CHECK(s.counters.gap_resets == 101 * 15);
  CHECK(s.counters.measurements_duplicate == 101 * 16);
  const auto j = summary_to_json(s);
  CHECK(j["counters"]["gap_resets"] == 101 * 15);
  CHECK(j["counters"]["measurements_duplicate"] == 101 * 16);
  CHECK(j["counters"]["association_cap_hits"] == 101 * 17);
  CHECK(j["counters"]["tentative_evicted"] == 101 * 18);
  CHECK(j["counters"]["mixture_truncated"] == 101 * 19);
  CHECK(j["counters"].size() == 19);
}

TEST_CASE("sim aggregator: hand-computed means over evaluation scans, statuses, latency and measurements") {
  // 2 runs x 3 scans, evaluation interval 2..3.
  Aggregator agg(SummaryHeader{"s", "t", 2, 3, 1, 1.0, 2, 3, TrackScoringParams{}});
  const std::vector<sc::SimScan> scans = {scan_with(1, 4), scan_with(2, 6), scan_with(3, 8)};
  RunRecord a = record(0, {1, 2, 3}, {10, 20, 30});
  a.statuses = {Status::kOk, Status::kPartial, Status::kCapacityExceeded, Status::kOk};
  a.by_scan[0].tracks = {track_at(5, 0, 0, true)};
  a.by_scan[2].tracks = {track_at(6, 0, 0, true), track_at(9, 0, 0, false)};
  agg.add_run(scans, a, {metrics(100, 2, 1, 0), metrics(10, 2, 1, 0), metrics(20, 2, 3, 1)});
  RunRecord b = record(1, {1, 3}, {40, 0, 50});  // scan 2 not delivered
  b.statuses = {Status::kOk, Status::kNumericalError, Status::kOk};
  b.by_scan[1].tracks = {track_at(5, 0, 0, true)};
  agg.add_run(scans, b, {metrics(200, 2, 0, 0), metrics(30, 1, 0, 0), metrics(40, 1, 2, 2)});
  const Summary s = agg.summary();

  CHECK(s.eval_scan_count == 4);
  CHECK(s.mean_ospa == doctest::Approx((10.0 + 20.0 + 30.0 + 40.0) / 4.0));
  CHECK(s.mean_gospa == doctest::Approx(2.0 * 25.0));
  CHECK(s.mean_truths == doctest::Approx((2.0 + 2.0 + 1.0 + 1.0) / 4.0));
  CHECK(s.mean_confirmed_tracks == doctest::Approx((1.0 + 3.0 + 0.0 + 2.0) / 4.0));
  CHECK(s.nft == doctest::Approx((0.0 + 1.0 + 0.0 + 2.0) / 4.0));
  CHECK(s.cardinality_error == doctest::Approx((1.0 + 1.0 + 1.0 + 1.0) / 4.0));
  REQUIRE(s.ospa_per_scan.size() == 3);
  CHECK(s.ospa_per_scan[0] == doctest::Approx(150.0));  // every scan, evaluated or not
  CHECK(s.ospa_per_scan[1] == doctest::Approx(20.0));
  CHECK(s.ospa_per_scan[2] == doctest::Approx(30.0));
  CHECK(s.tracks_found_per_run == doctest::Approx((2.0 + 1.0) / 2.0));  // run 0: ids 5, 6; run 1: id 5
  // Measurements per delivered scan: run 0 gives 4 + 6 + 8, run 1 gives 4 + 8.
  CHECK(s.mean_measurements == doctest::Approx(30.0 / 5.0));
  CHECK(s.latency.count == 5);
  CHECK(s.latency.max_us == 50.0);
  CHECK(s.latency.p50_us == 30.0);
  CHECK(s.steps_partial == 1);
  CHECK(s.steps_capacity == 1);
  CHECK(s.step_errors == 1);
  CHECK(s.steps_not_ok() == 3);
  CHECK(s.step_status.at("ok") == 4);
  CHECK(s.step_status.at("numerical_error") == 1);
}

TEST_CASE("sim aggregator: each run's mean OSPA over its evaluation scans, in run order") {
  // 2 runs x 3 scans, evaluation interval 2..3: scan 1 (OSPA 100 / 200) is left out.
  Aggregator agg(SummaryHeader{"s", "t", 2, 3, 1, 1.0, 2, 3, TrackScoringParams{}});
  const std::vector<sc::SimScan> scans = {scan_with(1, 0), scan_with(2, 0), scan_with(3, 0)};
  agg.add_run(scans, record(0, {1, 2, 3}, {0, 0, 0}), {metrics(100, 1, 1, 0), metrics(10, 1, 1, 0), metrics(20, 1, 1, 0)});
  agg.add_run(scans, record(1, {1, 2, 3}, {0, 0, 0}), {metrics(200, 1, 1, 0), metrics(30, 1, 1, 0), metrics(50, 1, 1, 0)});
  const Summary s = agg.summary();
  REQUIRE(s.ospa_per_run.size() == 2);
  CHECK(s.ospa_per_run[0] == doctest::Approx(15.0));  // (10 + 20) / 2
  CHECK(s.ospa_per_run[1] == doctest::Approx(40.0));  // (30 + 50) / 2
}

TEST_CASE("sim aggregator: each run's MOSPA (Mahalanobis) over its evaluation scans, in run order") {
  // As above with the Mahalanobis OSPA: scan 1 (9 / 8) is left out.
  Aggregator agg(SummaryHeader{"s", "t", 2, 3, 1, 1.0, 2, 3, TrackScoringParams{}});
  const std::vector<sc::SimScan> scans = {scan_with(1, 0), scan_with(2, 0), scan_with(3, 0)};
  std::vector<ScanMetrics> m0 = {metrics(0, 1, 1, 0), metrics(0, 1, 1, 0), metrics(0, 1, 1, 0)};
  std::vector<ScanMetrics> m1 = m0;
  const double run0[3] = {9.0, 2.0, 4.0}, run1[3] = {8.0, 6.0, 7.0};
  for (std::size_t k = 0; k < 3; ++k) {
    m0[k].ospa_mahalanobis = run0[k];
    m1[k].ospa_mahalanobis = run1[k];
  }
  agg.add_run(scans, record(0, {1, 2, 3}, {0, 0, 0}), m0);
  agg.add_run(scans, record(1, {1, 2, 3}, {0, 0, 0}), m1);
  const Summary s = agg.summary();
  REQUIRE(s.ospa_mahalanobis_per_run.size() == 2);
  CHECK(s.ospa_mahalanobis_per_run[0] == doctest::Approx(3.0));  // (2 + 4) / 2
  CHECK(s.ospa_mahalanobis_per_run[1] == doctest::Approx(6.5));  // (6 + 7) / 2
  CHECK(s.mean_ospa_mahalanobis == doctest::Approx((2.0 + 4.0 + 6.0 + 7.0) / 4.0));
}

TEST_CASE("sim aggregator: the measurement checksum chains over delivered scans only, in order") {
  const std::vector<sc::SimScan> scans = {scan_with(1, 2), scan_with(2, 3), scan_with(3, 1)};
  Aggregator agg(SummaryHeader{"s", "t", 1, 3, 1, 1.0, 1, 3, TrackScoringParams{}});
  agg.add_run(scans, record(0, {1, 3}, {0, 0, 0}), std::vector<ScanMetrics>(3));
  const std::uint64_t expected = measurement_checksum(scans[2], measurement_checksum(scans[0], kChecksumSeed));
  CHECK(agg.summary().measurement_checksum == expected);
  CHECK(expected != measurement_checksum(scans[0], measurement_checksum(scans[2], kChecksumSeed)));
}

TEST_CASE("sim evaluator: matched lists each truth within c of its OSPA-assigned track, with the distance") {
  // c = 10 m. Truth 1 <- track at 5 m (3-4-5); truth 2's nearest track is 12 m away (beyond c).
  sc::SimScan scan;
  scan.scan = 1;
  scan.truth = {truth_at(1, 0.0, 0.0, -1), truth_at(2, 100.0, 0.0, -1)};
  EstimateOut est;
  est.tracks = {track_at(7, 3.0, 4.0, true), track_at(8, 112.0, 0.0, true)};
  ScanEvaluator ev(10.0, 2.0);
  const ScanMetrics m = ev.evaluate(scan, est);
  REQUIRE(m.matched.size() == 1);
  CHECK(m.matched[0].target_id == 1);
  CHECK(m.matched[0].distance_m == doctest::Approx(5.0));
}

TEST_CASE("sim aggregator: confirmed-track count per scan, mean and standard deviation over runs") {
  // 3 runs x 2 scans; confirmed counts scan 1: 1, 2, 3 (mean 2, population std sqrt(2/3));
  // scan 2: 4, 4, 4 (std 0). Truths: 2, 2, 1 at scan 1.
  Aggregator agg(SummaryHeader{"s", "t", 3, 2, 1, 1.0, 1, 2, TrackScoringParams{}});
  const std::vector<sc::SimScan> scans = {scan_with(1, 0), scan_with(2, 0)};
  const std::uint32_t scan1[] = {1, 2, 3};
  const std::uint32_t truths1[] = {2, 2, 1};
  for (std::uint32_t r = 0; r < 3; ++r) {
    RunRecord rec = record(r, {1, 2}, {0, 0, 0});
    rec.by_scan.resize(2);
    agg.add_run(scans, rec, {metrics(0, truths1[r], scan1[r], 0), metrics(0, 1, 4, 0)});
  }
  const Summary s = agg.summary();
  REQUIRE(s.confirmed_mean_per_scan.size() == 2);
  CHECK(s.confirmed_mean_per_scan[0] == doctest::Approx(2.0));
  CHECK(s.confirmed_std_per_scan[0] == doctest::Approx(std::sqrt(2.0 / 3.0)));
  CHECK(s.confirmed_mean_per_scan[1] == doctest::Approx(4.0));
  CHECK(s.confirmed_std_per_scan[1] == doctest::Approx(0.0));
  CHECK(s.truths_per_scan[0] == doctest::Approx(5.0 / 3.0));
}

TEST_CASE("sim aggregator: per-object RMSE over matched evaluation scans, sorted, and objects never matched") {
  // 1 run x 3 scans, evaluation 2..3. Target 1 matched at 3 m (scan 2) and 4 m (scan 3):
  // RMSE sqrt((9 + 16) / 2). Target 2 alive at scans 2, 3, matched only at scan 1 (not
  // evaluated): never matched. Target 3 matched at 1 m on scan 3: RMSE 1.
  Aggregator agg(SummaryHeader{"s", "t", 1, 3, 1, 1.0, 2, 3, TrackScoringParams{}});
  std::vector<sc::SimScan> scans = {scan_with(1, 0), scan_with(2, 0), scan_with(3, 0)};
  for (auto& s : scans) s.truth = {truth_at(1, 0, 0, -1), truth_at(2, 50, 0, -1)};
  scans[2].truth.push_back(truth_at(3, 90, 0, -1));
  std::vector<ScanMetrics> m(3);
  m[0].matched = {ObjectError{2, 7.0}};
  m[1].matched = {ObjectError{1, 3.0}};
  m[2].matched = {ObjectError{1, 4.0}, ObjectError{3, 1.0}};
  agg.add_run(scans, record(0, {1, 2, 3}, {0, 0, 0}), m);
  const Summary s = agg.summary();
  REQUIRE(s.object_rmse_m.size() == 2);
  CHECK(s.object_rmse_m[0] == doctest::Approx(1.0));
  CHECK(s.object_rmse_m[1] == doctest::Approx(std::sqrt(12.5)));
  CHECK(s.objects_never_matched == 1);
  CHECK(s.object_rmse_quantile(0.5) == doctest::Approx(1.0));   // nearest rank: ceil(0.5 * 2) = 1st
  CHECK(s.object_rmse_quantile(0.9) == doctest::Approx(std::sqrt(12.5)));
}

namespace {

/// Truncates its mixture on the steps listed (1-based) and on flush when
/// asked; nothing else.
class TruncatingTracker final : public TrackerAdapter {
 public:
  TruncatingTracker(std::vector<std::uint32_t> steps, bool on_flush) : steps_(std::move(steps)), on_flush_(on_flush) {}
  std::string init(const TrackerSetup&) override { return ""; }
  Status step(const sc::SimScan&, std::vector<EstimateOut>&) override {
    ++n_;
    for (const std::uint32_t k : steps_) c_.mixture_truncated += k == n_ ? 7u : 0u;  // 7 components at once
    return Status::kOk;
  }
  Status flush(std::vector<EstimateOut>&) override {
    if (on_flush_) ++c_.mixture_truncated;
    return Status::kOk;
  }
  TrackerCounters counters() const override { return c_; }

 private:
  std::vector<std::uint32_t> steps_;
  bool on_flush_;
  std::uint32_t n_ = 0;
  TrackerCounters c_{};
};

/// A smoother of lag 2: step n hands out the estimate of step n - 2, and
/// flush() the last two.
class LaggingTracker final : public TrackerAdapter {
 public:
  std::string init(const TrackerSetup&) override { return ""; }
  Status step(const sc::SimScan&, std::vector<EstimateOut>& out) override {
    ++n_;
    if (n_ > 2) emit(n_ - 2, out);
    return Status::kOk;
  }
  Status flush(std::vector<EstimateOut>& out) override {
    for (std::uint32_t k = n_ > 2 ? n_ - 1 : 1; k <= n_; ++k) emit(k, out);
    return Status::kOk;
  }
  TrackerCounters counters() const override { return {}; }

 private:
  static void emit(std::uint32_t step, std::vector<EstimateOut>& out) {
    out.emplace_back();
    out.back().scan = step;
  }
  std::uint32_t n_ = 0;
};

/// LaggingTracker that also hands out a provisional estimate of the scan
/// it just consumed on steps 2 and 4.
class ProvisionalTracker final : public TrackerAdapter {
 public:
  std::string init(const TrackerSetup&) override { return ""; }
  Status step(const sc::SimScan& s, std::vector<EstimateOut>& out) override { return lag_.step(s, out); }
  Status flush(std::vector<EstimateOut>& out) override { return lag_.flush(out); }
  TrackerCounters counters() const override { return {}; }
  bool provisional(EstimateOut& out) const override {
    ++calls_;
    if (calls_ != 2 && calls_ != 4) return false;
    out = EstimateOut{};
    out.scan = calls_;
    return true;
  }

 private:
  LaggingTracker lag_;
  mutable std::uint32_t calls_ = 0;  // one call per step
};

/// The first 5 scans of seed000-s2, run 0 begun.
std::unique_ptr<MeasurementSource> five_scans() {
  sc::ScenarioSpec spec;
  REQUIRE(sc::builtin_scenario("seed000-s2", spec));
  truncate_scans(spec, 5);
  auto source = std::make_unique<MeasurementSource>(spec, 1, 1.0);
  source->begin_run(0);
  return source;
}

}  // namespace

TEST_CASE("sim run loop: each estimate records the scan after whose step() it was handed out") {
  const std::unique_ptr<MeasurementSource> owned = five_scans();
  MeasurementSource& source = *owned;
  LaggingTracker lag;
  const RunRecord rec = run_tracker(source, lag, 0, nullptr);
  REQUIRE(rec.by_scan.size() == 5);
  // Scans 1..3 after steps 3..5; scans 4 and 5 by flush(), after scan 5.
  const std::uint32_t expected[5] = {3, 4, 5, 5, 5};
  for (std::uint32_t k = 1; k <= 5; ++k) CHECK(rec.by_scan[k - 1].reported_after_scan == expected[k - 1]);
}

TEST_CASE("sim run loop: steps whose mixture truncation grew are counted once each, flush included") {
  const std::unique_ptr<MeasurementSource> owned = five_scans();
  MeasurementSource& source = *owned;
  TruncatingTracker a({2, 4}, true);
  const RunRecord ra = run_tracker(source, a, 0, nullptr);
  CHECK(ra.steps_truncating == 3);  // steps 2 and 4 (7 components each) and flush
  CHECK(ra.counters.mixture_truncated == 15);
  TruncatingTracker b({5}, false);
  const RunRecord rb = run_tracker(source, b, 1, nullptr);
  CHECK(rb.steps_truncating == 1);

  Aggregator agg(SummaryHeader{"s", "t", 2, 5, 1, 1.0, 1, 5, TrackScoringParams{}});
  const std::vector<ScanMetrics> m(5);
  agg.add_run(source.scans(), ra, m);
  agg.add_run(source.scans(), rb, m);
  const Summary s = agg.summary();
  CHECK(s.steps_truncating == 4);
  CHECK(summary_to_json(s)["steps_mixture_truncated"] == 4);
}

TEST_CASE("sim aggregator: real-time OSPA averages the evaluation scans that have a real-time estimate") {
  // 2 runs x 3 scans, evaluation interval 2..3. Run a has a real-time
  // estimate of scans 2 and 3 (OSPA 40, 60), run b of scan 3 only (OSPA 80;
  // its scan 2 entry, OSPA 500, was never handed out in time and does not count).
  Aggregator agg(SummaryHeader{"s", "t", 2, 3, 1, 1.0, 2, 3, TrackScoringParams{}});
  const std::vector<sc::SimScan> scans = {scan_with(1, 0), scan_with(2, 0), scan_with(3, 0)};
  const std::vector<ScanMetrics> m = {metrics(1, 1, 0, 0), metrics(1, 1, 0, 0), metrics(1, 1, 0, 0)};
  RunRecord a = record(0, {1, 2, 3}, {0, 0, 0});
  a.provisional_by_scan = a.by_scan;
  a.provisional_by_scan[1].reported_after_scan = 2;
  a.provisional_by_scan[2].reported_after_scan = 3;
  const std::vector<ScanMetrics> ra = {metrics(900, 1, 0, 0), metrics(40, 1, 1, 0), metrics(60, 1, 1, 0)};
  RunRecord b = record(1, {1, 2, 3}, {0, 0, 0});
  b.provisional_by_scan = b.by_scan;
  b.provisional_by_scan[2].reported_after_scan = 3;
  const std::vector<ScanMetrics> rb = {metrics(900, 1, 0, 0), metrics(500, 1, 0, 0), metrics(80, 1, 1, 0)};
  agg.add_run(scans, a, m, &ra);
  agg.add_run(scans, b, m, &rb);
  const Summary s = agg.summary();
  CHECK(s.mean_realtime_ospa == doctest::Approx(60.0));  // (40 + 60 + 80) / 3
  CHECK(s.realtime_scan_fraction == doctest::Approx(0.75));  // 3 of 4 evaluation scans
  CHECK(s.mean_ospa == doctest::Approx(1.0));
}

TEST_CASE("sim run loop: provisional_by_scan holds the provisional estimate each step handed out for its own scan") {
  const std::unique_ptr<MeasurementSource> owned = five_scans();
  MeasurementSource& source = *owned;
  LaggingTracker lag;  // finalises scan k after step k + 2: never its own scan in time
  const RunRecord plain = run_tracker(source, lag, 0, nullptr);
  REQUIRE(plain.provisional_by_scan.size() == 5);
  for (const EstimateOut& e : plain.provisional_by_scan) CHECK(e.reported_after_scan == 0);
  CHECK(plain.provisional_steps == 0);
  ProvisionalTracker prov;
  const RunRecord rec = run_tracker(source, prov, 0, nullptr);
  REQUIRE(rec.provisional_by_scan.size() == 5);
  const std::uint32_t expected[5] = {0, 2, 0, 4, 0};  // scans 2 and 4, handed out after their own step
  for (std::uint32_t k = 1; k <= 5; ++k) CHECK(rec.provisional_by_scan[k - 1].reported_after_scan == expected[k - 1]);
  CHECK(rec.provisional_steps == 2);
}
