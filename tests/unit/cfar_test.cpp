// CFAR detector: thresholds against closed forms, Pfa measured on noise.
#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

#include "alloc_guard.h"
#include "mptrack/frontend/cfar.h"

namespace fe = mptrack::frontend;
using mptrack::Status;

namespace {

fe::CfarParams params(fe::CfarType type, double pfa, std::size_t guard = 2,
                      std::size_t train = 8) {
  fe::CfarParams p;
  p.type = type;
  p.pfa = pfa;
  p.guard_cells = guard;
  p.training_cells = train;
  p.edge = fe::CfarEdge::kSkip;
  return p;
}

// Measured false-alarm rate on n cells of unit exponential noise (|CN(0,1)|^2).
double measured_pfa(const fe::Cfar& cfar, std::size_t n, unsigned seed, std::size_t& tested) {
  std::mt19937_64 rng(seed);
  std::exponential_distribution<float> expo(1.0f);
  std::vector<float> line(n);
  for (float& x : line) x = expo(rng);
  std::size_t hits = 0;
  tested = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const fe::CfarResult r = cfar.test(line.data(), n, i);
    if (!r.tested) continue;
    ++tested;
    if (r.detected) ++hits;
  }
  return static_cast<double>(hits) / static_cast<double>(tested);
}

}  // namespace

TEST_CASE("cfar CA threshold equals the closed form N (Pfa^(-1/N) - 1)") {
  fe::Cfar cfar;
  for (double pfa : {1e-2, 1e-4, 1e-6}) {
    REQUIRE(cfar.init(params(fe::CfarType::kCellAveraging, pfa)) == Status::kOk);
    const double expected = 16.0 * (std::pow(pfa, -1.0 / 16.0) - 1.0);
    CHECK(cfar.alpha() == doctest::Approx(expected).epsilon(1e-12));
  }
}

TEST_CASE("cfar SO with one cell per side: Pfa = 2 / (2 + alpha) (min of two Exp(1) is Exp(2))") {
  CHECK(fe::cfar_pfa(fe::CfarType::kSmallestOf, 1, 0, 3.0) == doctest::Approx(0.4));
  fe::Cfar cfar;
  REQUIRE(cfar.init(params(fe::CfarType::kSmallestOf, 0.01, 0, 1)) == Status::kOk);
  CHECK(cfar.alpha() == doctest::Approx(198.0).epsilon(1e-12));  // 2/(2+a) = 0.01
}

TEST_CASE("cfar GO + SO false-alarm probabilities sum to twice the one-sided CA value") {
  // P(Z > t max(X,Y)) + P(Z > t min(X,Y)) = P(Z > tX) + P(Z > tY) = 2 (1 + t)^-n.
  for (double a : {0.5, 2.0, 7.0}) {
    const std::size_t n = 8;
    const double t = a / static_cast<double>(n);
    const double sum = fe::cfar_pfa(fe::CfarType::kGreatestOf, n, 0, a) +
                       fe::cfar_pfa(fe::CfarType::kSmallestOf, n, 0, a);
    CHECK(sum == doctest::Approx(2.0 * std::pow(1.0 + t, -8.0)).epsilon(1e-12));
  }
}

TEST_CASE("cfar OS with k = 2T (the maximum) matches prod (N-i)/(N-i+t)") {
  // N = 2: k = 2, c_k = 1/1 + 1/2 = 1.5; t = alpha / 1.5; Pfa = 2/(2+t) * 1/(1+t).
  const double alpha = 3.0;
  const double t = alpha / 1.5;
  CHECK(fe::cfar_pfa(fe::CfarType::kOrderedStatistic, 1, 2, alpha) ==
        doctest::Approx(2.0 / (2.0 + t) / (1.0 + t)));
}

TEST_CASE("cfar measured Pfa on exponential noise matches the design Pfa for every variant") {
  // 400k cells at Pfa 1e-3: ~400 expected hits, binomial sd 20; tolerance 20% (4 sd).
  for (fe::CfarType type : {fe::CfarType::kCellAveraging, fe::CfarType::kGreatestOf,
                            fe::CfarType::kSmallestOf, fe::CfarType::kOrderedStatistic}) {
    fe::Cfar cfar;
    REQUIRE(cfar.init(params(type, 1e-3)) == Status::kOk);
    std::size_t tested = 0;
    const double pfa = measured_pfa(cfar, 400000, 17u + static_cast<unsigned>(type), tested);
    CHECK(tested == 400000 - 2 * 10);
    CHECK(pfa == doctest::Approx(1e-3).epsilon(0.2));
  }
}

