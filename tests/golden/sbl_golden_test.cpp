// Golden record of the SBL detector (float, SblDefaultCaps, seed 004 caps) on
// two synthesised frames: three echoes in noise (two of them 2.5 m apart in
// one range cell) and a lone weak echo. The frames come from the front-end test
// synthesiser (xorshift + dmath, bit-identical on every target), so the
// committed file pins the detector's output bit for bit on x86-64, aarch64 and
// armhf.
// Regenerate (after an intended change): MPTRACK_GOLDEN_REGENERATE=1 ./sbl_golden_test
#include <doctest/doctest.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "../unit/sbl_test_scene.h"
#include "golden.h"
#include "mptrack/sbl/sbl_detector.h"

using mptrack::Status;
using Caps = mptrack::frontend::Seed004RadarCaps;
using mptrack::test::SblEcho;

TEST_CASE("SBL golden: two frames of seed 004 echoes in noise, float, bit-exact") {
  const mptrack::SblParams p;
  auto det = std::make_unique<mptrack::SblDetector<float>>();
  auto cube = std::make_unique<mptrack::frontend::RadarCube<Caps>>();
  REQUIRE(det->init(p) == Status::kOk);
  mptrack::test::GoldenFile g("sbl_detector");
  const SblEcho frame0[3] = {{14.5, 25.1, 4.0, 0.3}, {16.0, 27.0, 3.0, 2.0}, {-25.0, 40.0, 2.0, -1.0}};
  const SblEcho frame1[1] = {{30.0, 30.0, 1.5, 0.5}};
  for (std::uint32_t f = 0; f < 2; ++f) {
    mptrack::test::sbl_scene<Caps>(p, f == 0 ? frame0 : frame1, f == 0 ? 3 : 1, true, 4000 + f, *cube);
    cube->time_us = 100000u * (f + 1);
    mptrack::Scan<float, 16> scan;
    REQUIRE(det->process(*cube, scan) == Status::kOk);
    const std::string s = "f" + std::to_string(f);
    g.add(s + ".n", static_cast<unsigned>(scan.measurements.size()));
    REQUIRE(det->num_detections() == scan.measurements.size());
    for (std::size_t i = 0; i < scan.measurements.size(); ++i) {
      const std::string q = s + ".d" + std::to_string(i);
      const auto& m = scan.measurements[i];
      const auto& d = det->detection(i);
      g.add(q + ".range", m.range_m);
      g.add(q + ".azimuth", m.azimuth_rad);
      g.add(q + ".amplitude", m.amplitude);
      g.add(q + ".x", d.x_m);
      g.add(q + ".y", d.y_m);
      g.add(q + ".snr", d.snr);
      g.add(q + ".cxx", d.cov_m2(0, 0));
      g.add(q + ".cxy", d.cov_m2(0, 1));
      g.add(q + ".cyy", d.cov_m2(1, 1));
      g.add(q + ".mu_re", d.mu.re);
      g.add(q + ".mu_im", d.mu.im);
    }
  }
  g.add("added", static_cast<std::uint64_t>(det->counters().components_added));
  g.add("pruned", static_cast<std::uint64_t>(det->counters().components_pruned));
  CHECK(g.matches());
}
