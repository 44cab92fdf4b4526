// Golden case of the SBL detector (float, SblDefaultCaps, seed 004 caps) on
// two synthesised frames: three echoes in noise (two of them 2.5 m apart in
// one range cell) and a lone weak echo. The frames come from the front-end
// test synthesiser (xorshift + dmath, bit-identical on every target).
#include <cstddef>
#include <cstdint>

#include "../../unit/sbl_test_scene.h"
#include "golden_cases.h"
#include "mptrack/sbl/sbl_detector.h"

namespace mptrack::test {

namespace {

using Caps = frontend::Seed004RadarCaps;

Slot<SblDetector<float>> g_detector;
Slot<frontend::RadarCube<Caps>> g_cube;

}  // namespace

void golden_case_sbl_detector(GoldenSink& g) {
  const SblParams p;
  SblDetector<float>& det = g_detector.make();
  frontend::RadarCube<Caps>& cube = g_cube.make();
  g.require(det.init(p) == Status::kOk, "sbl init");
  const SblEcho frame0[3] = {{14.5, 25.1, 4.0, 0.3}, {16.0, 27.0, 3.0, 2.0}, {-25.0, 40.0, 2.0, -1.0}};
  const SblEcho frame1[1] = {{30.0, 30.0, 1.5, 0.5}};
  for (std::uint32_t f = 0; f < 2; ++f) {
    sbl_scene<Caps>(p, f == 0 ? frame0 : frame1, f == 0 ? 3 : 1, true, 4000 + f, cube);
    cube.time_us = 100000u * (f + 1);
    Scan<float, 16> scan;
    g.require(det.process(cube, scan) == Status::kOk, "sbl process");
    const Label s = Label("f") + f;
    g.add(s + ".n", static_cast<unsigned>(scan.measurements.size()));
    g.require(det.num_detections() == scan.measurements.size(), "sbl detections match the scan");
    for (std::size_t i = 0; i < scan.measurements.size(); ++i) {
      const Label q = s + ".d" + i;
      const auto& m = scan.measurements[i];
      const auto& d = det.detection(i);
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
  g.add("added", static_cast<std::uint64_t>(det.counters().components_added));
  g.add("pruned", static_cast<std::uint64_t>(det.counters().components_pruned));
}

}  // namespace mptrack::test
