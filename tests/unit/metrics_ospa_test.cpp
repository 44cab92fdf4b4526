#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "alloc_guard.h"
#include "mptrack/metrics/ospa.h"

using mptrack::MetricParams;
using mptrack::OspaMetric;
using mptrack::OspaResult;
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

// Independent OSPA: the definition of Schuhmacher et al. (2008) evaluated by
// enumerating every injection of the smaller set into the larger one, with
// std::pow (test code may use libm).
double brute_force_ospa(const std::vector<P2>& x, const std::vector<P2>& y, double c, double p) {
  const std::vector<P2>& small = x.size() <= y.size() ? x : y;
  const std::vector<P2>& large = x.size() <= y.size() ? y : x;
  const std::size_t m = small.size();
  const std::size_t n = large.size();
  if (n == 0) return 0.0;
  std::vector<std::size_t> perm(n);
  for (std::size_t j = 0; j < n; ++j) perm[j] = j;
  double best = std::numeric_limits<double>::infinity();
  do {
    double s = 0.0;
    for (std::size_t i = 0; i < m; ++i) {
      s += std::pow(std::min(c, (small[i] - large[perm[i]]).norm()), p);
    }
    best = std::min(best, s);
  } while (std::next_permutation(perm.begin(), perm.end()));
  return std::pow((best + std::pow(c, p) * static_cast<double>(n - m)) / static_cast<double>(n),
                  1.0 / p);
}

template <std::size_t N>
OspaResult<double> ospa(OspaMetric<double, N>& metric, const std::vector<P2>& x,
                        const std::vector<P2>& y) {
  OspaResult<double> r;
  CHECK(metric.compute(x.data(), x.size(), y.data(), y.size(), r) == Status::kOk);
  return r;
}

}  // namespace

TEST_CASE("OSPA of one truth and one estimate at distance 3 (c = 10) is 3") {
  OspaMetric<double, 4> m;
  REQUIRE(m.init(MetricParams<double>{2.0, 10.0}) == Status::kOk);
  const auto r = ospa(m, {P2(1, 1)}, {P2(4, 1)});
  CHECK(r.total == 3.0);
  CHECK(r.localisation == 3.0);
  CHECK(r.cardinality == 0.0);
}

TEST_CASE("OSPA is c when exactly one set is empty and 0 when both are") {
  OspaMetric<float, 4> m;
  REQUIRE(m.init(MetricParams<float>{2.0f, 10.0f}) == Status::kOk);
  const Eigen::Vector2f one(5.0f, -2.0f);
  OspaResult<float> r;
  REQUIRE(m.compute(&one, 1, nullptr, 0, r) == Status::kOk);
  CHECK(r.total == 10.0f);
  CHECK(r.cardinality == 10.0f);
  CHECK(r.localisation == 0.0f);
  REQUIRE(m.compute(nullptr, 0, &one, 1, r) == Status::kOk);
  CHECK(r.total == 10.0f);
  REQUIRE(m.compute(nullptr, 0, nullptr, 0, r) == Status::kOk);
  CHECK(r.total == 0.0f);
  CHECK(r.localisation == 0.0f);
  CHECK(r.cardinality == 0.0f);
}

TEST_CASE("OSPA of two truths and one estimate splits into localisation and cardinality") {
  // d = 5 to the near truth; n = 2, m = 1:
  // total = sqrt((25 + 100) / 2) = sqrt(62.5), loc = sqrt(12.5), card = sqrt(50).
  OspaMetric<double, 4> m;
  REQUIRE(m.init(MetricParams<double>{2.0, 10.0}) == Status::kOk);
  const auto r = ospa(m, {P2(0, 0), P2(100, 0)}, {P2(3, 4)});
  CHECK(r.total == doctest::Approx(std::sqrt(62.5)).epsilon(1e-15));
  CHECK(r.localisation == doctest::Approx(std::sqrt(12.5)).epsilon(1e-15));
  CHECK(r.cardinality == doctest::Approx(std::sqrt(50.0)).epsilon(1e-15));
  CHECK(r.total * r.total ==
        doctest::Approx(r.localisation * r.localisation + r.cardinality * r.cardinality));
  CHECK(m.matching().truth_to_estimate(0) == 0);
  CHECK(m.matching().truth_to_estimate(1) == -1);
}

