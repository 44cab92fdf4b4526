// GM-PHD and GM-CPHD with amplitude (phd/phd_filter.h) on the small seed
// 001-like scenario of phd_test_scenario.h: two targets, 40 uniform
// Rayleigh clutter points per scan.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>

#include "alloc_guard.h"
#include "mptrack/phd/phd_filter.h"
#include "phd_test_scenario.h"

using namespace mptrack;
using ScanD = Scan<double, DefaultCaps::kMaxMeasurements>;

namespace {

const phdtest::Truth kTruth[2] = {{-500.0, 10.0, 0.0, 5.0}, {300.0, -5.0, -400.0, 10.0}};

// Runs `scans` scans; returns the number of scans (from scan 10 on) whose
// extracted tracks are exactly the two targets within 40 m each.
template <class Filter>
int run_two_targets(Filter& f, const RfsFilterParams<double>& p, int scans, int clutter) {
  REQUIRE(f.init(p) == Status::kOk);
  auto scan = std::make_unique<ScanD>();
  int good = 0;
  for (int k = 0; k < scans; ++k) {
    phdtest::make_scan(*scan, k, kTruth, 2, clutter, 11);
    const Status st = f.step(*scan);
    CHECK((st == Status::kOk || st == Status::kCapacityExceeded));
    if (k < 10) continue;
    const auto& tracks = f.outputs()[0].tracks;
    if (tracks.size() != 2) continue;
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
    if (hit == 2) ++good;
  }
  return good;
}

/// Smallest reported existence min(w, 1) over `scans` scans of the two-target scene.
double min_reported_existence(const RfsFilterParams<double>& p, int scans) {
  auto f = std::make_unique<GmPhdFilter<double>>();
  REQUIRE(f->init(p) == Status::kOk);
  auto scan = std::make_unique<ScanD>();
  double lowest = 2.0;
  for (int k = 0; k < scans; ++k) {
    phdtest::make_scan(*scan, k, kTruth, 2, 40, 11);
    (void)f->step(*scan);
    for (const auto& t : f->outputs()[0].tracks) lowest = t.existence < lowest ? t.existence : lowest;
  }
  return lowest;
}

}  // namespace

TEST_CASE("GM-PHD reports only components heavier than extract_threshold, also above 0.5") {
  RfsFilterParams<double> p = phdtest::seed001_params();
  p.clutter_mode = ClutterMode::kEstimatedUniform;
  // At the default 0.5 some reported component weighs at most 0.95 (so the
  // stricter threshold below has something to hold back).
  REQUIRE(min_reported_existence(p, 40) <= 0.95);
  p.extract_threshold = 0.95;
  CHECK(min_reported_existence(p, 40) > 0.95);
}

TEST_CASE("GM-PHD with amplitude tracks two targets in 40 clutter points per scan") {
  auto f = std::make_unique<GmPhdFilter<double>>();
  RfsFilterParams<double> p = phdtest::seed001_params();
  p.clutter_mode = ClutterMode::kEstimatedUniform;
  const int good = run_two_targets(*f, p, 40, 40);
  // 30 evaluated scans; a PHD drops a track for a scan after a miss (P_D 0.98).
  CHECK(good >= 24);
  CHECK(f->expected_targets() == doctest::Approx(2.0).epsilon(0.1));
}

TEST_CASE("estimated uniform clutter rate converges to the true 40 per scan") {
  auto f = std::make_unique<GmPhdFilter<double>>();
  RfsFilterParams<double> p = phdtest::seed001_params();
  p.clutter_mode = ClutterMode::kEstimatedUniform;
  p.clutter_rate = 10.0;  // wrong prior
  (void)run_two_targets(*f, p, 40, 40);
  CHECK(f->clutter().total_rate() == doctest::Approx(40.0).epsilon(0.1));
  // Rayleigh clutter of unit noise power: the Weibull scale (b = 1) is 1.
  CHECK(f->clutter().source(0).power.mean() == doctest::Approx(1.0).epsilon(0.15));
}

