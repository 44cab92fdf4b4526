// Seed 004 drone trajectories (docs/algorithms/scenarios.md §Seed 004) at hand-computed
// frames.
#include <doctest/doctest.h>

#include <cmath>

#include "mptrack/adc/adc_scenario.h"
#include "mptrack/adc/trajectory.h"

namespace adc = mptrack::adc;

namespace {
constexpr double kV = 4.949747468305833;  // 7 cos 45 deg [m/s]
const adc::DroneSpec& drone(const adc::AdcScenario& s, std::uint32_t id) { return s.drones[id - 1]; }
}  // namespace

TEST_CASE("adc trajectory: track 1 moves radially at 45 deg from (10, 10) to r = 83.4 m") {
  adc::AdcScenario s;
  REQUIRE(adc::builtin_adc_scenario("seed004-drones", s));
  const adc::DroneState p1 = adc::drone_state_at(drone(s, 1), 1, 0.1);
  CHECK(p1.x == 10.0);
  CHECK(p1.y == 10.0);
  // n = 100: 99 steps of 0.1 s at 4.9497 m/s -> 10 + 49.0025 = 59.0025 per axis.
  const adc::DroneState p100 = adc::drone_state_at(drone(s, 1), 100, 0.1);
  CHECK(p100.x == doctest::Approx(59.00249993622774));
  CHECK(p100.y == doctest::Approx(59.00249993622774));
  CHECK(std::hypot(p100.x, p100.y) == doctest::Approx(83.44).epsilon(1e-3));
}

TEST_CASE("adc trajectory: tracks 1 and 2 cross within 0.21 m at frame 22") {
  adc::AdcScenario s;
  REQUIRE(adc::builtin_adc_scenario("seed004-drones", s));
  // 21 steps: x = 10 + 2.1 v for both; y1 = 10 + 2.1 v, y2 = 31 - 2.1 v.
  const adc::DroneState a = adc::drone_state_at(drone(s, 1), 22, 0.1);
  const adc::DroneState b = adc::drone_state_at(drone(s, 2), 22, 0.1);
  CHECK(a.x == doctest::Approx(10.0 + 2.1 * kV));
  CHECK(b.x == doctest::Approx(10.0 + 2.1 * kV));
  CHECK(b.y == doctest::Approx(31.0 - 2.1 * kV));
  const double d = std::hypot(a.x - b.x, a.y - b.y);
  CHECK(d == doctest::Approx(21.0 - 4.2 * kV));  // 0.21106 m
  CHECK(d < 0.53);                                       // paper: "within 53 cm"
  // Separations at n = 20 and 24 (docs/algorithms/scenarios.md §Seed 004: 2.19 and 1.68 m).
  const auto sep = [&](std::uint32_t n) {
    const adc::DroneState u = adc::drone_state_at(drone(s, 1), n, 0.1);
    const adc::DroneState v = adc::drone_state_at(drone(s, 2), n, 0.1);
    return std::hypot(u.x - v.x, u.y - v.y);
  };
  CHECK(sep(20) == doctest::Approx(2.19).epsilon(0.01));
  CHECK(sep(24) == doctest::Approx(1.68).epsilon(0.02));
}

TEST_CASE("adc trajectory: track 2 turns linearly in velocity from frame 21") {
  adc::AdcScenario s;
  REQUIRE(adc::builtin_adc_scenario("seed004-drones", s));
  // n = 31: v_1..v_21 = v0, v_{21+k} = v0 + (vb - v0) k/80 for k = 1..9, so
  // p = p0 + 0.1 (30 v0 + (vb - v0) 45/80); v_31 = v0 + (vb - v0) 10/80.
  const adc::DroneState p = adc::drone_state_at(drone(s, 2), 31, 0.1);
  CHECK(p.x == doctest::Approx(10.0 + 0.1 * (30.0 * kV - kV * 45.0 / 80.0)));
  CHECK(p.y == doctest::Approx(31.0 + 0.1 * (-30.0 * kV + (7.0 + kV) * 45.0 / 80.0)));
  CHECK(p.vx == doctest::Approx(kV * 70.0 / 80.0));
  CHECK(p.vy == doctest::Approx(-kV + (7.0 + kV) * 10.0 / 80.0));
  // After the 80-step ramp (n = 101 would be past the end): at n = 100, k = 79.
  const adc::DroneState q = adc::drone_state_at(drone(s, 2), 100, 0.1);
  CHECK(q.vy == doctest::Approx(-kV + (7.0 + kV) * 79.0 / 80.0));
}

TEST_CASE("adc trajectory: track 3 is born at (15, 20) at frame 50 and manoeuvres after 16 steps") {
  adc::AdcScenario s;
  REQUIRE(adc::builtin_adc_scenario("seed004-drones", s));
  const adc::DroneSpec& d3 = drone(s, 3);
  CHECK(d3.birth_frame == 50);
  CHECK(d3.death_frame == 95);
  const adc::DroneState b = adc::drone_state_at(d3, 50, 0.1);
  CHECK(b.x == 15.0);
  CHECK(b.y == 20.0);
  const adc::DroneState p = adc::drone_state_at(d3, 66, 0.1);  // 16 constant steps
  CHECK(p.x == doctest::Approx(15.0 + 1.6 * kV));
  CHECK(p.y == doctest::Approx(20.0 - 1.6 * kV));
  CHECK(p.vx == doctest::Approx(kV));
  // 14-step ramp to (-4.33, 2.5) ends at n = 80; constant afterwards.
  const adc::DroneState e = adc::drone_state_at(d3, 80, 0.1);
  CHECK(e.vx == doctest::Approx(-4.330127018922193));
  CHECK(e.vy == doctest::Approx(2.5));
  const adc::DroneState f = adc::drone_state_at(d3, 95, 0.1);
  CHECK(f.x == doctest::Approx(e.x - 1.5 * 4.330127018922193));
  CHECK(f.y == doctest::Approx(e.y + 1.5 * 2.5));
  // A continuous-time ramp gives r in 21.9..26.5 m; ours is discrete and differs by up
  // to 0.3 m at the far end of the turn (docs/algorithms/scenarios.md §Seed 004).
  for (std::uint32_t n = 50; n <= 95; ++n) {
    const adc::DroneState x = adc::drone_state_at(d3, n, 0.1);
    const double r = std::hypot(x.x, x.y);
    CHECK(r > 21.8);
    CHECK(r < 26.9);
  }
}