TEST_CASE("OSPA caps a far pair at c and the matching reports it outside the cutoff") {
  OspaMetric<double, 4> m;
  REQUIRE(m.init(MetricParams<double>{2.0, 10.0}) == Status::kOk);
  const auto r = ospa(m, {P2(0, 0)}, {P2(20, 0)});
  CHECK(r.total == 10.0);
  const auto& match = m.matching();
  CHECK(match.truth_to_estimate(0) == 0);  // assigned ...
  CHECK_FALSE(match.truth_within_cutoff(0));  // ... but not within c
  CHECK_FALSE(match.estimate_within_cutoff(0));
  CHECK(match.truth_distance(0) == 20.0);
  CHECK(match.num_within_cutoff() == 0);
}

TEST_CASE("OSPA with p = 1 uses the optimal, not the greedy, assignment") {
  // Greedy from truth 0 would take estimate 0 (d = 1) and leave truth 1 with
  // estimate 1 (d = 5): (1 + 5) / 2 = 3. Optimal: truth0-est1 (d = 2) and
  // truth1-est0 (d = 2): (2 + 2) / 2 = 2.
  OspaMetric<double, 4> m;
  REQUIRE(m.init(MetricParams<double>{1.0, 10.0}) == Status::kOk);
  const auto r = ospa(m, {P2(0, 0), P2(3, 0)}, {P2(1, 0), P2(-2, 0)});
  CHECK(r.total == doctest::Approx(2.0).epsilon(1e-15));
  CHECK(m.matching().truth_to_estimate(0) == 1);
  CHECK(m.matching().truth_to_estimate(1) == 0);
}

TEST_CASE("OSPA with p = 3 (dmath path) matches the closed form") {
  // One pair at d = 2 and one missing: ((8 + 1000) / 2)^(1/3) = 504^(1/3).
  OspaMetric<double, 4> m;
  REQUIRE(m.init(MetricParams<double>{3.0, 10.0}) == Status::kOk);
  const auto r = ospa(m, {P2(0, 0), P2(50, 50)}, {P2(0, 2)});
  CHECK(r.total == doctest::Approx(std::cbrt(504.0)).epsilon(1e-12));
  CHECK(r.localisation == doctest::Approx(std::cbrt(4.0)).epsilon(1e-12));
  CHECK(r.cardinality == doctest::Approx(std::cbrt(500.0)).epsilon(1e-12));
}

TEST_CASE("OSPA equals the brute-force definition on random small sets") {
  auto m = std::make_unique<OspaMetric<double, 6>>();
  Lcg rng{2024u};
  for (const double p : {1.0, 2.0, 2.5}) {
    REQUIRE(m->init(MetricParams<double>{p, 10.0}) == Status::kOk);
    for (int trial = 0; trial < 60; ++trial) {
      const auto x = random_set(rng, static_cast<std::size_t>(trial % 6), 30.0);
      const auto y = random_set(rng, static_cast<std::size_t>((trial / 6) % 7), 30.0);
      CHECK(ospa(*m, x, y).total == doctest::Approx(brute_force_ospa(x, y, 10.0, p)).epsilon(1e-9));
    }
  }
}

TEST_CASE("OSPA is symmetric and zero on identical sets") {
  auto m = std::make_unique<OspaMetric<double, 8>>();
  REQUIRE(m->init(MetricParams<double>{2.0, 10.0}) == Status::kOk);
  Lcg rng{31337u};
  for (int trial = 0; trial < 50; ++trial) {
    const auto x = random_set(rng, static_cast<std::size_t>(trial % 8), 25.0);
    const auto y = random_set(rng, static_cast<std::size_t>((trial * 3) % 9), 25.0);
    CHECK(ospa(*m, x, y).total == doctest::Approx(ospa(*m, y, x).total).epsilon(1e-12));
    CHECK(ospa(*m, x, x).total == 0.0);
  }
}

TEST_CASE("OSPA satisfies the triangle inequality on random small sets") {
  auto m = std::make_unique<OspaMetric<double, 6>>();
  Lcg rng{5u};
  for (const double p : {1.0, 2.0}) {
    REQUIRE(m->init(MetricParams<double>{p, 10.0}) == Status::kOk);
    for (int trial = 0; trial < 200; ++trial) {
      const auto x = random_set(rng, static_cast<std::size_t>(trial % 5), 20.0);
      const auto y = random_set(rng, static_cast<std::size_t>((trial / 5) % 6), 20.0);
      const auto z = random_set(rng, static_cast<std::size_t>((trial / 3) % 4), 20.0);
      const double xz = ospa(*m, x, z).total;
      const double xy = ospa(*m, x, y).total;
      const double yz = ospa(*m, y, z).total;
      CHECK(xz <= xy + yz + 1e-9);
    }
  }
}

