// Shared by the PHD and CBMeMBer golden cases: scan k of the
// phd_test_scenario.h data (two targets, 40 clutter points), drawn in double
// and rounded to the filter's scalar T.
#pragma once

#include "../../unit/phd_test_scenario.h"
#include "golden_sink.h"
#include "mptrack/caps.h"
#include "mptrack/measurement.h"

namespace mptrack::test {

inline const phdtest::Truth kPhdGoldenTruth[2] = {{-500.0, 10.0, 0.0, 5.0}, {300.0, -5.0, -400.0, 10.0}};

template <class T>
void phd_golden_scan(int k, Scan<double, DefaultCaps::kMaxMeasurements>& scan_d,
                     Scan<T, DefaultCaps::kMaxMeasurements>& scan) {
  phdtest::make_scan(scan_d, k, kPhdGoldenTruth, 2, 40, 21);
  scan.time_us = scan_d.time_us;
  scan.measurements.clear();
  for (const auto& m : scan_d.measurements) {
    Measurement<T> y;
    y.range_m = T(m.range_m);
    y.azimuth_rad = T(m.azimuth_rad);
    y.amplitude = T(m.amplitude);
    (void)scan.measurements.push_back(y);
  }
}

}  // namespace mptrack::test
