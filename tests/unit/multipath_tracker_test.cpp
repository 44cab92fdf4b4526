// Behaviour of the multipath MF-BP tracker (seed 002) on small deterministic
// OTHR scenes (othr_scenario.h): tracks found and held, positions near the
// truth, clutter-only scans confirm nothing, no allocation in step(), and
// the params checks.
#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <memory>
#include <string>

#include "alloc_guard.h"
#include "mptrack/multipath/multipath_tracker.h"
#include "othr_scenario.h"

using mptrack::Status;
using Tracker = mptrack::MultipathMfbpTracker<float, mptrack::DefaultCaps>;
using ScanF = Tracker::ScanType;

namespace {

/// Ground distance [km] between a reported Cartesian position and truth.
double ground_error_km(const mptrack::TrackReport<float>& r, const mptrack::model::OthrState<double>& x) {
  const double tx = x(0) * std::cos(x(2)) * 1e3;
  const double ty = x(0) * std::sin(x(2)) * 1e3;
  const double dx = static_cast<double>(r.state(0)) - tx;
  const double dy = static_cast<double>(r.state(2)) - ty;
  return std::sqrt(dx * dx + dy * dy) * 1e-3;
}

/// Counted tracks within max_km of truth target x, per report.
int tracks_near(const Tracker::Estimate& e, const mptrack::model::OthrState<double>& x, double max_km) {
  int n = 0;
  for (const auto& r : e.tracks) n += ground_error_km(r, x) < max_km ? 1 : 0;
  return n;
}

othr_scene::Scene one_target_scene(double pd, double clutter) {
  othr_scene::Scene s;
  s.targets = othr_scene::seed002_targets();
  s.targets.resize(1);
  s.pd = pd;
  s.clutter_mean = clutter;
  return s;
}

/// Runs the scene; per scan, how many live truths have a counted track
/// within 10 km and how many counted tracks are near no truth.
struct RunTally {
  int truth_scans = 0;
  int covered = 0;
  int false_reports = 0;
};

RunTally run_scene(const othr_scene::Scene& scene, int num_scans, Tracker::Params p) {
  p.pd.fill(static_cast<float>(scene.pd));
  p.clutter_mean_count = static_cast<float>(scene.clutter_mean > 1.0 ? scene.clutter_mean : 1.0);
  const auto scans = othr_scene::make_scans<Tracker::kMaxMeasurements>(scene, num_scans);
  auto trk = std::make_unique<Tracker>();
  REQUIRE(trk->init(p) == Status::kOk);
  RunTally tally;
  for (int k = 0; k < num_scans; ++k) {
    REQUIRE(trk->step(scans[static_cast<std::size_t>(k)]) == Status::kOk);
    const auto& e = trk->outputs()[0];
    for (const auto& t : scene.targets) {
      if (k < t.first_scan || k > t.last_scan) continue;
      ++tally.truth_scans;
      tally.covered += tracks_near(e, t.at(k, scene.dt_s), 10.0) > 0 ? 1 : 0;
    }
    for (const auto& r : e.tracks) {
      bool near = false;
      for (const auto& t : scene.targets) {
        if (k >= t.first_scan && k <= t.last_scan && ground_error_km(r, t.at(k, scene.dt_s)) < 10.0) near = true;
      }
      tally.false_reports += near ? 0 : 1;
    }
  }
  return tally;
}

}  // namespace

TEST_CASE("multipath: one target on four paths, pd 0.75, Nc 20: one counted track on it from scan 6") {
  const auto scene = one_target_scene(0.75, 20.0);
  const auto scans = othr_scene::make_scans<Tracker::kMaxMeasurements>(scene, 20);
  auto trk = std::make_unique<Tracker>();
  REQUIRE(trk->init(Tracker::Params{}) == Status::kOk);
  for (int k = 0; k < 20; ++k) {
    REQUIRE(trk->step(scans[static_cast<std::size_t>(k)]) == Status::kOk);
    if (k < 6) continue;
    const auto& e = trk->outputs()[0];
    CAPTURE(k);
    REQUIRE(e.tracks.size() == 1);
    CHECK(ground_error_km(e.tracks[0], scene.targets[0].at(k, scene.dt_s)) < 10.0);
    CHECK(e.tracks[0].confirmed);
    CHECK(e.tracks[0].existence >= 0.85f);
  }
}

