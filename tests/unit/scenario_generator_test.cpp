// Scenario generator: reproducibility, hand-computed seed 000 trajectories
// (docs/algorithms/scenarios.md §Seed 000), clutter time variation (seed 000 eq. (104)),
// measurement bookkeeping.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>

#include "mptrack/scenario/builtin.h"
#include "mptrack/scenario/generator.h"

using namespace mptrack::scenario;
using mptrack::Status;

namespace {

ScenarioSpec builtin(const char* name) {
  ScenarioSpec s;
  REQUIRE(builtin_scenario(name, s));
  return s;
}

const TargetSpec& target(const ScenarioSpec& s, std::uint32_t id) {
  for (const auto& t : s.targets) {
    if (t.id == id) return t;
  }
  FAIL("no target " << id);
  return s.targets.front();
}

bool same_bits(const SimScan& a, const SimScan& b) {
  if (a.measurements.size() != b.measurements.size()) return false;
  for (std::size_t j = 0; j < a.measurements.size(); ++j) {
    const auto& x = a.measurements[j];
    const auto& y = b.measurements[j];
    if (std::memcmp(&x.range_m, &y.range_m, sizeof(double)) != 0 ||
        std::memcmp(&x.azimuth_rad, &y.azimuth_rad, sizeof(double)) != 0 ||
        std::memcmp(&x.amplitude, &y.amplitude, sizeof(double)) != 0 || x.origin.id != y.origin.id ||
        x.origin.kind != y.origin.kind) {
      return false;
    }
  }
  return true;
}

}  // namespace

TEST_CASE("generator: same seed and run give the same bits; another seed or run differs") {
  const ScenarioSpec s2 = builtin("seed000-s2");
  Generator a, b, c, d;
  REQUIRE(a.init(s2, 1, 0) == Status::kOk);
  REQUIRE(b.init(s2, 1, 0) == Status::kOk);
  REQUIRE(c.init(s2, 2, 0) == Status::kOk);
  REQUIRE(d.init(s2, 1, 1) == Status::kOk);
  SimScan sa, sb, sc, sd;
  for (std::uint32_t k : {1u, 2u, 150u}) {
    REQUIRE(a.generate(k, sa) == Status::kOk);
    REQUIRE(b.generate(k, sb) == Status::kOk);
    REQUIRE(c.generate(k, sc) == Status::kOk);
    REQUIRE(d.generate(k, sd) == Status::kOk);
    CHECK(sa.measurements.size() > 0);
    CHECK(same_bits(sa, sb));
    CHECK_FALSE(same_bits(sa, sc));
    CHECK_FALSE(same_bits(sa, sd));
  }
}

TEST_CASE("generator: a scan does not depend on which scans were generated before it") {
  const ScenarioSpec s2 = builtin("seed000-s2");
  Generator g;
  REQUIRE(g.init(s2, 5, 3) == Status::kOk);
  SimScan alone, after;
  REQUIRE(g.generate(7, alone) == Status::kOk);
  for (std::uint32_t k = 1; k <= 7; ++k) REQUIRE(g.generate(k, after) == Status::kOk);
  CHECK(same_bits(alone, after));
}

TEST_CASE("generator: Targets 1 and 2 follow the default truth of docs/algorithms/scenarios.md") {
  const ScenarioSpec s = builtin("seed000-s2");
  const TargetSpec& t1 = target(s, 1);
  const TargetSpec& t2 = target(s, 2);
  // k = 1, t = 0: Table II.
  KinematicState x = target_state_at(s, t1, scan_time_s(s, 1));
  CHECK(x.px == 10000.0);
  CHECK(x.py == 13465.0);
  // k = 21, t = 25 s: end of the CV phase, y = 13465 - 40 * 25.
  x = target_state_at(s, t1, scan_time_s(s, 21));
  CHECK(x.px == doctest::Approx(11000.0).epsilon(1e-12));
  CHECK(x.py == doctest::Approx(12465.0).epsilon(1e-12));
  // t = 146.875 s: v_y = 0 at y = 12465 - 40 * 121.875 / 2 = 10027.5.
  x = target_state_at(s, t1, 146.875);
  CHECK(x.py == doctest::Approx(10027.5).epsilon(1e-12));
  CHECK(std::fabs(x.vy) < 1e-9);
  // Mid-maneuver t = 85.9375 s (tau = 60.9375): y = 12465 - 40 tau + a tau^2 / 2.
  const double tau = 60.9375, a = 40.0 / 121.875;
  x = target_state_at(s, t1, 85.9375);
  CHECK(x.py == doctest::Approx(12465.0 - 40.0 * tau + 0.5 * a * tau * tau).epsilon(1e-12));
  CHECK(x.vy == doctest::Approx(-20.0).epsilon(1e-12));
  // k = 119 (first evaluated scan of S1) and k = 340: parallel, 20 m apart.
  x = target_state_at(s, t1, scan_time_s(s, 119));
  CHECK(x.px == doctest::Approx(15900.0).epsilon(1e-12));
  CHECK(x.py == doctest::Approx(10027.5).epsilon(1e-12));
  CHECK(x.vx == 40.0);
  CHECK(x.vy == 0.0);
  const KinematicState e1 = target_state_at(s, t1, scan_time_s(s, 340));
  const KinematicState e2 = target_state_at(s, t2, scan_time_s(s, 340));
  CHECK(e1.px == doctest::Approx(26950.0).epsilon(1e-12));
  CHECK(e1.py - e2.py == doctest::Approx(20.0).epsilon(1e-9));
}

