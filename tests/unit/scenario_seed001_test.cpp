// Seed 001 scenarios S1-S5 (seed001_amplitude_spec.md section 6): truth at
// hand-computed scans, Poisson clutter means, the Weibull amplitude law and
// the Cartesian measurement delivered as (range, azimuth).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>

#include "mptrack/scenario/builtin.h"
#include "mptrack/scenario/generator.h"

namespace sc = mptrack::scenario;

namespace {

sc::ScenarioSpec seed001(int n) {
  sc::ScenarioSpec s;
  REQUIRE(sc::builtin_scenario("seed001-s" + std::to_string(n), s));
  return s;
}

const sc::TruthState* find(const sc::SimScan& scan, std::uint32_t id) {
  for (const auto& t : scan.truth) {
    if (t.target_id == id) return &t;
  }
  return nullptr;
}

std::size_t clutter_count(const sc::SimScan& scan) {
  std::size_t n = 0;
  for (const auto& m : scan.measurements) n += m.origin.kind == sc::OriginKind::kClutter ? 1U : 0U;
  return n;
}

}  // namespace

TEST_CASE("seed001: truth positions at hand-computed scans (CV from the birth means, T = 1 s)") {
  const sc::ScenarioSpec s = seed001(1);
  CHECK(s.space == sc::MeasurementSpace::kCartesian);
  CHECK(s.targets.size() == 12);
  sc::Generator gen;
  REQUIRE(gen.init(s, 7, 0) == mptrack::Status::kOk);
  sc::SimScan scan;
  // Scan 40: target 1 = (0,0) + 39 s x (15, 10); target 5 = (400, 600) + 30 s x (-25, -5).
  REQUIRE(gen.generate(40, scan) == mptrack::Status::kOk);
  CHECK(scan.truth.size() == 12);
  REQUIRE(find(scan, 1) != nullptr);
  CHECK(find(scan, 1)->x.px == doctest::Approx(585.0));
  CHECK(find(scan, 1)->x.py == doctest::Approx(390.0));
  REQUIRE(find(scan, 5) != nullptr);
  CHECK(find(scan, 5)->x.px == doctest::Approx(-350.0));
  CHECK(find(scan, 5)->x.py == doctest::Approx(450.0));
  // Scan 41: targets 1 and 5 are gone together.
  REQUIRE(gen.generate(41, scan) == mptrack::Status::kOk);
  CHECK(scan.truth.size() == 10);
  CHECK(find(scan, 1) == nullptr);
  CHECK(find(scan, 5) == nullptr);
  // Scan 50: target 12 = (600, -200) + 20 s x (-30, 0); scan 9: 3 targets, scan 10: 6.
  REQUIRE(gen.generate(50, scan) == mptrack::Status::kOk);
  REQUIRE(find(scan, 12) != nullptr);
  CHECK(find(scan, 12)->x.px == doctest::Approx(0.0));
  CHECK(find(scan, 12)->x.py == doctest::Approx(-200.0));
  CHECK(find(scan, 12)->x.vx == doctest::Approx(-30.0));
  REQUIRE(gen.generate(9, scan) == mptrack::Status::kOk);
  CHECK(scan.truth.size() == 3);
  REQUIRE(gen.generate(10, scan) == mptrack::Status::kOk);
  CHECK(scan.truth.size() == 6);
}

TEST_CASE("seed001: every target stays inside [-1000, 1000]^2 for its whole life") {
  for (int n = 1; n <= 5; ++n) {
    const sc::ScenarioSpec s = seed001(n);
    for (const auto& t : s.targets) {
      for (std::uint32_t k = t.birth_scan; k <= t.death_scan; ++k) {
        const sc::KinematicState x = sc::target_state_at(s, t, sc::scan_time_s(s, k));
        CHECK(std::fabs(x.px) <= 1000.0);
        CHECK(std::fabs(x.py) <= 1000.0);
      }
    }
  }
}

TEST_CASE("seed001: a Cartesian measurement arrives as the polar form of its (x, y)") {
  const sc::ScenarioSpec s = seed001(2);
  sc::Generator gen;
  REQUIRE(gen.init(s, 3, 1) == mptrack::Status::kOk);
  sc::SimScan scan;
  REQUIRE(gen.generate(25, scan) == mptrack::Status::kOk);
  REQUIRE(!scan.measurements.empty());
  for (const auto& m : scan.measurements) {
    CHECK(m.range_m == doctest::Approx(std::hypot(m.x_m, m.y_m)));
    CHECK(m.range_m * std::cos(m.azimuth_rad) == doctest::Approx(m.x_m).epsilon(1e-9));
    CHECK(m.range_m * std::sin(m.azimuth_rad) == doctest::Approx(m.y_m).epsilon(1e-9));
    CHECK(std::fabs(m.x_m) <= 1000.0);
    CHECK(std::fabs(m.y_m) <= 1000.0);
  }
}

