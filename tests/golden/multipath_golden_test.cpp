// Golden record of the multipath MF-BP tracker (float, SmallBoardCaps) over
// 12 scans of a small OTHR scene (tests/unit/othr_scenario.h): targets 1 and
// 2 of seed 002 (parallel, 50 km apart) on four ionospheric paths, pd 0.75,
// 30 clutter detections per scan. The scans use only + - * / sqrt and
// mptrack::dmath, so they are the same bits on every target, and the file
// pins the tracker's output bit for bit on the Linux targets (x86-64, aarch64,
// armhf, ppc). Not a shared golden case yet: the scene generator allocates
// (std::vector), so it does not run on the bare-metal images.
// Regenerate (after an intended change): MPTRACK_GOLDEN_REGENERATE=1 ./multipath_golden_test
#include <doctest/doctest.h>

#include <cstddef>
#include <cstdint>
#include <memory>

#include "golden.h"
#include "mptrack/multipath/multipath_tracker.h"
#include "../unit/othr_scenario.h"

using mptrack::Status;
using Tracker = mptrack::MultipathMfbpTracker<float, mptrack::SmallBoardCaps>;

TEST_CASE("multipath golden: 12 OTHR scans of two targets on four paths, float, bit-exact") {
  othr_scene::Scene scene;
  scene.targets = othr_scene::seed002_targets();
  scene.targets.resize(2);
  scene.pd = 0.75;
  scene.clutter_mean = 30.0;
  const auto scans = othr_scene::make_scans<Tracker::kMaxMeasurements>(scene, 12);
  Tracker::Params params;
  params.clutter_mean_count = 30.0f;
  params.report_tentative = true;  // pin tentative tracks too
  auto trk = std::make_unique<Tracker>();
  REQUIRE(trk->init(params) == Status::kOk);
  mptrack::test::GoldenFile g("multipath_tracker");
  for (std::size_t k = 0; k < scans.size(); ++k) {
    REQUIRE(trk->step(scans[k]) == Status::kOk);
    const auto& est = trk->outputs()[0];
    const mptrack::test::Label s = mptrack::test::Label("s") + k;
    g.add(s + ".n", static_cast<unsigned>(est.tracks.size()));
    for (const auto& r : est.tracks) {
      const mptrack::test::Label p = s + ".t" + r.id;
      g.add(p + ".confirmed", r.confirmed ? 1 : 0);
      g.add(p + ".meas", static_cast<int>(r.measurement_index));
      g.add(p + ".existence", r.existence);
      for (int a = 0; a < 4; ++a) g.add(p + ".x" + a, r.state(a));
      for (int a = 0; a < 4; ++a) {
        for (int b = a; b < 4; ++b) g.add(p + ".P" + a + b, r.covariance(a, b));
      }
    }
  }
  const auto& c = trk->counters();
  g.add("tracks_born", c.tracks_born);
  g.add("tracks_confirmed", c.tracks_confirmed);
  g.add("tracks_deleted", c.tracks_deleted);
  g.add("numerical_repairs", c.numerical_repairs);
  g.add("bp_not_converged", c.bp_not_converged);
  CHECK(c.tracks_confirmed >= 2);
  CHECK(g.matches());
}
