// MF-BP's provisional (lag-0) output (MfbpTracker::provisional(),
// docs/algorithms/mfbp.md §Provisional output) on the small deterministic
// scenario of mfbp_scenario.h: when it exists, which scan it is, how it is
// predicted between windows, that its tracks are on the targets, and that
// it allocates nothing.
#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <memory>

#include "alloc_guard.h"
#include "mfbp_scenario.h"
#include "mptrack/mfbp/mfbp_tracker.h"

using namespace mptrack;

using mfbp_test::TestCaps;

namespace {

constexpr std::size_t kClutter = 10;
using Tracker = MfbpTracker<float, TestCaps>;
using ScanT = Scan<float, TestCaps::kMaxMeasurements>;

std::unique_ptr<Tracker> make_tracker(std::size_t window, std::size_t slide) {
  auto trk = std::make_unique<Tracker>();
  MfbpParams<float> p = seed000_default_params<float>();
  p.window_length = window;
  p.slide = slide;
  p.uniform_rate_per_scan = float(kClutter);
  REQUIRE(trk->init(p) == Status::kOk);
  return trk;
}

// Scan k of the scene into scan, stepped into trk (accepted).
void step_scene(Tracker& trk, mfbp_test::Lcg& rng, int k, ScanT& scan) {
  mfbp_test::make_scan(rng, k, kClutter, scan);
  REQUIRE(trk.step(scan) != Status::kOutOfOrder);
}

// 3 sigma of the measurement noise in Cartesian at ~23 km (cross-range dominates).
constexpr double kThreeSigma = 3.0 * 250.0;

double distance_to_truth(const TrackReport<float>& r, int k, std::size_t i) {
  double p[2];
  mfbp_test::truth_at(k, i, p);
  return std::hypot(static_cast<double>(r.state(0)) - p[0], static_cast<double>(r.state(2)) - p[1]);
}

}  // namespace

TEST_CASE("mfbp provisional: a window every scan gives the newest scan's estimate from the first full window on") {
  auto trk = make_tracker(7, 1);
  mfbp_test::Lcg rng;
  auto scan = std::make_unique<ScanT>();
  for (int k = 0; k < 20; ++k) {
    step_scene(*trk, rng, k, *scan);
    // Scans 0..5 fill the window; from scan 6 on every step runs a window.
    CHECK(trk->has_provisional() == (k >= 6));
    if (trk->has_provisional()) {
      CHECK(trk->provisional().scan_index == static_cast<std::uint32_t>(k));
      CHECK(trk->provisional().time_us == scan->time_us);
    }
  }
}

TEST_CASE("mfbp provisional: with slide 3 it is computed on window steps and predicted on the others") {
  auto trk = make_tracker(7, 3);
  mfbp_test::Lcg rng;
  auto scan = std::make_unique<ScanT>();
  Tracker::Estimate previous;
  std::size_t predicted_tracks = 0;
  for (int k = 0; k < 20; ++k) {
    step_scene(*trk, rng, k, *scan);
    // The first window runs at scan 6, then every third scan (9, 12, ...).
    const bool window_ran = k >= 6 && (k - 6) % 3 == 0;
    REQUIRE(trk->has_provisional() == (k >= 6));
    if (k < 6) continue;
    const Tracker::Estimate& e = trk->provisional();
    CHECK(e.scan_index == static_cast<std::uint32_t>(k));
    CHECK(e.time_us == scan->time_us);
    if (!window_ran) {
      // Predicted from the previous step's estimate: same tracks, position
      // advanced by velocity x 1.25 s, velocity kept, no measurement.
      REQUIRE(e.tracks.size() == previous.tracks.size());
      for (std::size_t i = 0; i < e.tracks.size(); ++i) {
        const auto& a = previous.tracks[i];
        const auto& b = e.tracks[i];
        CHECK(b.id == a.id);
        CHECK(static_cast<double>(b.state(0)) == doctest::Approx(static_cast<double>(a.state(0) + 1.25f * a.state(1))));
        CHECK(static_cast<double>(b.state(2)) == doctest::Approx(static_cast<double>(a.state(2) + 1.25f * a.state(3))));
        CHECK(b.state(1) == a.state(1));
        CHECK(b.covariance(0, 0) > a.covariance(0, 0));
        CHECK(b.measurement_index == -1);
        ++predicted_tracks;
      }
    }
    previous = e;
  }
  CHECK(predicted_tracks > 0u);
}