TEST_CASE("generator: Targets 3-5 move at constant velocity and cross near k = 170.5") {
  const ScenarioSpec s = builtin("seed000-s2");
  const KinematicState x3 = target_state_at(s, target(s, 3), scan_time_s(s, 171));  // t = 212.5 s
  CHECK(x3.px == doctest::Approx(36500.0).epsilon(1e-12));
  CHECK(x3.py == doctest::Approx(20543.0 - 12.0 * 212.5).epsilon(1e-12));
  // y = 18000 (Target 4's line) at t = 2543/12 s (T3) and 2542/12 s (T5): k = 170.5 and 170.47.
  CHECK(target_state_at(s, target(s, 3), 2543.0 / 12.0).py == doctest::Approx(18000.0).epsilon(1e-12));
  CHECK(target_state_at(s, target(s, 5), 2542.0 / 12.0).py == doctest::Approx(18000.0).epsilon(1e-12));
  CHECK(target_state_at(s, target(s, 4), 2542.0 / 12.0).py == 18000.0);
}

TEST_CASE("generator: a coordinated turn of 90 degrees rotates the velocity and offsets v/w (1-cos, sin)") {
  ScenarioSpec s = builtin("seed000-s2");
  TargetSpec t;
  t.id = 9;
  t.initial_state = {20000.0, 100.0, 20000.0, 0.0};
  t.birth_scan = 1;
  t.death_scan = 340;
  MotionSegment ct;
  ct.start_s = 0.0;
  ct.kind = MotionKind::kCoordinatedTurn;
  ct.turn_rate_deg_s = 9.0;  // 90 degrees in 10 s
  t.motion = {ct};
  const KinematicState x = target_state_at(s, t, 10.0);
  const double r = 100.0 / (kPi / 20.0);  // v / omega = 636.62 m
  CHECK(x.px == doctest::Approx(20000.0 + r).epsilon(1e-12));
  CHECK(x.py == doctest::Approx(20000.0 + r).epsilon(1e-12));
  CHECK(std::fabs(x.vx) < 1e-9);
  CHECK(x.vy == doctest::Approx(100.0).epsilon(1e-12));
}

TEST_CASE("generator: S3 clutter follows seed 000 eq. (104) (count x1 -> x1.5 -> x1, covariance 1/3 -> 4/3)") {
  const ScenarioSpec s3 = builtin("seed000-s3");
  const ClutterSpec& c1 = s3.clutter[1];  // 20 points, [130, 170], diag(1 km, 3 deg)^2
  REQUIRE(c1.id == 1);
  const ClutterAtScan start = clutter_at_scan(s3, c1, 130);
  const ClutterAtScan mid = clutter_at_scan(s3, c1, 150);
  const ClutterAtScan end = clutter_at_scan(s3, c1, 170);
  CHECK(start.mean_count == doctest::Approx(20.0).epsilon(1e-12));
  CHECK(mid.mean_count == doctest::Approx(30.0).epsilon(1e-12));
  CHECK(end.mean_count == doctest::Approx(20.0).epsilon(1e-12));
  CHECK(start.cov_rr == doctest::Approx(1e6 / 3.0).epsilon(1e-12));
  CHECK(mid.cov_rr == doctest::Approx(1e6 * (1.0 / 3.0 + 0.5)).epsilon(1e-12));
  CHECK(end.cov_rr == doctest::Approx(1e6 * 4.0 / 3.0).epsilon(1e-12));
  const double sa = 3.0 * kPi / 180.0;
  CHECK(end.cov_aa == doctest::Approx(sa * sa * 4.0 / 3.0).epsilon(1e-12));
  CHECK(mid.mean_azimuth_rad == doctest::Approx(30.0 * kPi / 180.0).epsilon(1e-15));
  // S2: constant.
  const ScenarioSpec s2 = builtin("seed000-s2");
  CHECK(clutter_at_scan(s2, s2.clutter[1], 150).mean_count == 20.0);
  CHECK(clutter_at_scan(s2, s2.clutter[1], 150).cov_rr == 1e6);
}