TEST_CASE("OSPA matching exposes assignments and false tracks for the harness") {
  // Truth 0 has track 1 nearby, truth 1 has track 2 nearby, track 0 is far
  // from everything: it is the one false track (NFT = 1).
  OspaMetric<double, 4> m;
  REQUIRE(m.init(MetricParams<double>{2.0, 10.0}) == Status::kOk);
  (void)ospa(m, {P2(0, 0), P2(30, 0)}, {P2(200, 200), P2(1, 0), P2(30, 2)});
  const auto& match = m.matching();
  CHECK(match.num_truths() == 2);
  CHECK(match.num_estimates() == 3);
  CHECK(match.truth_to_estimate(0) == 1);
  CHECK(match.truth_to_estimate(1) == 2);
  CHECK(match.estimate_to_truth(0) == -1);
  CHECK(match.estimate_to_truth(1) == 0);
  CHECK(match.estimate_to_truth(2) == 1);
  CHECK_FALSE(match.estimate_within_cutoff(0));
  CHECK(match.estimate_within_cutoff(1));
  CHECK(match.estimate_within_cutoff(2));
  CHECK(match.truth_distance(1) == 2.0);
  CHECK(match.num_within_cutoff() == 2);
}

TEST_CASE("OSPA rejects bad parameters and bad input") {
  OspaMetric<float, 2> m;
  OspaResult<float> r;
  const Eigen::Vector2f pts[3] = {Eigen::Vector2f(0, 0), Eigen::Vector2f(1, 1), Eigen::Vector2f(2, 2)};
  CHECK(m.compute(pts, 1, pts, 1, r) == Status::kNotInitialized);
  CHECK(m.init(MetricParams<float>{0.5f, 10.0f}) == Status::kInvalidArgument);
  CHECK(m.init(MetricParams<float>{2.0f, 0.0f}) == Status::kInvalidArgument);
  CHECK(m.init(MetricParams<float>{2.0f, std::numeric_limits<float>::infinity()}) ==
        Status::kInvalidArgument);
  CHECK(m.init(MetricParams<float>{40.0f, 631.0f}) == Status::kInvalidArgument);  // c^p overflows
  REQUIRE(m.init(MetricParams<float>{2.0f, 631.0f}) == Status::kOk);
  CHECK(m.compute(pts, 3, pts, 1, r) == Status::kCapacityExceeded);
  CHECK(m.compute(nullptr, 1, pts, 1, r) == Status::kInvalidArgument);
  const Eigen::Vector2f bad(std::numeric_limits<float>::quiet_NaN(), 0.0f);
  CHECK(m.compute(&bad, 1, pts, 1, r) == Status::kInvalidInput);
  CHECK(r.total == 0.0f);
  CHECK(m.matching().num_truths() == 0);
}

TEST_CASE("OSPA with 64 points allocates nothing") {
  using Metric = OspaMetric<float, 64>;
  auto m = std::make_unique<Metric>();
  REQUIRE(m->init(MetricParams<float>{2.0f, 10.0f}) == Status::kOk);
  std::vector<Eigen::Vector2f> x(64), y(60);
  Lcg rng{8u};
  for (auto& p : x) p = Eigen::Vector2f(static_cast<float>(100.0 * rng.next()), static_cast<float>(100.0 * rng.next()));
  for (auto& p : y) p = Eigen::Vector2f(static_cast<float>(100.0 * rng.next()), static_cast<float>(100.0 * rng.next()));
  OspaResult<float> r;
  Status st = Status::kOk;
  {
    mptrack::test::NoAllocScope guard;
    st = m->compute(x.data(), x.size(), y.data(), y.size(), r);
    CHECK(guard.allocations() == 0);
  }
  CHECK(st == Status::kOk);
  // 4 unmatched truths alone contribute c^2 * 4 / 64, so total >= sqrt(6.25).
  CHECK(r.total >= 2.5f);
  CHECK(r.total <= 10.0f);
}
