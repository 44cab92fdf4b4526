// IGGM building blocks (model/amplitude_iggm.h, model/inverse_gamma*.h,
// phd/cardinality.h, rfs/mixture.h):
// values checked against closed forms derived by hand in the comments.
#include <doctest/doctest.h>

#include <cmath>

#include "mptrack/phd/cardinality.h"
#include "mptrack/model/amplitude_iggm.h"
#include "mptrack/model/inverse_gamma.h"
#include "mptrack/model/inverse_gamma_merge.h"
#include "mptrack/rfs/mixture.h"

using namespace mptrack;
using namespace mptrack::model;
using namespace mptrack::phd;
using namespace mptrack::rfs;

TEST_CASE("trigamma matches pi^2/6 at 1 and the recurrence at 0.5") {
  CHECK(trigamma(1.0) == doctest::Approx(1.6449340668482264).epsilon(1e-8));
  // psi'(1/2) = pi^2 / 2
  CHECK(trigamma(0.5) == doctest::Approx(4.934802200544679).epsilon(1e-8));
}

TEST_CASE("expected detection probability is (beta/(beta+d^2))^alpha for Swerling I") {
  InverseGamma<double> p;
  p.a = 3.0;
  p.b = 200.0;  // mean varsigma 100
  const double d = 1.5;
  // (200 / 202.25)^3 = 0.96699...
  const double expect = std::pow(200.0 / 202.25, 3.0);
  CHECK(target_detection_probability(p, d, 1) == doctest::Approx(expect).epsilon(1e-14));
  // Swerling III plug-in: x = 2 d^2 / 100 = 0.045, (1 + x) e^-x
  CHECK(target_detection_probability(p, d, 2) ==
        doctest::Approx(1.045 * std::exp(-0.045)).epsilon(1e-14));
}

TEST_CASE("K_RL for n = 1 is the Lomax density times 2a") {
  InverseGamma<double> p;
  p.a = 4.0;
  p.b = 30.0;
  const double a = 3.0, d = 1.0;
  const AmplitudeTerms<double> t = amplitude_terms(a, d, 1.0);
  CHECK(t.target_excess == doctest::Approx(8.0));
  // 2a * alpha beta^alpha / (beta + e)^(alpha+1) = 6 * 4 * 30^4 / 38^5
  const double expect = 6.0 * 4.0 * std::pow(30.0, 4.0) / std::pow(38.0, 5.0);
  CHECK(std::exp(log_target_amplitude(p, t, 1)) == doctest::Approx(expect).epsilon(1e-13));
  // With b = 1 the clutter marginal has the same form.
  CHECK(std::exp(log_clutter_amplitude(p, t)) == doctest::Approx(expect).epsilon(1e-13));
}

TEST_CASE("known Weibull likelihood integrates to 1 above the threshold") {
  const double d = 1.2, b = 0.8, sigma0 = 2.0;
  double integral = 0.0;
  const double h = 1e-3;
  for (double a = d + h / 2; a < 40.0; a += h) {
    integral += std::exp(log_clutter_amplitude_known(sigma0, amplitude_terms(a, d, b))) * h;
  }
  CHECK(integral == doctest::Approx(1.0).epsilon(1e-4));
}

TEST_CASE("forgetting keeps the IG mean and lowers the shape") {
  InverseGamma<double> p;
  p.a = 21.0;
  p.b = 400.0;  // mean 20
  forget_clamped(p, 1.25, 2.01);
  CHECK(p.a == doctest::Approx((21.0 + 0.25) / 1.25));
  CHECK(p.mean() == doctest::Approx(20.0).epsilon(1e-12));
}

