// VmpTracker on seed 004's own scenario as host-sim synthesises it
// (adc::FrameSynthesizer: Swerling 3, model-A noise) with the parameters
// adc::vmp_params_for builds: the regression guard for the end-to-end numbers
// of docs/algorithms/vmp.md §Measured (there over 100 runs; here 4).
#include <doctest/doctest.h>

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "mptrack/adc/adc_scenario.h"
#include "mptrack/adc/synthesizer.h"
#include "mptrack/adc/vmp_config.h"
#include "mptrack/metrics/ospa.h"
#include "mptrack/vmp/vmp_tracker.h"

using mptrack::Status;

TEST_CASE("VMP on seed004-drones: all three drones tracked, through the crossing, OSPA below 1 m") {
  mptrack::adc::AdcScenario sc;
  REQUIRE(mptrack::adc::builtin_adc_scenario("seed004-drones", sc));
  const mptrack::VmpParams p = mptrack::adc::vmp_params_for(sc);
  mptrack::ParamError where;
  REQUIRE(mptrack::VmpTracker<float>::validate(p, &where) == Status::kOk);
  auto ospa = std::make_unique<mptrack::OspaMetric<double, 64>>();
  REQUIRE(ospa->init(mptrack::MetricParams<double>{}) == Status::kOk);
  auto cube = std::make_unique<mptrack::adc::AdcCube>();
  std::vector<mptrack::adc::DroneTruth> truth;
  double sum70 = 0.0, sum_cross = 0.0;
  int n70 = 0;
  std::uint64_t extra_tracks = 0;
  constexpr int kRuns = 4;
  for (std::uint32_t run = 0; run < kRuns; ++run) {
    mptrack::adc::FrameSynthesizer syn;
    REQUIRE(syn.init(sc, 1234, run) == Status::kOk);
    auto trk = std::make_unique<mptrack::VmpTracker<float>>();
    REQUIRE(trk->init(p) == Status::kOk);
    for (std::uint32_t n = 1; n <= 70; ++n) {
      REQUIRE(syn.synthesize(n, *cube, truth) == Status::kOk);
      REQUIRE(trk->step(*cube) == Status::kOk);
      const auto& e = trk->outputs()[0];
      std::vector<Eigen::Vector2d> x, y;
      for (const auto& t : truth) x.emplace_back(t.state.x, t.state.y);
      for (const auto& r : e.tracks) y.emplace_back(static_cast<double>(r.state(0)), static_cast<double>(r.state(2)));
      mptrack::OspaResult<double> res;
      REQUIRE(ospa->compute(x.data(), x.size(), y.data(), y.size(), res) == Status::kOk);
      sum70 += res.total;
      ++n70;
      if (n >= 20 && n <= 24) sum_cross += res.total;
      if (y.size() > x.size()) extra_tracks += y.size() - x.size();
    }
  }
  const double mean70 = sum70 / n70;
  MESSAGE("mean OSPA frames 1-70: " << mean70 << " m, crossing 20-24: " << sum_cross / (5 * kRuns) << " m");
  CHECK(mean70 < 1.0);
  CHECK(sum_cross / (5 * kRuns) < 1.0);
  CHECK(extra_tracks == 0);
}
