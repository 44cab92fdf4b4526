// Golden case of the CBMeMBer filter (double and float), 15 scans of the
// phd_test_scenario.h data.
#include "golden_cases.h"
#include "mptrack/cbmember/cbmember_filter.h"
#include "phd_scan.h"

namespace mptrack::test {

namespace {

Slot<CbMemberFilter<double>> g_filter_d;
Slot<CbMemberFilter<float>> g_filter_f;
Slot<Scan<double, DefaultCaps::kMaxMeasurements>> g_scan_src;  // drawn in double
Slot<Scan<double, DefaultCaps::kMaxMeasurements>> g_scan_d;    // the filter's input
Slot<Scan<float, DefaultCaps::kMaxMeasurements>> g_scan_f;

template <class T>
void record(GoldenSink& g, CbMemberFilter<T>& f, Scan<T, DefaultCaps::kMaxMeasurements>& scan, const char* tag,
            ClutterMode mode) {
  RfsFilterParams<T> p;
  p.amplitude.threshold = T(phdtest::kThreshold);
  p.clutter_mode = mode;
  g.require(f.init(p) == Status::kOk, "cbmember init");
  auto& scan_src = g_scan_src.make();
  for (int k = 0; k < 15; ++k) {
    phd_golden_scan<T>(k, scan_src, scan);
    (void)f.step(scan);
    const Label s = Label(tag) + ".k" + k;
    g.add(s + ".expected", f.expected_targets());
    for (const auto& t : f.outputs()[0].tracks) {
      const Label id = s + ".t" + t.id;
      g.add(id + ".px", t.state(0));
      g.add(id + ".py", t.state(2));
      g.add(id + ".r", t.existence);
      g.add(id + ".snr", t.snr);
    }
  }
}

}  // namespace

void golden_case_cbmember_filter(GoldenSink& g) {
  record<double>(g, g_filter_d.make(), g_scan_d.make(), "cbm.d.est", ClutterMode::kEstimatedUniform);
  record<float>(g, g_filter_f.make(), g_scan_f.make(), "cbm.f.map", ClutterMode::kEstimatedMap);
}

}  // namespace mptrack::test