TEST_CASE("IG merge of identical beliefs returns them; of two matches E[1/s]") {
  InverseGamma<double> a;
  a.a = 5.0;
  a.b = 40.0;
  IgMergeAccumulator<double> same;
  same.add(0.3, a);
  same.add(0.7, a);
  const InverseGamma<double> m = same.result(1e4);
  CHECK(m.a == doctest::Approx(5.0).epsilon(1e-6));
  CHECK(m.b == doctest::Approx(40.0).epsilon(1e-6));

  InverseGamma<double> b;
  b.a = 10.0;
  b.b = 50.0;
  IgMergeAccumulator<double> two;
  two.add(1.0, a);
  two.add(1.0, b);
  const InverseGamma<double> r = two.result(1e4);
  // KL projection keeps E[1/s] = mean of alpha/beta = (0.125 + 0.2)/2 and
  // E[ln 1/s] = mean of psi(alpha) - ln beta: ln alpha - psi(alpha) = c.
  CHECK(r.a / r.b == doctest::Approx(0.1625).epsilon(1e-12));
  const double c = std::log(0.1625) - 0.5 * (dmath::ddigamma(5.0) - std::log(40.0) +
                                             dmath::ddigamma(10.0) - std::log(50.0));
  CHECK(std::log(r.a) - dmath::ddigamma(r.a) == doctest::Approx(c).epsilon(1e-9));
  CHECK(ig_symmetric_kl(a, a) == doctest::Approx(0.0));
  CHECK(ig_symmetric_kl(a, b) > 0.0);
}

TEST_CASE("log-domain ESF of {2, 3, 4}: e1 = 9, e2 = 26, e3 = 24") {
  Cardinality<double, 8> card;
  card.init();
  const double lr[3] = {std::log(2.0), std::log(3.0), std::log(4.0)};
  std::array<double, 9> e{};
  const std::size_t top = card.esf(lr, 3, 3, e);
  CHECK(top == 3);
  CHECK(std::exp(e[0]) == doctest::Approx(1.0));
  CHECK(std::exp(e[1]) == doctest::Approx(9.0));
  CHECK(std::exp(e[2]) == doctest::Approx(26.0));
  CHECK(std::exp(e[3]) == doctest::Approx(24.0));
  // Leaving out the 3: {2, 4} -> e1 = 6, e2 = 8.
  card.esf(lr, 3, 1, e);
  CHECK(std::exp(e[1]) == doctest::Approx(6.0));
  CHECK(std::exp(e[2]) == doctest::Approx(8.0));
}

TEST_CASE("cardinality prediction: binomial thinning then Poisson births") {
  Cardinality<double, 8> card;
  card.init();
  card.predict(0.5, 1.0);  // from n = 0: Poisson(1)
  CHECK(card.probability(0) == doctest::Approx(std::exp(-1.0)));
  CHECK(card.probability(2) == doctest::Approx(std::exp(-1.0) / 2.0));
  CHECK(card.mean() == doctest::Approx(1.0).epsilon(1e-4));  // truncated at 8
  // Thinning alone: mean scales by p_S.
  card.predict(0.9, 1e-300);
  CHECK(card.mean() == doctest::Approx(0.9).epsilon(1e-4));
}

TEST_CASE("mixture reduction merges close components by moment matching and prunes light ones") {
  StaticVector<TargetComponent<double>, 8> in;
  StaticVector<TargetComponent<double>, 4> out;
  TargetComponent<double> c;
  c.weight = 0.6;
  c.P = Mat4<double>::Identity() * 100.0;
  c.label = 7;
  (void)in.push_back(c);
  c.weight = 0.2;
  c.x(0) = 10.0;  // Mahalanobis^2 = 1 < 4
  c.label = 9;
  (void)in.push_back(c);
  c.weight = 1e-7;  // pruned
  (void)in.push_back(c);
  c.weight = 0.5;
  c.x(0) = 500.0;  // far: its own component
  (void)in.push_back(c);
  ReductionSettings<double> s;
  ReductionScratch<8> scratch;
  std::uint64_t repairs = 0;
  double max_dropped = -1.0;
  CHECK(reduce_mixture(in, out, s, scratch, repairs, max_dropped) == 0);
  REQUIRE(out.size() == 2);
  CHECK(out[0].weight == doctest::Approx(0.8));
  CHECK(out[0].label == 7);
  CHECK(out[0].x(0) == doctest::Approx(2.5));  // (0.6*0 + 0.2*10)/0.8
  // P = 100 + spread: (0.6*2.5^2 + 0.2*7.5^2)/0.8 = 18.75
  CHECK(out[0].P(0, 0) == doctest::Approx(118.75));
  CHECK(out[1].weight == doctest::Approx(0.5));
  CHECK(max_dropped == 0.0);  // nothing truncated
}

