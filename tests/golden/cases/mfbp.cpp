// Golden case of the MF-BP tracker (float): 30 scans of the small
// two-target scenario (tests/unit/mfbp_scenario.h), online filter and
// window-7 smoother. Every finalised confirmed track's id, state, existence
// and SNR are recorded as raw bits, plus the counters.
#include "../../unit/mfbp_scenario.h"
#include "golden_cases.h"
#include "mptrack/mfbp/mfbp_tracker.h"

namespace mptrack::test {

namespace {

using Tracker = MfbpTracker<float, mfbp_test::TestCaps>;
using TestScan = Scan<float, mfbp_test::TestCaps::kMaxMeasurements>;

Slot<Tracker> g_tracker;
Slot<TestScan> g_scan;

void record(const Tracker& trk, GoldenSink& g, const char* tag) {
  for (const auto& est : trk.outputs()) {
    const Label k = Label(tag) + ".k" + est.scan_index;
    g.add(k + ".n", static_cast<int>(est.tracks.size()));
    for (const auto& t : est.tracks) {
      const Label p = k + ".id" + t.id;
      for (int i = 0; i < 4; ++i) g.add(p + ".x" + i, t.state(i));
      g.add(p + ".Pxx", t.covariance(0, 0));
      g.add(p + ".Pyy", t.covariance(2, 2));
      g.add(p + ".e", t.existence);
      g.add(p + ".snr", t.snr);
      g.add(p + ".j", static_cast<int>(t.measurement_index));
    }
    for (const auto& c : est.clutter) {
      const Label p = k + ".c" + c.id;
      g.add(p + ".n", c.expected_count);
      g.add(p + ".cnr", c.cnr);
    }
  }
}

void run_case(std::size_t window, std::size_t slide, const char* tag, GoldenSink& g) {
  Tracker& trk = g_tracker.make();
  MfbpParams<float> p = seed000_default_params<float>();
  p.window_length = window;
  p.slide = slide;
  p.uniform_rate_per_scan = 10.0f;
  g.require(trk.init(p) == Status::kOk, "mfbp init");
  mfbp_test::Lcg rng;
  TestScan& scan = g_scan.make();
  for (int k = 0; k < 30; ++k) {
    mfbp_test::make_scan(rng, k, 10, scan);
    g.require(trk.step(scan) == Status::kOk, "mfbp step");
    record(trk, g, tag);
  }
  g.require(trk.flush() == Status::kOk, "mfbp flush");
  record(trk, g, tag);
  const auto& c = trk.counters();
  const Label t(tag);
  g.add(t + ".born", c.tracks_born);
  g.add(t + ".confirmed", c.tracks_confirmed);
  g.add(t + ".deleted", c.tracks_deleted);
  g.add(t + ".repairs", c.numerical_repairs);
  g.add(t + ".bp_not_converged", c.bp_not_converged);
}

}  // namespace

void golden_case_mfbp_tracker(GoldenSink& g) {
  run_case(1, 1, "filter", g);
  run_case(7, 3, "smoother", g);
}

}  // namespace mptrack::test
