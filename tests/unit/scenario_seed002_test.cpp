// The seed 002 OTHR scenario (host-sim/scenario/src/othr_generator.cpp):
// truth in ground coordinates mapped to Cartesian, one detection per target
// and path through the core OTHR model, the region and clutter count, and
// the per-path pd that --pd overrides.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>

#include "mptrack/model/othr_measurement.h"
#include "mptrack/scenario/builtin.h"
#include "mptrack/scenario/generator.h"
#include "mptrack/scenario/othr_generator.h"

namespace sc = mptrack::scenario;

namespace {

sc::ScenarioSpec seed002() {
  sc::ScenarioSpec s;
  REQUIRE(sc::builtin_scenario("seed002-othr", s));
  REQUIRE(sc::validate(s).empty());
  return s;
}

}  // namespace

TEST_CASE("seed002: target 1 at scan 11 is 1700 + 0.1 x 160 km at bearing 0.48 + 8.7e-5 x 160 rad") {
  const sc::ScenarioSpec s = seed002();
  REQUIRE(s.space == sc::MeasurementSpace::kOthr);
  const auto g = sc::othr_ground_state_at(s, s.targets[0], sc::scan_time_s(s, 11));
  CHECK(g[0] == doctest::Approx(1716.0));
  CHECK(g[2] == doctest::Approx(0.48 + 8.7e-5 * 160.0));
  const sc::KinematicState x = sc::target_state_at(s, s.targets[0], sc::scan_time_s(s, 11));
  CHECK(std::hypot(x.px, x.py) == doctest::Approx(1716.0e3));
  CHECK(std::atan2(x.py, x.px) == doctest::Approx(g[2]));
  // Target 3 is born at scan 10: its clock starts there.
  const auto g3 = sc::othr_ground_state_at(s, s.targets[2], sc::scan_time_s(s, 10));
  CHECK(g3[0] == doctest::Approx(1850.0));
}

TEST_CASE("seed002: with pd 1 every live target gives one detection per path, near h^tau(x)") {
  sc::ScenarioSpec s = seed002();
  for (auto& p : s.othr.paths) p.pd = 1.0;  // what --pd 1 does
  sc::Generator gen;
  REQUIRE(gen.init(s, 7, 0) == mptrack::Status::kOk);
  sc::SimScan scan;
  REQUIRE(gen.generate(15, scan) == mptrack::Status::kOk);  // targets 1-4 alive
  CHECK(scan.has_doppler);
  REQUIRE(scan.truth.size() == 4);
  int per_target[5] = {0, 0, 0, 0, 0};
  for (const auto& m : scan.measurements) {
    if (m.origin.kind != sc::OriginKind::kTarget) continue;
    ++per_target[m.origin.id];
    REQUIRE(m.path >= 0);
    const auto g = sc::othr_ground_state_at(s, s.targets[m.origin.id - 1], sc::scan_time_s(s, 15));
    const auto& ps = s.othr.paths[static_cast<std::size_t>(m.path)];
    const mptrack::model::OthrMeas<double> y = mptrack::model::othr_measure(
        mptrack::model::OthrState<double>(g[0], g[1], g[2], g[3]),
        mptrack::model::OthrPath<double>{ps.tx_height_km, ps.rx_height_km}, s.othr.baseline_km);
    CHECK(std::abs(m.range_m - y(0) * 1e3) < 5.0 * s.sigma_range_m);
    CHECK(std::abs(m.doppler_mps - y(1) * 1e3) < 5.0 * s.othr.sigma_range_rate_mps);
    CHECK(std::abs(m.azimuth_rad - y(2)) < 5.0 * sc::deg_to_rad(s.sigma_azimuth_deg));
  }
  for (int id = 1; id <= 4; ++id) CHECK(per_target[id] == 4);
}

TEST_CASE("seed002: clutter fills the slant box with mean Nc = 125 per scan") {
  const sc::ScenarioSpec s = seed002();
  sc::Generator gen;
  REQUIRE(gen.init(s, 3, 0) == mptrack::Status::kOk);
  double total = 0.0;
  const double az_min = sc::deg_to_rad(s.region.azimuth_min_deg);
  const double az_max = sc::deg_to_rad(s.region.azimuth_max_deg);
  for (std::uint32_t k = 1; k <= 30; ++k) {
    sc::SimScan scan;
    REQUIRE(gen.generate(k, scan) == mptrack::Status::kOk);
    for (const auto& m : scan.measurements) {
      if (m.origin.kind != sc::OriginKind::kClutter) continue;
      total += 1.0;
      CHECK(m.range_m >= s.region.range_min_m);
      CHECK(m.range_m <= s.region.range_max_m);
      CHECK(m.azimuth_rad >= az_min);
      CHECK(m.azimuth_rad <= az_max);
      CHECK(std::abs(m.doppler_mps) <= s.othr.range_rate_max_mps);
    }
  }
  // 30 Poisson(125) draws: mean 125, standard error sqrt(125 / 30) = 2.04.
  CHECK(total / 30.0 == doctest::Approx(125.0).epsilon(0.06));
}

TEST_CASE("seed002: a spec with no path or a pd outside (0, 1] is refused with the field named") {
  sc::ScenarioSpec s = seed002();
  s.othr.paths[2].pd = 0.0;
  CHECK(sc::validate(s).rfind("paths.list[2].pd", 0) == 0);
  s = seed002();
  s.othr.paths.clear();
  CHECK(sc::validate(s).rfind("paths.list", 0) == 0);
}