TEST_CASE("mixture reduction counts components dropped by the cap") {
  StaticVector<TargetComponent<double>, 8> in;
  StaticVector<TargetComponent<double>, 2> out;
  for (int k = 0; k < 3; ++k) {
    TargetComponent<double> c;
    c.weight = 0.1 * (k + 1);
    c.x(0) = 1000.0 * k;
    (void)in.push_back(c);
  }
  ReductionSettings<double> s;
  ReductionScratch<8> scratch;
  std::uint64_t repairs = 0;
  double max_dropped = -1.0;
  CHECK(reduce_mixture(in, out, s, scratch, repairs, max_dropped) == 1);
  REQUIRE(out.size() == 2);
  CHECK(out[0].weight == doctest::Approx(0.3));  // heaviest kept
  CHECK(out[1].weight == doctest::Approx(0.2));
  CHECK(max_dropped == doctest::Approx(0.1));
}

TEST_CASE("mixture truncation keeps the heaviest merged components, not the heaviest heads") {
  // Heads in weight order: A 0.5, B 0.3, C 0.25; D (0.2) lies 5 m from C
  // under P = 100 I (Mahalanobis^2 0.25 <= 4) and merges into it: C+D = 0.45.
  // With room for 2 the J_max rule keeps A and C+D and leaves B out.
  StaticVector<TargetComponent<double>, 8> in;
  StaticVector<TargetComponent<double>, 2> out;
  const double w[4] = {0.5, 0.3, 0.25, 0.2};
  const double x[4] = {0.0, 1000.0, 2000.0, 2005.0};
  for (int k = 0; k < 4; ++k) {
    TargetComponent<double> c;
    c.weight = w[k];
    c.x(0) = x[k];
    c.P = Mat4<double>::Identity() * 100.0;
    c.label = static_cast<std::uint32_t>(k + 1);
    (void)in.push_back(c);
  }
  ReductionSettings<double> s;
  ReductionScratch<8> scratch;
  std::uint64_t repairs = 0;
  double max_dropped = -1.0;
  CHECK(reduce_mixture(in, out, s, scratch, repairs, max_dropped) == 1);
  REQUIRE(out.size() == 2);
  CHECK(out[0].label == 1);
  CHECK(out[0].weight == doctest::Approx(0.5));
  CHECK(out[1].label == 3);
  CHECK(out[1].weight == doctest::Approx(0.45));
  CHECK(out[1].x(0) == doctest::Approx((0.25 * 2000.0 + 0.2 * 2005.0) / 0.45));
  CHECK(max_dropped == doctest::Approx(0.3));  // B, replaced by C+D
}

TEST_CASE("mixture truncation re-sorts the kept components heaviest first") {
  // Room for 2; heads 0.4 (alone), 0.3 (absorbs 0.25: 0.55), 0.2 (alone).
  // Kept after the merge: 0.4 then 0.55; the 0.2 is left out; output 0.55, 0.4.
  StaticVector<TargetComponent<double>, 8> in;
  StaticVector<TargetComponent<double>, 2> out;
  const double w[4] = {0.4, 0.3, 0.25, 0.2};
  const double x[4] = {0.0, 1000.0, 1005.0, 3000.0};
  for (int k = 0; k < 4; ++k) {
    TargetComponent<double> c;
    c.weight = w[k];
    c.x(0) = x[k];
    c.P = Mat4<double>::Identity() * 100.0;
    (void)in.push_back(c);
  }
  ReductionSettings<double> s;
  ReductionScratch<8> scratch;
  std::uint64_t repairs = 0;
  double max_dropped = -1.0;
  CHECK(reduce_mixture(in, out, s, scratch, repairs, max_dropped) == 1);
  REQUIRE(out.size() == 2);
  CHECK(out[0].weight == doctest::Approx(0.55));
  CHECK(out[1].weight == doctest::Approx(0.4));
  CHECK(max_dropped == doctest::Approx(0.2));
}
