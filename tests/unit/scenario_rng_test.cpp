// Deterministic RNG of the scenario generator: sample moments against the
// exact ones (fixed seed, tolerances of about 5 standard errors).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>

#include "mptrack/scenario/rng.h"

using mptrack::scenario::Rng;

namespace {

struct Moments {
  double mean = 0.0;
  double var = 0.0;
};

template <class Draw>
Moments moments(int n, Draw draw) {
  double s = 0.0, s2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const double x = draw();
    s += x;
    s2 += x * x;
  }
  const double m = s / n;
  return {m, s2 / n - m * m};
}

constexpr int kN = 200000;

}  // namespace

TEST_CASE("rng: the same seed gives the same stream, another seed a different one") {
  Rng a(42), b(42), c(43);
  bool all_equal = true;
  bool any_equal_c = false;
  for (int i = 0; i < 1000; ++i) {
    const std::uint64_t x = a.next();
    all_equal = all_equal && x == b.next();
    any_equal_c = any_equal_c || x == c.next();
  }
  CHECK(all_equal);
  CHECK_FALSE(any_equal_c);
}

TEST_CASE("rng: uniform has mean 1/2 and variance 1/12 and stays in [0, 1)") {
  Rng r(1);
  bool in_range = true;
  const Moments m = moments(kN, [&] {
    const double u = r.uniform();
    in_range = in_range && u >= 0.0 && u < 1.0;
    return u;
  });
  CHECK(in_range);
  CHECK(std::fabs(m.mean - 0.5) < 5.0 * std::sqrt(1.0 / 12.0 / kN));
  CHECK(std::fabs(m.var - 1.0 / 12.0) < 0.002);
}

TEST_CASE("rng: below(bound) is uniform over 0..bound-1") {
  Rng r(7);
  int counts[5] = {0, 0, 0, 0, 0};
  for (int i = 0; i < 50000; ++i) ++counts[r.below(5)];
  for (int c : counts) CHECK(std::abs(c - 10000) < 5 * 90);  // sd = sqrt(50000 * 0.2 * 0.8) = 89
  CHECK(r.below(1) == 0);
}

TEST_CASE("rng: normal has mean 0 and variance 1") {
  Rng r(2);
  const Moments m = moments(kN, [&] { return r.normal(); });
  CHECK(std::fabs(m.mean) < 5.0 / std::sqrt(kN));
  CHECK(std::fabs(m.var - 1.0) < 5.0 * std::sqrt(2.0 / kN));
}

TEST_CASE("rng: exponential has mean 1 and variance 1") {
  Rng r(3);
  const Moments m = moments(kN, [&] { return r.exponential(); });
  CHECK(std::fabs(m.mean - 1.0) < 5.0 / std::sqrt(kN));
  CHECK(std::fabs(m.var - 1.0) < 0.03);
}

TEST_CASE("rng: Poisson mean and variance equal lambda, below and above the 30 chunk") {
  for (double lambda : {0.7, 4.0, 45.0, 135.0}) {
    Rng r(4);
    const int n = 40000;
    const Moments m = moments(n, [&] { return static_cast<double>(r.poisson(lambda)); });
    CAPTURE(lambda);
    CHECK(std::fabs(m.mean - lambda) < 5.0 * std::sqrt(lambda / n));
    CHECK(std::fabs(m.var / lambda - 1.0) < 0.04);
  }
  Rng r(5);
  CHECK(r.poisson(0.0) == 0);
}

TEST_CASE("rng: Gamma(n, scale) power has mean n*scale (Swerling I: 1 + snr)") {
  // Swerling I, snr 10/3: u ~ Gamma(1, 1 + snr), E[u] = 1 + snr = 4.333
  // (docs/algorithms/models.md §Detection probability).
  Rng r(6);
  const double vs = 1.0 + 10.0 / 3.0;
  const Moments m1 = moments(kN, [&] { return r.gamma_int(1, vs); });
  CHECK(std::fabs(m1.mean - vs) < 5.0 * vs / std::sqrt(kN));
  CHECK(std::fabs(m1.var / (vs * vs) - 1.0) < 0.03);
  // Swerling III: Gamma(2, vs/2): mean vs, variance vs^2 / 2.
  const Moments m3 = moments(kN, [&] { return r.gamma_int(2, vs / 2.0); });
  CHECK(std::fabs(m3.mean - vs) < 5.0 * vs / std::sqrt(2.0 * kN));
  CHECK(std::fabs(m3.var / (vs * vs / 2.0) - 1.0) < 0.03);
}

TEST_CASE("rng: detection rates of thresholded power equal the exact Pd (docs/algorithms/models.md)") {
  const double d2 = 0.715 * 0.715;
  const double vs = 1.0 + 10.0 / 3.0;
  Rng r(8);
  int hits1 = 0, hits3 = 0;
  for (int i = 0; i < kN; ++i) {
    if (r.gamma_int(1, vs) > d2) ++hits1;
    if (r.gamma_int(2, vs / 2.0) > d2) ++hits3;
  }
  // Exact Pd (docs/algorithms/models.md §Detection probability): 0.889 (Swerling I,
  // snr 10/3) and 0.976 (Swerling III).
  const double pd1 = std::exp(-d2 / vs);
  const double x = 2.0 * d2 / vs;
  const double pd3 = std::exp(-x) * (1.0 + x);
  CHECK(pd1 == doctest::Approx(0.889).epsilon(0.001));
  CHECK(pd3 == doctest::Approx(0.976).epsilon(0.001));
  CHECK(std::fabs(hits1 / static_cast<double>(kN) - pd1) < 5.0 * std::sqrt(pd1 * (1 - pd1) / kN));
  CHECK(std::fabs(hits3 / static_cast<double>(kN) - pd3) < 5.0 * std::sqrt(pd3 * (1 - pd3) / kN));
}

TEST_CASE("rng: truncated Gamma draws exceed t and have the exact conditional mean") {
  const double t = 0.715 * 0.715;
  const double scale1 = 2.0;  // uniform clutter, cnr 1: Gamma(1, 2)
  Rng r(9);
  bool above = true;
  const Moments m1 = moments(kN, [&] {
    const double u = r.gamma_int_above(1, scale1, t);
    above = above && u > t;
    return u;
  });
  CHECK(above);
  // Memoryless: E[u | u > t] = t + scale.
  CHECK(std::fabs(m1.mean - (t + scale1)) < 5.0 * scale1 / std::sqrt(kN));
  // Gamma(2, th) | > t: E = (t^2 + 2 t th + 2 th^2) / (t + th) (integrate x^2 e^-x/th over x > t).
  const double th = (1.0 + 20.0 / 3.0) / 2.0;
  const Moments m3 = moments(kN, [&] { return r.gamma_int_above(2, th, t); });
  const double expect = (t * t + 2.0 * t * th + 2.0 * th * th) / (t + th);
  CHECK(std::fabs(m3.mean - expect) < 5.0 * std::sqrt(m3.var / kN));
}
