// Golden case of GM-PHD and GM-CPHD (double and float) over 15 scans of the
// phd_test_scenario.h data: extracted states, weights, SNRs, the clutter
// rate and cardinality.
#include "golden_cases.h"
#include "mptrack/phd/phd_filter.h"
#include "phd_scan.h"

namespace mptrack::test {

namespace {

Slot<GmPhdFilter<double>> g_phd_d;
Slot<GmCphdFilter<double>> g_cphd_d;
Slot<GmPhdFilter<float>> g_phd_f;
Slot<GmCphdFilter<float>> g_cphd_f;
Slot<Scan<double, DefaultCaps::kMaxMeasurements>> g_scan_src;  // drawn in double
Slot<Scan<double, DefaultCaps::kMaxMeasurements>> g_scan_d;    // the filter's input
Slot<Scan<float, DefaultCaps::kMaxMeasurements>> g_scan_f;

template <class T, class Filter>
void record(GoldenSink& g, Filter& f, Scan<T, DefaultCaps::kMaxMeasurements>& scan, const char* tag,
            ClutterMode mode) {
  RfsFilterParams<T> p;
  p.amplitude.threshold = T(phdtest::kThreshold);
  p.clutter_mode = mode;
  g.require(f.init(p) == Status::kOk, "phd init");
  auto& scan_src = g_scan_src.make();
  for (int k = 0; k < 15; ++k) {
    phd_golden_scan<T>(k, scan_src, scan);
    (void)f.step(scan);
    const Label s = Label(tag) + ".k" + k;
    g.add(s + ".expected", f.expected_targets());
    g.add(s + ".clutter_rate", f.clutter().total_rate());
    for (const auto& t : f.outputs()[0].tracks) {
      const Label id = s + ".t" + t.id;
      g.add(id + ".px", t.state(0));
      g.add(id + ".vy", t.state(3));
      g.add(id + ".w", t.existence);
      g.add(id + ".snr", t.snr);
    }
  }
}

}  // namespace

void golden_case_phd_filters(GoldenSink& g) {
  record<double>(g, g_phd_d.make(), g_scan_d.make(), "phd.d.est", ClutterMode::kEstimatedUniform);
  record<double>(g, g_cphd_d.make(), g_scan_d.make(), "cphd.d.map", ClutterMode::kEstimatedMap);
  record<float>(g, g_phd_f.make(), g_scan_f.make(), "phd.f.known", ClutterMode::kKnownUniform);
  record<float>(g, g_cphd_f.make(), g_scan_f.make(), "cphd.f.est", ClutterMode::kEstimatedUniform);
}

}  // namespace mptrack::test
