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

}  // namespace

TEST_CASE("multipath: one target on four paths, pd 0.75, Nc 20: one counted track on it") {
  const auto scene = one_target_scene(0.75, 20.0);
  const auto scans = othr_scene::make_scans<Tracker::kMaxMeasurements>(scene, 20);
  auto trk = std::make_unique<Tracker>();
  REQUIRE(trk->init(Tracker::Params{}) == Status::kOk);
  int held = 0;
  for (int k = 0; k < 20; ++k) {
    REQUIRE(trk->step(scans[static_cast<std::size_t>(k)]) == Status::kOk);
    const auto& e = trk->outputs()[0];
    const auto x = scene.targets[0].at(k, scene.dt_s);
    MESSAGE("k " << k << " n " << e.tracks.size() << " near " << tracks_near(e, x, 10.0) << " live " << trk->tracks().size());
    if (k >= 5) {
      CHECK(e.tracks.size() == 1);
      held += tracks_near(e, x, 10.0);
    }
  }
  CHECK(held == 15);
}
