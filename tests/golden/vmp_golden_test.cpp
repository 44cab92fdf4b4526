// Golden record of the VMP tracker on raw frames (float, VmpSmallCaps) over 16
// frames of two drones converging to within one resolution cell, with
// per-frame amplitude fluctuation and thermal noise from the deterministic
// generator of tests/unit/vmp_test_frames.h (only + - * /, sqrt and
// mptrack::dmath: the same input bits on every target). The committed file pins
// the tracker's output bit for bit on x86-64, aarch64 and armhf.
// Regenerate (after an intended change): MPTRACK_GOLDEN_REGENERATE=1 ./vmp_golden_test
#include <doctest/doctest.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "golden.h"
#include "mptrack/math/detmath.h"
#include "mptrack/vmp/vmp_tracker.h"
#include "../unit/vmp_test_frames.h"

using mptrack::Status;
using Tracker = mptrack::VmpTracker<float, mptrack::VmpSmallCaps>;

TEST_CASE("VMP golden: 16 raw frames of two converging drones, float, bit-exact") {
  const mptrack::VmpParams params;
  auto trk = std::make_unique<Tracker>();
  REQUIRE(trk->init(params) == Status::kOk);
  auto cube = std::make_unique<vmp_test::Cube>();
  vmp_test::Lcg rng{0x5eed0012u};
  mptrack::test::GoldenFile g("vmp_tracker");
  for (std::uint32_t k = 0; k < 16; ++k) {
    const double t = 0.1 * static_cast<double>(k);
    vmp_test::clear(*cube, 100000u * static_cast<std::uint64_t>(k + 1));
    // Drone 1 radial at 45 deg; drone 2 converging on it (1.2 m apart at k = 15).
    const double pos[2][2] = {{12.0 + 4.95 * t, 12.0 + 4.95 * t}, {12.0 + 4.95 * t, 24.0 - 2.7 * t}};
    for (const auto& p : pos) {
      const double amp = 0.7 + 0.6 * rng.uniform();
      double s = 0.0, c = 1.0;
      mptrack::dmath::dsincos(mptrack::dmath::kTwoPi<double> * rng.uniform(), s, c);
      vmp_test::add_echo(params, p[0], p[1], amp * c, amp * s, *cube);
    }
    vmp_test::add_noise(params, rng, *cube);
    REQUIRE(trk->step(*cube) == Status::kOk);
    REQUIRE(trk->outputs().size() == 1);
    const auto& est = trk->outputs()[0];
    const std::string sk = "s" + std::to_string(k);
    g.add(sk + ".n", static_cast<unsigned>(est.tracks.size()));
    for (std::size_t i = 0; i < est.tracks.size(); ++i) {
      const auto& r = est.tracks[i];
      const std::string p = sk + ".t" + std::to_string(r.id);
      g.add(p + ".existence", r.existence);
      g.add(p + ".snr", r.snr);
      for (int a = 0; a < 4; ++a) g.add(p + ".x" + std::to_string(a), r.state(a));
      for (int a = 0; a < 4; ++a) {
        for (int b = a; b < 4; ++b) g.add(p + ".P" + std::to_string(a) + std::to_string(b), r.covariance(a, b));
      }
    }
  }
  const auto& c = trk->counters();
  g.add("scans", c.scans);
  g.add("tracks_born", c.tracks_born);
  g.add("tracks_deleted", c.tracks_deleted);
  g.add("numerical_repairs", c.numerical_repairs);
  CHECK(c.tracks_born == 2);  // both drones, nothing else
  CHECK(g.matches());
}
