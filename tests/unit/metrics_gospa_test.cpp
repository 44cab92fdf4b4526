#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "alloc_guard.h"
#include "mptrack/metrics/gospa.h"

using mptrack::GospaMetric;
using mptrack::GospaResult;
using mptrack::MetricParams;
using mptrack::Status;

namespace {

using P2 = Eigen::Matrix<double, 2, 1>;

struct Lcg {
  std::uint32_t state;
  double next() {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / 16777216.0;
  }
};

std::vector<P2> random_set(Lcg& rng, std::size_t n, double extent) {
  std::vector<P2> s(n);
  for (auto& p : s) p = P2(extent * rng.next(), extent * rng.next());
  return s;
}

// Independent GOSPA (alpha = 2): minimum over every *partial* assignment
// gamma (each truth either unmatched or matched to a distinct estimate, any
// distance allowed) of sum_gamma d^p + c^p/2 (|X| + |Y| - 2|gamma|), by
// recursion; Rahmathullah et al. (2017) eq. (2) as written. Note: a pair at
// d > c is allowed here, so the cap at c is *not* built in.
double brute_partial(const std::vector<P2>& x, const std::vector<P2>& y, std::size_t i,
                     std::vector<bool>& used, double c, double p) {
  const double half = std::pow(c, p) / 2.0;
  if (i == x.size()) {
    std::size_t unused = 0;
    for (bool u : used) unused += u ? 0u : 1u;
    return half * static_cast<double>(unused);
  }
  double best = half + brute_partial(x, y, i + 1, used, c, p);  // truth i missed
  for (std::size_t j = 0; j < y.size(); ++j) {
    if (used[j]) continue;
    used[j] = true;
    best = std::min(best, std::pow((x[i] - y[j]).norm(), p) + brute_partial(x, y, i + 1, used, c, p));
    used[j] = false;
  }
  return best;
}

double brute_force_gospa(const std::vector<P2>& x, const std::vector<P2>& y, double c, double p) {
  std::vector<bool> used(y.size(), false);
  return std::pow(brute_partial(x, y, 0, used, c, p), 1.0 / p);
}

template <std::size_t N>
GospaResult<double> gospa(GospaMetric<double, N>& metric, const std::vector<P2>& x,
                          const std::vector<P2>& y) {
  GospaResult<double> r;
  CHECK(metric.compute(x.data(), x.size(), y.data(), y.size(), r) == Status::kOk);
  return r;
}

}  // namespace

TEST_CASE("GOSPA of one truth and one estimate at distance 3 (c = 10) is 3") {
  GospaMetric<double, 4> m;
  REQUIRE(m.init(MetricParams<double>{2.0, 10.0}) == Status::kOk);
  const auto r = gospa(m, {P2(0, 0)}, {P2(0, 3)});
  CHECK(r.total == 3.0);
  CHECK(r.localisation_pow == 9.0);
  CHECK(r.missed_pow == 0.0);
  CHECK(r.false_pow == 0.0);
  CHECK(r.num_matched == 1);
}

TEST_CASE("GOSPA charges c^p/2 per missed truth and per false estimate") {
  GospaMetric<double, 4> m;
  REQUIRE(m.init(MetricParams<double>{2.0, 10.0}) == Status::kOk);
  // One truth, no estimate: sqrt(100 / 2).
  auto r = gospa(m, {P2(0, 0)}, {});
  CHECK(r.total == doctest::Approx(std::sqrt(50.0)).epsilon(1e-15));
  CHECK(r.num_missed == 1);
  CHECK(r.missed_pow == 50.0);
  CHECK(r.num_false == 0);
  // No truth, two estimates: sqrt(2 * 50).
  r = gospa(m, {}, {P2(0, 0), P2(5, 5)});
  CHECK(r.total == doctest::Approx(10.0).epsilon(1e-15));
  CHECK(r.num_false == 2);
  CHECK(r.false_pow == 100.0);
  // Both empty.
  r = gospa(m, {}, {});
  CHECK(r.total == 0.0);
}

TEST_CASE("GOSPA of two truths and one estimate: one matched, one missed") {
  // d = 5 to the near truth: 25 + 50 = 75.
  GospaMetric<double, 4> m;
  REQUIRE(m.init(MetricParams<double>{2.0, 10.0}) == Status::kOk);
  const auto r = gospa(m, {P2(0, 0), P2(100, 0)}, {P2(3, 4)});
  CHECK(r.total == doctest::Approx(std::sqrt(75.0)).epsilon(1e-15));
  CHECK(r.localisation_pow == doctest::Approx(25.0).epsilon(1e-15));
  CHECK(r.num_matched == 1);
  CHECK(r.num_missed == 1);
  CHECK(r.num_false == 0);
}

