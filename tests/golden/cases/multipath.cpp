// Golden case of the multipath MF-BP tracker (float, SmallBoardCaps): 12
// scans of a small OTHR scene (tests/unit/othr_scenario.h), targets 1 and 2
// of seed 002 (parallel, 50 km apart) on four ionospheric paths, pd 0.75, 30
// clutter detections per scan. The scans use only + - * / sqrt and
// mptrack::dmath, so they are the same bits on every target; they are made
// one at a time (ScanMaker), without the heap, so the case also runs on the
// bare-metal images. Every reported track (tentative ones too) is recorded
// as raw bits, plus the counters.
#include "../../unit/othr_scenario.h"
#include "golden_cases.h"
#include "mptrack/multipath/multipath_tracker.h"

namespace mptrack::test {

namespace {

using Tracker = MultipathMfbpTracker<float, SmallBoardCaps>;

Slot<Tracker> g_tracker;
Slot<Tracker::ScanType> g_scan;
Slot<othr_scene::SceneConfig> g_scene;

void record(const Tracker& trk, std::size_t k, GoldenSink& g) {
  const auto& est = trk.outputs()[0];
  const Label s = Label("s") + k;
  g.add(s + ".n", static_cast<unsigned>(est.tracks.size()));
  for (const auto& r : est.tracks) {
    const Label p = s + ".t" + r.id;
    g.add(p + ".confirmed", r.confirmed ? 1 : 0);
    g.add(p + ".meas", static_cast<int>(r.measurement_index));
    g.add(p + ".existence", r.existence);
    for (int a = 0; a < 4; ++a) g.add(p + ".x" + a, r.state(a));
    for (int a = 0; a < 4; ++a) {
      for (int b = a; b < 4; ++b) g.add(p + ".P" + a + b, r.covariance(a, b));
    }
  }
}

}  // namespace

void golden_case_multipath_tracker(GoldenSink& g) {
  othr_scene::Target targets[4];
  othr_scene::seed002_target_table(targets);
  othr_scene::SceneConfig& scene = g_scene.make();
  scene.pd = 0.75;
  scene.clutter_mean = 30.0;
  othr_scene::ScanMaker maker(targets, 2, scene);  // targets 1 and 2
  Tracker::Params params;
  params.clutter_mean_count = 30.0f;
  params.report_tentative = true;  // pin tentative tracks too
  Tracker& trk = g_tracker.make();
  g.require(trk.init(params) == Status::kOk, "multipath init");
  Tracker::ScanType& scan = g_scan.make();
  for (std::size_t k = 0; k < 12; ++k) {
    maker.next(static_cast<int>(k), scan);
    g.require(trk.step(scan) == Status::kOk, "multipath step");
    record(trk, k, g);
  }
  const auto& c = trk.counters();
  g.add("tracks_born", c.tracks_born);
  g.add("tracks_confirmed", c.tracks_confirmed);
  g.add("tracks_deleted", c.tracks_deleted);
  g.add("numerical_repairs", c.numerical_repairs);
  g.add("bp_not_converged", c.bp_not_converged);
}

}  // namespace mptrack::test