TEST_CASE("mfbp provisional: the online filter has none, its outputs have no lag") {
  auto trk = make_tracker(1, 1);
  mfbp_test::Lcg rng;
  auto scan = std::make_unique<ScanT>();
  for (int k = 0; k < 10; ++k) {
    step_scene(*trk, rng, k, *scan);
    CHECK_FALSE(trk->has_provisional());
    REQUIRE(trk->outputs().size() == 1u);
    CHECK(trk->outputs()[0].scan_index == static_cast<std::uint32_t>(k));
  }
}

TEST_CASE("mfbp provisional: flush() and a refused scan leave none, and none is predicted after flush()") {
  auto trk = make_tracker(7, 1);
  mfbp_test::Lcg rng;
  auto scan = std::make_unique<ScanT>();
  for (int k = 0; k < 8; ++k) {
    step_scene(*trk, rng, k, *scan);
  }
  REQUIRE(trk->has_provisional());
  CHECK(trk->step(*scan) == Status::kOutOfOrder);  // the same time stamp again
  CHECK_FALSE(trk->has_provisional());
  step_scene(*trk, rng, 8, *scan);
  REQUIRE(trk->has_provisional());
  CHECK(trk->flush() == Status::kOk);
  CHECK_FALSE(trk->has_provisional());
  step_scene(*trk, rng, 9, *scan);  // a new window starts: nothing to predict
  CHECK_FALSE(trk->has_provisional());
}

TEST_CASE("mfbp provisional: its confirmed tracks are on the targets at lag 0, one per target") {
  auto trk = make_tracker(7, 1);
  mfbp_test::Lcg rng;
  auto scan = std::make_unique<ScanT>();
  int covered[2] = {0, 0}, false_reports = 0, provisional_scans = 0;
  for (int k = 0; k < 40; ++k) {
    step_scene(*trk, rng, k, *scan);
    if (k < 12 || !trk->has_provisional()) continue;
    ++provisional_scans;
    int near[2] = {0, 0};
    for (const auto& r : trk->provisional().tracks) {
      CHECK(r.confirmed);
      if (distance_to_truth(r, k, 0) < kThreeSigma) {
        ++near[0];
      } else if (distance_to_truth(r, k, 1) < kThreeSigma) {
        ++near[1];
      } else {
        ++false_reports;
      }
    }
    for (int i = 0; i < 2; ++i) {
      CHECK(near[i] <= 1);
      covered[i] += near[i] == 1 ? 1 : 0;
    }
  }
  CHECK(provisional_scans == 28);
  CHECK(false_reports == 0);
  CHECK(covered[0] >= provisional_scans * 9 / 10);
  CHECK(covered[1] >= provisional_scans * 9 / 10);
}

TEST_CASE("mfbp provisional: a step that reports one allocates nothing") {
  auto trk = make_tracker(7, 1);
  mfbp_test::Lcg rng;
  auto scan = std::make_unique<ScanT>();
  std::size_t allocs = 0, reported = 0;
  for (int k = 0; k < 15; ++k) {
    mfbp_test::make_scan(rng, k, kClutter, *scan);
    test::NoAllocScope guard;
    const Status s = trk->step(*scan);
    if (trk->has_provisional()) reported += trk->provisional().tracks.size();
    allocs += guard.allocations();
    CHECK(s != Status::kOutOfOrder);
  }
  CHECK(reported > 0u);
  CHECK(allocs == 0u);
}
