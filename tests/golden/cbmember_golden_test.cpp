// Bit-exact record of the CBMeMBer filter (double and float), 15 scans of
// the phd_test_scenario.h data.
#include <doctest/doctest.h>

#include <memory>
#include <string>

#include "golden.h"
#include "mptrack/cbmember/cbmember_filter.h"
#include "../unit/phd_test_scenario.h"

using namespace mptrack;

namespace {

const phdtest::Truth kTruth[2] = {{-500.0, 10.0, 0.0, 5.0}, {300.0, -5.0, -400.0, 10.0}};

template <class T>
void record(test::GoldenFile& g, const std::string& tag, ClutterMode mode) {
  auto f = std::make_unique<CbMemberFilter<T>>();
  RfsFilterParams<T> p;
  p.amplitude.threshold = T(phdtest::kThreshold);
  p.clutter_mode = mode;
  REQUIRE(f->init(p) == Status::kOk);
  auto scan_d = std::make_unique<Scan<double, DefaultCaps::kMaxMeasurements>>();
  auto scan = std::make_unique<Scan<T, DefaultCaps::kMaxMeasurements>>();
  for (int k = 0; k < 15; ++k) {
    phdtest::make_scan(*scan_d, k, kTruth, 2, 40, 21);
    scan->time_us = scan_d->time_us;
    scan->measurements.clear();
    for (const auto& m : scan_d->measurements) {
      Measurement<T> y;
      y.range_m = T(m.range_m);
      y.azimuth_rad = T(m.azimuth_rad);
      y.amplitude = T(m.amplitude);
      (void)scan->measurements.push_back(y);
    }
    (void)f->step(*scan);
    const std::string s = tag + ".k" + std::to_string(k);
    g.add(s + ".expected", f->expected_targets());
    for (const auto& t : f->outputs()[0].tracks) {
      const std::string id = s + ".t" + std::to_string(t.id);
      g.add(id + ".px", t.state(0));
      g.add(id + ".py", t.state(2));
      g.add(id + ".r", t.existence);
      g.add(id + ".snr", t.snr);
    }
  }
}

}  // namespace

TEST_CASE("CBMeMBer golden record") {
  test::GoldenFile g("cbmember_filter");
  record<double>(g, "cbm.d.est", ClutterMode::kEstimatedUniform);
  record<float>(g, "cbm.f.map", ClutterMode::kEstimatedMap);
  CHECK(g.size() > 50);
  CHECK(g.matches());
}