TEST_CASE("cfar ordered statistic default rank is 3/4 of 2T and its noise estimate is unbiased") {
  fe::Cfar cfar;
  REQUIRE(cfar.init(params(fe::CfarType::kOrderedStatistic, 1e-3)) == Status::kOk);
  CHECK(cfar.params().os_rank == 12);
  // Mean of z over many cells of Exp(1) noise -> 1.
  std::mt19937_64 rng(5);
  std::exponential_distribution<float> expo(1.0f);
  std::vector<float> line(50000);
  for (float& x : line) x = expo(rng);
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const fe::CfarResult r = cfar.test(line.data(), line.size(), i);
    if (!r.tested) continue;
    sum += static_cast<double>(r.noise);
    ++n;
  }
  CHECK(sum / static_cast<double>(n) == doctest::Approx(1.0).epsilon(0.02));
}

TEST_CASE("cfar edges: skip leaves edge cells untested, shift and wrap use 2T cells") {
  // Line 0..20 of powers equal to the index; G = 1, T = 2, CA.
  std::vector<float> line(21);
  for (std::size_t i = 0; i < line.size(); ++i) line[i] = static_cast<float>(i);
  fe::CfarParams p = params(fe::CfarType::kCellAveraging, 1e-2, 1, 2);
  fe::Cfar cfar;
  REQUIRE(cfar.init(p) == Status::kOk);
  CHECK_FALSE(cfar.test(line.data(), 21, 2).tested);
  CHECK(cfar.test(line.data(), 21, 3).tested);
  CHECK(cfar.test(line.data(), 21, 3).noise == doctest::Approx((0 + 1 + 5 + 6) / 4.0));
  CHECK_FALSE(cfar.test(line.data(), 21, 18).tested);

  p.edge = fe::CfarEdge::kShift;
  REQUIRE(cfar.init(p) == Status::kOk);
  // Cell 0: no left cells; right run extends to 4 cells: 2, 3, 4, 5.
  CHECK(cfar.test(line.data(), 21, 0).noise == doctest::Approx((2 + 3 + 4 + 5) / 4.0));
  // Cell 2: left has cell 0 only; right 4, 5, 6.
  CHECK(cfar.test(line.data(), 21, 2).noise == doctest::Approx((0 + 4 + 5 + 6) / 4.0));
  // Cell 20: left run 15, 16, 17, 18.
  CHECK(cfar.test(line.data(), 21, 20).noise == doctest::Approx((15 + 16 + 17 + 18) / 4.0));

  p.edge = fe::CfarEdge::kWrap;
  REQUIRE(cfar.init(p) == Status::kOk);
  // Cell 0: left 18, 19 (wrapped), right 2, 3.
  CHECK(cfar.test(line.data(), 21, 0).noise == doctest::Approx((18 + 19 + 2 + 3) / 4.0));
}

TEST_CASE("cfar detects a strong cell in noise and GO/SO split the window into halves") {
  std::vector<float> line(41, 1.0f);
  for (std::size_t i = 0; i < 20; ++i) line[i] = 4.0f;  // clutter edge left of cell 20
  line[20] = 30.0f;
  fe::Cfar go;
  fe::Cfar so;
  REQUIRE(go.init(params(fe::CfarType::kGreatestOf, 1e-3, 1, 4)) == Status::kOk);
  REQUIRE(so.init(params(fe::CfarType::kSmallestOf, 1e-3, 1, 4)) == Status::kOk);
  CHECK(go.test(line.data(), 41, 20).noise == 4.0f);
  CHECK(so.test(line.data(), 41, 20).noise == 1.0f);
  CHECK(so.test(line.data(), 41, 20).detected);
}

TEST_CASE("cfar init rejects invalid parameters") {
  fe::Cfar cfar;
  fe::CfarParams p;
  p.training_cells = 0;
  CHECK(cfar.init(p) == Status::kInvalidArgument);
  p = fe::CfarParams{};
  p.pfa = 0.0;
  CHECK(cfar.init(p) == Status::kInvalidArgument);
  p.pfa = 0.7;
  CHECK(cfar.init(p) == Status::kInvalidArgument);
  p = fe::CfarParams{};
  p.os_rank = 17;  // > 2T = 16
  CHECK(cfar.init(p) == Status::kInvalidArgument);
  p = fe::CfarParams{};
  p.type = static_cast<fe::CfarType>(9);
  CHECK(cfar.init(p) == Status::kInvalidArgument);
}

TEST_CASE("cfar test does not allocate (OS uses in-object scratch)") {
  fe::Cfar cfar;
  REQUIRE(cfar.init(params(fe::CfarType::kOrderedStatistic, 1e-4)) == Status::kOk);
  std::vector<float> line(256, 1.0f);
  line[100] = 1000.0f;
  mptrack::test::NoAllocScope guard;
  const fe::CfarResult r = cfar.test(line.data(), line.size(), 100);
  CHECK(guard.allocations() == 0);
  CHECK(r.detected);
}