TEST_CASE("multipath: the seed 002 scene at pd 0.75, Nc 125 (4 targets, 30 scans, 8 seeds): mean TPD >= 0.82") {
  // Eight noise seeds: one seed decides little (two detections of the two
  // parallel targets 50 km apart can fall in one group and start a ghost).
  int truth_scans = 0, covered = 0, false_reports = 0;
  for (std::uint32_t seed = 0; seed < 8; ++seed) {
    othr_scene::Scene scene;
    scene.targets = othr_scene::seed002_targets();
    scene.pd = 0.75;
    scene.clutter_mean = 125.0;
    scene.seed = 0x5eed0002u + seed;
    const RunTally t = run_scene(scene, 30, Tracker::Params{});
    REQUIRE(t.truth_scans == 82);  // 2 x 20 + 2 x 21 target-scans
    truth_scans += t.truth_scans;
    covered += t.covered;
    false_reports += t.false_reports;
  }
  MESSAGE("TPD " << static_cast<double>(covered) / truth_scans << ", false reports per run " << false_reports / 8.0);
  CHECK(static_cast<double>(covered) / truth_scans >= 0.82);  // measured 0.87
  CHECK(false_reports <= 8 * 10);                             // measured about 7 per run
}

TEST_CASE("multipath: clutter alone (Nc 400, 30 scans) yields no counted track") {
  othr_scene::Scene scene;
  scene.clutter_mean = 400.0;
  const RunTally t = run_scene(scene, 30, Tracker::Params{});
  CHECK(t.false_reports == 0);
}

TEST_CASE("multipath: a group of one detection starts no track when min_group_size is 2") {
  // One target on one path only: every scan has a single target detection.
  auto scene = one_target_scene(0.999, 0.0);
  scene.geometry.num_paths = 1;
  const RunTally t = run_scene(scene, 8, Tracker::Params{});
  CHECK(t.covered == 0);
  CHECK(t.false_reports == 0);
}

TEST_CASE("multipath: step() allocates nothing") {
  othr_scene::Scene scene;
  scene.targets = othr_scene::seed002_targets();
  scene.clutter_mean = 125.0;
  const auto scans = othr_scene::make_scans<Tracker::kMaxMeasurements>(scene, 15);
  auto trk = std::make_unique<Tracker>();
  REQUIRE(trk->init(Tracker::Params{}) == Status::kOk);
  std::size_t allocations = 0;
  for (const auto& s : scans) {
    mptrack::test::NoAllocScope guard;
    const Status st = trk->step(s);
    allocations += guard.allocations();
    CHECK(st == Status::kOk);
  }
  CHECK(allocations == 0);
  CHECK(trk->counters().tracks_born > 0);
}

TEST_CASE("multipath: validate() names num_paths above Caps::kMaxPaths and a pd outside (0, 1)") {
  Tracker::Params p;
  mptrack::ParamError where;
  p.num_paths = 5;  // DefaultCaps: kMaxPaths = 4
  CHECK(Tracker::validate(p, &where) == Status::kInvalidArgument);
  CHECK(std::string(where.field) == "num_paths");
  p = Tracker::Params{};
  p.pd[2] = 1.0f;
  CHECK(Tracker::validate(p, &where) == Status::kInvalidArgument);
  CHECK(std::string(where.field) == "pd");
  p = Tracker::Params{};
  p.min_group_size = 5;
  CHECK(Tracker::validate(p, &where) == Status::kInvalidArgument);
  CHECK(std::string(where.field) == "min_group_size");
}

TEST_CASE("multipath: the gate-pair cap drops the farthest pairs, counts them and returns kCapacityExceeded") {
  // A confirmed track, then a scan with 40 detections on its EE path
  // prediction (DefaultCaps::kMaxGatePairs = 32 per pseudo-target).
  const auto scene = one_target_scene(0.999, 0.0);
  auto scans = othr_scene::make_scans<Tracker::kMaxMeasurements>(scene, 9);
  auto trk = std::make_unique<Tracker>();
  REQUIRE(trk->init(Tracker::Params{}) == Status::kOk);
  for (int k = 0; k < 8; ++k) {
    REQUIRE(trk->step(scans[static_cast<std::size_t>(k)]) == Status::kOk);
  }
  REQUIRE(trk->outputs()[0].tracks.size() == 1);
  auto& last = scans[8];
  last.measurements.clear();
  const auto y = mptrack::model::othr_measure(scene.targets[0].at(8, scene.dt_s), scene.geometry.paths[0],
                                              scene.geometry.baseline_km);
  for (int n = 0; n < 40; ++n) {
    mptrack::Measurement<float> m;
    m.range_m = static_cast<float>(y(0) * 1e3 + 50.0 * n);
    m.doppler_mps = static_cast<float>(y(1) * 1e3);
    m.azimuth_rad = static_cast<float>(y(2));
    REQUIRE(last.measurements.push_back(m) == Status::kOk);
  }
  CHECK(trk->step(last) == Status::kCapacityExceeded);
  CHECK(trk->counters().association_cap_hits >= 4);
}