TEST_CASE("GM-CPHD MAP cardinality is 2 and the tracks follow the targets") {
  auto f = std::make_unique<GmCphdFilter<double>>();
  RfsFilterParams<double> p = phdtest::seed001_params();
  const int good = run_two_targets(*f, p, 40, 40);
  CHECK(good >= 24);
  CHECK(f->cardinality().map() == 2);
  CHECK(f->cardinality().probability(2) > 0.8);
}

TEST_CASE("amplitude suppresses clutter-born false tracks compared with kinematics only") {
  auto with_amp = std::make_unique<GmPhdFilter<double>>();
  auto without = std::make_unique<GmPhdFilter<double>>();
  RfsFilterParams<double> p = phdtest::seed001_params();
  p.clutter_mode = ClutterMode::kKnownUniform;
  const int good_amp = run_two_targets(*with_amp, p, 40, 80);
  p.amplitude.use_amplitude = false;
  const int good_ki = run_two_targets(*without, p, 40, 80);
  CHECK(good_amp > good_ki);
}

TEST_CASE("estimated clutter map finds a hot spot and its rate") {
  auto f = std::make_unique<GmPhdFilter<double>>();
  RfsFilterParams<double> p = phdtest::seed001_params();
  p.clutter_mode = ClutterMode::kEstimatedMap;
  REQUIRE(f->init(p) == Status::kOk);
  auto scan = std::make_unique<ScanD>();
  for (int k = 0; k < 30; ++k) {
    phdtest::make_scan(*scan, k, kTruth, 2, 20, 3);
    phdtest::Lcg rng(static_cast<std::uint64_t>(k) + 99u);
    for (int c = 0; c < 10; ++c) {  // hot spot at (400, 400), sigma 10 m
      const double u = phdtest::kThreshold * phdtest::kThreshold - dmath::dlog(rng.uniform());
      phdtest::add_xy(*scan, 400.0 + 10.0 * rng.normal(), 400.0 + 10.0 * rng.normal(), std::sqrt(u));
    }
    (void)f->step(*scan);
  }
  REQUIRE(f->clutter().size() == 2);
  const auto& hs = f->clutter().source(1);
  CHECK(hs.mean(0) == doctest::Approx(400.0).epsilon(0.02));
  CHECK(hs.mean(1) == doctest::Approx(400.0).epsilon(0.02));
  CHECK(hs.rate() == doctest::Approx(10.0).epsilon(0.15));
  CHECK(f->clutter().source(0).rate() == doctest::Approx(20.0).epsilon(0.2));
  // No extracted track sits on the hot spot.
  for (const auto& t : f->outputs()[0].tracks) {
    CHECK(std::abs(t.state(0) - 400.0) + std::abs(t.state(2) - 400.0) > 100.0);
  }
}

TEST_CASE("PHD and CPHD step() do not allocate") {
  auto phd_f = std::make_unique<GmPhdFilter<double>>();
  auto cphd_f = std::make_unique<GmCphdFilter<double>>();
  RfsFilterParams<double> p = phdtest::seed001_params();
  REQUIRE(phd_f->init(p) == Status::kOk);
  REQUIRE(cphd_f->init(p) == Status::kOk);
  auto scan = std::make_unique<ScanD>();
  std::size_t allocs = 0;
  for (int k = 0; k < 10; ++k) {
    phdtest::make_scan(*scan, k, kTruth, 2, 40, 5);
    mptrack::test::NoAllocScope guard;
    (void)phd_f->step(*scan);
    (void)cphd_f->step(*scan);
    allocs += guard.allocations();
  }
  CHECK(allocs == 0);
}