TEST_CASE("GOSPA counts a pair beyond c as one missed plus one false target") {
  GospaMetric<double, 4> m;
  REQUIRE(m.init(MetricParams<double>{2.0, 10.0}) == Status::kOk);
  const auto r = gospa(m, {P2(0, 0)}, {P2(20, 0)});
  CHECK(r.total == doctest::Approx(10.0).epsilon(1e-15));
  CHECK(r.num_matched == 0);
  CHECK(r.num_missed == 1);
  CHECK(r.num_false == 1);
  CHECK(r.localisation_pow == 0.0);
}

TEST_CASE("GOSPA equals the brute-force partial-assignment definition on random sets") {
  auto m = std::make_unique<GospaMetric<double, 6>>();
  Lcg rng{99u};
  for (const double p : {1.0, 2.0, 3.0}) {
    REQUIRE(m->init(MetricParams<double>{p, 8.0}) == Status::kOk);
    for (int trial = 0; trial < 60; ++trial) {
      const auto x = random_set(rng, static_cast<std::size_t>(trial % 6), 25.0);
      const auto y = random_set(rng, static_cast<std::size_t>((trial / 6) % 7), 25.0);
      const auto r = gospa(*m, x, y);
      CHECK(r.total == doctest::Approx(brute_force_gospa(x, y, 8.0, p)).epsilon(1e-9));
      CHECK(r.num_missed + r.num_matched == x.size());
      CHECK(r.num_false + r.num_matched == y.size());
      CHECK(std::pow(r.total, p) ==
            doctest::Approx(r.localisation_pow + r.missed_pow + r.false_pow).epsilon(1e-9));
    }
  }
}

TEST_CASE("GOSPA is symmetric with missed and false swapped") {
  auto m = std::make_unique<GospaMetric<double, 8>>();
  REQUIRE(m->init(MetricParams<double>{2.0, 10.0}) == Status::kOk);
  Lcg rng{17u};
  for (int trial = 0; trial < 40; ++trial) {
    const auto x = random_set(rng, static_cast<std::size_t>(trial % 8), 30.0);
    const auto y = random_set(rng, static_cast<std::size_t>((trial * 5) % 9), 30.0);
    const auto a = gospa(*m, x, y);
    const auto b = gospa(*m, y, x);
    CHECK(a.total == doctest::Approx(b.total).epsilon(1e-12));
    CHECK(a.num_missed == b.num_false);
    CHECK(a.num_false == b.num_missed);
  }
}

TEST_CASE("GOSPA satisfies the triangle inequality on random small sets") {
  auto m = std::make_unique<GospaMetric<double, 6>>();
  REQUIRE(m->init(MetricParams<double>{2.0, 10.0}) == Status::kOk);
  Lcg rng{123u};
  for (int trial = 0; trial < 200; ++trial) {
    const auto x = random_set(rng, static_cast<std::size_t>(trial % 5), 20.0);
    const auto y = random_set(rng, static_cast<std::size_t>((trial / 5) % 6), 20.0);
    const auto z = random_set(rng, static_cast<std::size_t>((trial / 3) % 4), 20.0);
    CHECK(gospa(*m, x, z).total <= gospa(*m, x, y).total + gospa(*m, y, z).total + 1e-9);
  }
}

TEST_CASE("GOSPA with 64 points allocates nothing") {
  auto m = std::make_unique<GospaMetric<float, 64>>();
  REQUIRE(m->init(MetricParams<float>{2.0f, 10.0f}) == Status::kOk);
  std::vector<Eigen::Vector2f> x(64), y(64);
  Lcg rng{3u};
  for (std::size_t i = 0; i < 64; ++i) {
    x[i] = Eigen::Vector2f(static_cast<float>(500.0 * rng.next()), static_cast<float>(500.0 * rng.next()));
    // Every estimate 1 m east of its truth: all matched, total = sqrt(64 * 1) = 8.
    y[i] = x[i] + Eigen::Vector2f(1.0f, 0.0f);
  }
  GospaResult<float> r;
  Status st = Status::kOk;
  {
    mptrack::test::NoAllocScope guard;
    st = m->compute(x.data(), x.size(), y.data(), y.size(), r);
    CHECK(guard.allocations() == 0);
  }
  CHECK(st == Status::kOk);
  CHECK(r.num_matched == 64);
  CHECK(r.total == doctest::Approx(8.0).epsilon(1e-4));
}