TEST_CASE("generator: measurements lie in the region and truth points at its own measurement") {
  const ScenarioSpec s2 = builtin("seed000-s2");
  Generator g;
  REQUIRE(g.init(s2, 11, 0) == Status::kOk);
  SimScan scan;
  std::size_t detected = 0;
  for (std::uint32_t k = 140; k <= 160; ++k) {
    REQUIRE(g.generate(k, scan) == Status::kOk);
    CHECK(scan.scan == k);
    CHECK(scan.time_us == static_cast<std::uint64_t>(k - 1) * 1250000u);
    CHECK(scan.truth.size() == 5);
    for (const auto& m : scan.measurements) {
      CHECK(m.range_m >= 10000.0);
      CHECK(m.range_m <= 50000.0);
      CHECK(m.azimuth_rad >= 10.0 * kPi / 180.0);
      CHECK(m.azimuth_rad <= 60.0 * kPi / 180.0);
      CHECK(m.amplitude > 0.715);
    }
    for (const auto& t : scan.truth) {
      if (t.measurement_index < 0) continue;
      ++detected;
      const SimMeasurement& m = scan.measurements[static_cast<std::size_t>(t.measurement_index)];
      CHECK(m.origin.kind == OriginKind::kTarget);
      CHECK(m.origin.id == t.target_id);
      const double r = std::sqrt(t.x.px * t.x.px + t.x.py * t.x.py);
      CHECK(std::fabs(m.range_m - r) < 6.0 * 20.0);  // 6 sigma
    }
  }
  // 21 scans x 5 targets, Pd 0.889 / 0.972: expect about 96 detections.
  CHECK(detected > 80);
  CHECK(detected < 106);
}

TEST_CASE("generator: uniform clutter count averages the Poisson mean; clutter_scale scales it") {
  const ScenarioSpec s1 = builtin("seed000-s1");  // targets 1, 2 + 30 uniform clutter points
  for (double scale : {1.0, 2.0}) {
    GeneratorOptions opt;
    opt.clutter_scale = scale;
    double clutter = 0.0;
    const int runs = 400;
    for (int run = 0; run < runs; ++run) {
      Generator g;
      REQUIRE(g.init(s1, 3, static_cast<std::uint32_t>(run), opt) == Status::kOk);
      SimScan scan;
      REQUIRE(g.generate(200, scan) == Status::kOk);
      for (const auto& m : scan.measurements) clutter += m.origin.kind == OriginKind::kClutter ? 1.0 : 0.0;
    }
    const double lambda = 30.0 * scale;
    CAPTURE(scale);
    CHECK(std::fabs(clutter / runs - lambda) < 5.0 * std::sqrt(lambda / runs));
  }
}

TEST_CASE("generator: to_scan copies into a tracker Scan and reports overflow") {
  const ScenarioSpec s2 = builtin("seed000-s2");
  Generator g;
  REQUIRE(g.init(s2, 1, 0) == Status::kOk);
  SimScan scan;
  REQUIRE(g.generate(1, scan) == Status::kOk);
  REQUIRE(scan.measurements.size() > 8);
  mptrack::Scan<float, 256> big;
  CHECK(to_scan(scan, big) == Status::kOk);
  CHECK(big.measurements.size() == scan.measurements.size());
  CHECK(big.time_us == 0);
  CHECK(big.measurements[0].range_m == static_cast<float>(scan.measurements[0].range_m));
  mptrack::Scan<float, 8> small;
  CHECK(to_scan(scan, small) == Status::kCapacityExceeded);
  CHECK(small.measurements.size() == 8);
}

TEST_CASE("generator: init rejects invalid specs and out-of-range scans") {
  ScenarioSpec s = builtin("seed000-s1");
  s.targets[1].snr = -1.0;
  Generator g;
  CHECK(g.init(s, 1, 0) == Status::kInvalidArgument);
  CHECK(g.error() == "targets[1].snr = -1: must be in (0, 1e+12] (linear)");
  SimScan scan;
  CHECK(g.generate(1, scan) == Status::kInvalidArgument);  // not initialised
  s = builtin("seed000-s1");
  s.clutter[0].death_scan = 400;
  CHECK(g.init(s, 1, 0) == Status::kInvalidArgument);
  CHECK(g.error() == "clutter[0].lifetime: expected [birth, death] with 1 <= birth <= death <= scans (340)");
  REQUIRE(g.init(builtin("seed000-s1"), 1, 0) == Status::kOk);
  CHECK(g.generate(0, scan) == Status::kInvalidArgument);
  CHECK(g.generate(341, scan) == Status::kInvalidArgument);
  CHECK(g.generate(340, scan) == Status::kOk);
}
