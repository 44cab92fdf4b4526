// Seed 003 sea-clutter scene generator (host-sim/sea): determinism, clutter
// power, SCR of the injected targets, target placement.
#include <doctest/doctest.h>

#include <cmath>

#include "mptrack/sea/sea_generator.h"

namespace sea = mptrack::sea;

namespace {

sea::SeaScenario sea_a() {
  sea::SeaScenario s;
  REQUIRE(sea::builtin_sea_scenario("seed003-sea-a", s));
  return s;
}

}  // namespace

TEST_CASE("sea scenes: the same seed gives the same samples, another seed other samples") {
  sea::SeaSceneGenerator a(sea_a(), 7), b(sea_a(), 7), c(sea_a(), 8);
  sea::SeaScan sa, sb, scn;
  REQUIRE(a.next(sa));
  REQUIRE(b.next(sb));
  REQUIRE(c.next(scn));
  CHECK(sa.re == sb.re);
  CHECK(sa.im == sb.im);
  CHECK(sa.re != scn.re);
}

TEST_CASE("sea scenes: 15 scans, then none; every built-in validates") {
  for (const auto& name : sea::builtin_sea_scenario_names()) {
    sea::SeaScenario s;
    REQUIRE(sea::builtin_sea_scenario(name, s));
    CHECK(s.validate().empty());
  }
  sea::SeaSceneGenerator g(sea_a(), 1);
  sea::SeaScan scan;
  int n = 0;
  while (g.next(scan)) ++n;
  CHECK(n == 15);
}

TEST_CASE("sea scenes: mean clutter power is the CNR (texture mean 1, unit-power speckle, unit noise)") {
  // 30 dB -> 1000 per sample on average; 3 scenes x 15 scans of a Gamma(3)
  // texture over 96 correlated bins: the mean is within 20 % of 1000.
  double sum = 0.0;
  int n = 0;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    sea::SeaSceneGenerator g(sea_a(), seed);
    sea::SeaScan scan;
    while (g.next(scan)) {
      sum += scan.clutter_power;
      ++n;
    }
  }
  CHECK(sum / n == doctest::Approx(1000.0).epsilon(0.2));
}

TEST_CASE("sea scenes: a target's echo power is 10^(SCR/10) times the scan's clutter power") {
  sea::SeaScenario with = sea_a();
  with.num_targets = 1;
  with.scr_db = 10.0;
  with.target_amp_log_sd = 0.0;  // a(p) = 1: the power is exactly P_t
  sea::SeaScenario without = with;
  without.num_targets = 0;
  sea::SeaSceneGenerator g1(with, 5), g0(without, 5);
  sea::SeaScan s1, s0;
  REQUIRE(g1.next(s1));
  REQUIRE(g0.next(s0));
  double target_power = 0.0;  // sum over bins of the mean power per pulse (sum omega = 1)
  for (std::size_t i = 0; i < s1.re.size(); ++i) {
    const double dr = static_cast<double>(s1.re[i]) - static_cast<double>(s0.re[i]);
    const double di = static_cast<double>(s1.im[i]) - static_cast<double>(s0.im[i]);
    target_power += dr * dr + di * di;
  }
  target_power /= static_cast<double>(with.pulses);
  CHECK(s1.clutter_power == s0.clutter_power);
  CHECK(target_power / s1.clutter_power == doctest::Approx(10.0).epsilon(2e-3));
}

TEST_CASE("sea scenes: targets keep Doppler in [-400, 300] Hz, range inside the margins, f = -2 rdot / lambda") {
  sea::SeaScenario s = sea_a();
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    sea::SeaSceneGenerator g(s, seed);
    sea::SeaScan scan;
    while (g.next(scan)) {
      for (const auto& t : scan.truth) {
        CHECK(t.doppler_hz >= -400.0);
        CHECK(t.doppler_hz <= 300.0);
        CHECK(t.doppler_hz == doctest::Approx(-2.0 * t.range_rate_mps / s.wavelength_m()));
        CHECK(t.range_bin >= s.edge_margin_bins - 0.01);
        CHECK(t.range_bin <= s.range_bins - 1 - s.edge_margin_bins + 0.01);
      }
    }
  }
}

TEST_CASE("sea scenes: sea-c's targets keep Doppler in [-90, 30] Hz, inside sea-b's clutter band") {
  sea::SeaScenario s;
  REQUIRE(sea::builtin_sea_scenario("seed003-sea-c", s));
  // sea-b's clutter is centred at -30 Hz with a 35 Hz sd: [-90, 30] Hz is
  // within 1.8 sd of that centre.
  int seen = 0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    sea::SeaSceneGenerator g(s, seed);
    sea::SeaScan scan;
    while (g.next(scan)) {
      for (const auto& t : scan.truth) {
        CHECK(t.doppler_hz >= -90.0);
        CHECK(t.doppler_hz <= 30.0);
        ++seen;
      }
    }
  }
  CHECK(seen == 5 * 15 * 3);
}

TEST_CASE("sea scenes: sea-c's clutter is sea-b's (the same samples without targets)") {
  sea::SeaScenario b, c;
  REQUIRE(sea::builtin_sea_scenario("seed003-sea-b", b));
  REQUIRE(sea::builtin_sea_scenario("seed003-sea-c", c));
  b.num_targets = 0;
  c.num_targets = 0;
  sea::SeaSceneGenerator gb(b, 4), gc(c, 4);
  sea::SeaScan sb, sc;
  REQUIRE(gb.next(sb));
  REQUIRE(gc.next(sc));
  CHECK(sb.re == sc.re);
  CHECK(sb.im == sc.im);
}