TEST_CASE("bad params, out-of-order scans and invalid measurements are statuses") {
  auto f = std::make_unique<GmPhdFilter<double>>();
  auto scan = std::make_unique<ScanD>();
  CHECK(f->step(*scan) == Status::kNotInitialized);
  RfsFilterParams<double> p = phdtest::seed001_params();
  p.survival_prob = 1.5;
  CHECK(f->init(p) == Status::kInvalidArgument);
  p = phdtest::seed001_params();
  REQUIRE(f->init(p) == Status::kOk);
  phdtest::make_scan(*scan, 3, kTruth, 2, 5, 1);
  Measurement<double> bad;
  bad.range_m = std::nan("");
  bad.amplitude = 3.0;
  (void)scan->measurements.push_back(bad);
  bad.range_m = 100.0;
  bad.amplitude = 0.5;  // below the threshold
  (void)scan->measurements.push_back(bad);
  CHECK(f->step(*scan) == Status::kPartial);
  CHECK(f->counters().measurements_invalid == 2);
  CHECK(f->step(*scan) == Status::kOutOfOrder);  // same time
  CHECK(f->counters().scans_rejected == 1);  // init() reset the earlier one
  CHECK(f->counters().scans == 1);
}

namespace {
struct TwoComponentCaps : DefaultCaps {
  static constexpr std::size_t kMaxMixtureComponents = 2;
};
}  // namespace

TEST_CASE("GM-PHD truncation to kMaxMixtureComponents is counted, not a capacity error") {
  // 40 clutter points per scan give far more than 2 components after
  // merging from scan 1 on: each step truncates, counts it in
  // mixture_truncated and still returns kOk (docs/algorithms/gm-phd.md
  // §Mixture reduction, step 3).
  auto f = std::make_unique<GmPhdFilter<double, TwoComponentCaps>>();
  RfsFilterParams<double> p = phdtest::seed001_params();
  p.clutter_mode = ClutterMode::kEstimatedUniform;
  REQUIRE(f->init(p) == Status::kOk);
  auto scan = std::make_unique<ScanD>();
  std::uint64_t before = 0;
  for (int k = 0; k < 5; ++k) {
    phdtest::make_scan(*scan, k, kTruth, 2, 40, 11);
    CHECK(f->step(*scan) == Status::kOk);
    if (k >= 1) CHECK(f->counters().mixture_truncated > before);
    before = f->counters().mixture_truncated;
    REQUIRE(f->components().size() <= 2);
    if (f->components().size() == 2) CHECK(f->components()[0].weight >= f->components()[1].weight);
  }
  CHECK(f->counters().track_cap_hits == 0);
}

TEST_CASE("GM-PHD truncation that leaves out a target-weight component is a capacity error") {
  // Three well-separated targets, no clutter, J_max 2: once each target's
  // component weighs about 1, the truncation must leave one of them out
  // (weight >= extract_threshold 0.5): counted in mixture_truncated AND in
  // track_cap_hits, and the step returns kCapacityExceeded.
  const phdtest::Truth three[3] = {{-500.0, 10.0, 0.0, 5.0}, {300.0, -5.0, -400.0, 10.0}, {0.0, 0.0, 600.0, 0.0}};
  auto f = std::make_unique<GmPhdFilter<double, TwoComponentCaps>>();
  RfsFilterParams<double> p = phdtest::seed001_params();
  p.clutter_mode = ClutterMode::kKnownUniform;
  REQUIRE(f->init(p) == Status::kOk);
  auto scan = std::make_unique<ScanD>();
  int capacity_steps = 0;
  for (int k = 0; k < 10; ++k) {
    phdtest::make_scan(*scan, k, three, 3, 0, 11);
    const std::uint64_t before = f->counters().track_cap_hits;
    const Status st = f->step(*scan);
    CHECK((st == Status::kCapacityExceeded) == (f->counters().track_cap_hits > before));
    if (st == Status::kCapacityExceeded) ++capacity_steps;
  }
  CHECK(capacity_steps > 0);
  CHECK(f->counters().mixture_truncated > 0);
}
