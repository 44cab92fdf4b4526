// Golden case of the GNN + CV-EKF baseline (float, DefaultCaps) over 20
// scans of a small deterministic scenario: two targets (one crossing the
// other's path), light clutter, noise from an LCG + Irwin-Hall Gaussian.
// Inputs use only + - * / sqrt and mptrack::dmath, so they are the same bits
// on every target.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "golden_cases.h"
#include "mptrack/gnn/gnn_tracker.h"
#include "mptrack/math/detmath.h"

namespace mptrack::test {

namespace {

using Tracker = GnnTracker<float, DefaultCaps>;

Slot<Tracker> g_tracker;

struct Lcg {
  std::uint32_t state;
  float uniform() {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) * (1.0f / 16777216.0f);
  }
  float gaussian() {
    float s = 0.0f;
    for (int k = 0; k < 12; ++k) s += uniform();
    return s - 6.0f;
  }
};

Measurement<float> measure(float x, float y, Lcg& rng) {
  Measurement<float> m;
  m.range_m = std::sqrt(x * x + y * y) + 0.2f * rng.gaussian();
  m.azimuth_rad = dmath::datan2(y, x) + 0.01f * rng.gaussian();
  m.amplitude = 5.0f;
  return m;
}


}  // namespace

void golden_case_gnn_tracker(GoldenSink& g) {
  Tracker::Params params;
  params.report_tentative = true;  // pin tentative tracks too
  Tracker& trk = g_tracker.make();
  g.require(trk.init(params) == Status::kOk, "gnn init");
  Lcg rng{0x5eed0004u};
  for (std::uint32_t k = 0; k < 20; ++k) {
    const float t = 0.1f * static_cast<float>(k);
    Tracker::ScanType scan;
    scan.time_us = 100000u * static_cast<std::uint64_t>(k + 1);
    // Target 1 detected every scan but 7; target 2 missed on scans 4 and 12.
    if (k != 7) {
      g.require(scan.measurements.push_back(measure(10.0f + 4.95f * t, 10.0f + 4.95f * t, rng)) == Status::kOk,
                "gnn push target 1");
    }
    if (k != 4 && k != 12) {
      g.require(scan.measurements.push_back(measure(10.0f + 4.95f * t, 31.0f - 4.95f * t, rng)) == Status::kOk,
                "gnn push target 2");
    }
    if (k % 3 == 0) {  // one clutter point every third scan
      Measurement<float> c;
      c.range_m = 5.0f + 60.0f * rng.uniform();
      c.azimuth_rad = -1.0f + 2.5f * rng.uniform();
      g.require(scan.measurements.push_back(c) == Status::kOk, "gnn push clutter");
    }
    g.require(trk.step(scan) == Status::kOk, "gnn step");
    g.require(trk.outputs().size() == 1, "gnn one estimate per scan");
    if (trk.outputs().size() != 1) return;
    const auto& est = trk.outputs()[0];
    const Label s = Label("s") + k;
    g.add(s + ".n", static_cast<unsigned>(est.tracks.size()));
    for (std::size_t i = 0; i < est.tracks.size(); ++i) {
      const auto& r = est.tracks[i];
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
  const auto& c = trk.counters();
  g.add("scans", c.scans);
  g.add("tracks_born", c.tracks_born);
  g.add("tracks_confirmed", c.tracks_confirmed);
  g.add("tracks_deleted", c.tracks_deleted);
  g.add("numerical_repairs", c.numerical_repairs);
  g.require(c.tracks_confirmed == 2, "gnn: both targets confirmed, no clutter track");
}

}  // namespace mptrack::test