TEST_CASE("seed001: clutter counts are Poisson with the paper's mean (40, 40, 39, 39, 156 per scan)") {
  const double expected[] = {40.0, 40.0, 39.0, 39.0, 156.0};
  for (int n = 1; n <= 5; ++n) {
    CAPTURE(n);
    const sc::ScenarioSpec s = seed001(n);
    double sum = 0.0, sum2 = 0.0;
    std::uint32_t scans = 0;
    for (std::uint32_t run = 0; run < 20; ++run) {
      sc::Generator gen;
      REQUIRE(gen.init(s, 11, run) == mptrack::Status::kOk);
      for (std::uint32_t k = 1; k <= s.num_scans; ++k) {
        sc::SimScan scan;
        REQUIRE(gen.generate(k, scan) == mptrack::Status::kOk);
        // Uniform or hot spots 500 m inside the box: no clutter point is dropped.
        const double c = static_cast<double>(clutter_count(scan));
        sum += c;
        sum2 += c * c;
        ++scans;
      }
    }
    // 1000 scans: the mean's std is sqrt(lambda / 1000); allow 4 of them.
    const double mean = sum / scans;
    const double var = sum2 / scans - mean * mean;
    CHECK(mean == doctest::Approx(expected[n - 1]).epsilon(4.0 * std::sqrt(expected[n - 1] / 1000.0) / expected[n - 1]));
    // Poisson: variance = mean (within 15 %).
    CHECK(var == doctest::Approx(expected[n - 1]).epsilon(0.15));
  }
}

TEST_CASE("seed001: hot-spot clutter sits at the four centres with sigma 10 m (S2)") {
  const sc::ScenarioSpec s = seed001(2);
  const double cx[] = {0.0, -500.0, 500.0, 0.0};
  const double cy[] = {0.0, -500.0, -500.0, 500.0};
  double sx[4] = {}, sxx[4] = {}, sy[4] = {};
  double count[4] = {};
  sc::Generator gen;
  REQUIRE(gen.init(s, 5, 0) == mptrack::Status::kOk);
  for (std::uint32_t k = 1; k <= s.num_scans; ++k) {
    sc::SimScan scan;
    REQUIRE(gen.generate(k, scan) == mptrack::Status::kOk);
    for (const auto& m : scan.measurements) {
      if (m.origin.kind != sc::OriginKind::kClutter) continue;
      REQUIRE(m.origin.id >= 1);
      REQUIRE(m.origin.id <= 4);
      const std::size_t h = m.origin.id - 1;
      count[h] += 1.0;
      sx[h] += m.x_m - cx[h];
      sxx[h] += (m.x_m - cx[h]) * (m.x_m - cx[h]);
      sy[h] += m.y_m - cy[h];
    }
  }
  for (std::size_t h = 0; h < 4; ++h) {
    CAPTURE(h);
    CHECK(count[h] == doctest::Approx(500.0).epsilon(0.2));  // 10 per scan x 50 scans
    CHECK(std::fabs(sx[h] / count[h]) < 2.0);                // 4 x 10 / sqrt(500) m
    CHECK(std::fabs(sy[h] / count[h]) < 2.0);
    CHECK(std::sqrt(sxx[h] / count[h]) == doctest::Approx(10.0).epsilon(0.15));
  }
}

TEST_CASE("seed001: Weibull clutter amplitude: a^(2b) - d^(2b) is Exp(sigma0) (mean sigma0, variance sigma0^2)") {
  // S3: b = 0.8, sigma0 = 2.07; S1: Rayleigh b = 1, sigma0 = 1.
  for (int n : {3, 1}) {
    CAPTURE(n);
    const sc::ScenarioSpec s = seed001(n);
    const double b = s.clutter[0].weibull_shape;
    const double sigma0 = s.clutter[0].weibull_scale;
    const double d2b = std::pow(s.threshold, 2.0 * b);
    double sum = 0.0, sum2 = 0.0, below = 0.0, total = 0.0;
    for (std::uint32_t run = 0; run < 10; ++run) {
      sc::Generator gen;
      REQUIRE(gen.init(s, 21, run) == mptrack::Status::kOk);
      for (std::uint32_t k = 1; k <= s.num_scans; ++k) {
        sc::SimScan scan;
        REQUIRE(gen.generate(k, scan) == mptrack::Status::kOk);
        for (const auto& m : scan.measurements) {
          if (m.origin.kind != sc::OriginKind::kClutter) continue;
          const double x = std::pow(m.amplitude, 2.0 * b) - d2b;
          below += m.amplitude < s.threshold ? 1.0 : 0.0;
          sum += x;
          sum2 += x * x;
          total += 1.0;
        }
      }
    }
    const double mean = sum / total;
    CHECK(below == 0.0);
    CHECK(total > 15000.0);
    CHECK(mean == doctest::Approx(sigma0).epsilon(4.0 / std::sqrt(total)));
    CHECK(sum2 / total - mean * mean == doctest::Approx(sigma0 * sigma0).epsilon(0.06));
  }
}

TEST_CASE("seed001: targets are detected with P_D = exp(-d^2 / 101) = 0.9775 (20 dB, Swerling I)") {
  const sc::ScenarioSpec s = seed001(1);
  double detected = 0.0, alive = 0.0;
  for (std::uint32_t run = 0; run < 20; ++run) {
    sc::Generator gen;
    REQUIRE(gen.init(s, 9, run) == mptrack::Status::kOk);
    for (std::uint32_t k = 1; k <= s.num_scans; ++k) {
      sc::SimScan scan;
      REQUIRE(gen.generate(k, scan) == mptrack::Status::kOk);
      for (const auto& t : scan.truth) {
        detected += t.detected ? 1.0 : 0.0;
        alive += 1.0;
      }
    }
  }
  // 20 runs x 409 target-scans: std of the rate ~ 0.0016.
  CHECK(detected / alive == doctest::Approx(0.977460).epsilon(0.007));
}
