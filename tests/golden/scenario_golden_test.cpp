// Golden record of seed000-s2's measurements (seed 1, run 0, scans 1..5) as
// float tracker input. Runs on x86-64 and, under qemu, on aarch64 and armhf:
// passing everywhere proves the generator (RNG transforms via dmath) draws
// identical bits on every target.
#include <doctest/doctest.h>

#include <string>

#include "golden.h"
#include "mptrack/caps.h"
#include "mptrack/scenario/builtin.h"
#include "mptrack/scenario/generator.h"

TEST_CASE("scenario golden: seed000-s2 scans 1..5 (float) are bit-exact") {
  using namespace mptrack::scenario;
  ScenarioSpec s2;
  REQUIRE(builtin_scenario("seed000-s2", s2));
  Generator gen;
  REQUIRE(gen.init(s2, 1, 0) == mptrack::Status::kOk);
  mptrack::test::GoldenFile g("scenario_s2_scans1to5");
  static mptrack::Scan<float, mptrack::DefaultCaps::kMaxMeasurements> scan;
  SimScan sim;
  for (std::uint32_t k = 1; k <= 5; ++k) {
    REQUIRE(gen.generate(k, sim) == mptrack::Status::kOk);
    REQUIRE(to_scan(sim, scan) == mptrack::Status::kOk);
    const mptrack::test::Label p = mptrack::test::Label("k") + k;
    g.add(p + ".time_us", scan.time_us);
    g.add(p + ".count", static_cast<std::uint64_t>(scan.measurements.size()));
    for (std::size_t j = 0; j < scan.measurements.size(); ++j) {
      const auto& m = scan.measurements[j];
      const mptrack::test::Label q = p + ".m" + j;
      g.add(q + ".r", m.range_m);
      g.add(q + ".az", m.azimuth_rad);
      g.add(q + ".amp", m.amplitude);
      g.add(q + ".origin", static_cast<std::int64_t>(sim.measurements[j].origin.kind == OriginKind::kTarget
                                                         ? static_cast<std::int64_t>(sim.measurements[j].origin.id)
                                                         : -1 - static_cast<std::int64_t>(sim.measurements[j].origin.id)));
    }
    for (const auto& t : sim.truth) {
      const mptrack::test::Label q = p + ".t" + t.target_id;
      g.add(q + ".px", t.x.px);
      g.add(q + ".py", t.x.py);
    }
  }
  CHECK(g.size() > 5 * 40);
  CHECK(g.matches());
}
