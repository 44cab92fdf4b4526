// Golden case of the VMP tracker on raw frames (float, VmpSmallCaps) over 16
// frames of two drones converging to within one resolution cell, with
// per-frame amplitude fluctuation and thermal noise from the deterministic
// generator of tests/unit/vmp_test_frames.h (only + - * /, sqrt and
// mptrack::dmath: the same input bits on every target).
#include <cstddef>
#include <cstdint>

#include "../../unit/vmp_test_frames.h"
#include "golden_cases.h"
#include "mptrack/math/detmath.h"
#include "mptrack/vmp/vmp_tracker.h"

namespace mptrack::test {

namespace {

using Tracker = VmpTracker<float, VmpSmallCaps>;

Slot<Tracker> g_tracker;
Slot<vmp_test::Cube> g_cube;

}  // namespace

void golden_case_vmp_tracker(GoldenSink& g) {
  const VmpParams params;
  Tracker& trk = g_tracker.make();
  g.require(trk.init(params) == Status::kOk, "vmp init");
  vmp_test::Cube& cube = g_cube.make();
  vmp_test::Lcg rng{0x5eed0012u};
  for (std::uint32_t k = 0; k < 16; ++k) {
    const double t = 0.1 * static_cast<double>(k);
    vmp_test::clear(cube, 100000u * static_cast<std::uint64_t>(k + 1));
    // Drone 1 radial at 45 deg; drone 2 converging on it (1.2 m apart at k = 15).
    const double pos[2][2] = {{12.0 + 4.95 * t, 12.0 + 4.95 * t}, {12.0 + 4.95 * t, 24.0 - 2.7 * t}};
    for (const auto& p : pos) {
      const double amp = 0.7 + 0.6 * rng.uniform();
      double s = 0.0, c = 1.0;
      dmath::dsincos(dmath::kTwoPi<double> * rng.uniform(), s, c);
      vmp_test::add_echo(params, p[0], p[1], amp * c, amp * s, cube);
    }
    vmp_test::add_noise(params, rng, cube);
    g.require(trk.step(cube) == Status::kOk, "vmp step");
    g.require(trk.outputs().size() == 1, "vmp one estimate per frame");
    if (trk.outputs().size() != 1) return;
    const auto& est = trk.outputs()[0];
    const Label sk = Label("s") + k;
    g.add(sk + ".n", static_cast<unsigned>(est.tracks.size()));
    for (std::size_t i = 0; i < est.tracks.size(); ++i) {
      const auto& r = est.tracks[i];
      const Label p = sk + ".t" + r.id;
      g.add(p + ".existence", r.existence);
      g.add(p + ".snr", r.snr);
      for (int a = 0; a < 4; ++a) g.add(p + ".x" + a, r.state(a));
      for (int a = 0; a < 4; ++a) {
        for (int b = a; b < 4; ++b) g.add(p + ".P" + a + b, r.covariance(a, b));
      }
    }
  }
  const auto& c = trk.counters();
  g.add("scans", c.scans);
  g.add("tracks_born", c.tracks_born);
  g.add("tracks_deleted", c.tracks_deleted);
  g.add("numerical_repairs", c.numerical_repairs);
  g.require(c.tracks_born == 2, "vmp: both drones born, nothing else");
}

}  // namespace mptrack::test
