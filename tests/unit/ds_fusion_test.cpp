// Dempster-Shafer fusion (core/include/mptrack/classify/ds_fusion.h):
// values by hand from seed 003 eqs. (24)-(25).
#include <doctest/doctest.h>

#include <cmath>

#include "mptrack/classify/ds_fusion.h"

namespace cl = mptrack::classify;

TEST_CASE("DS fusion: w = 0.5 returns the tracker's belief bit for bit") {
  // 0.1 + (1 - 0.1) is not exactly 1 in float, so the product formula alone
  // would move p; the neutral element must not.
  const float ps[] = {0.0f, 1e-7f, 0.1f, 0.3f, 0.123456789f, 0.7f, 0.999f, 1.0f};
  for (const float p : ps) {
    CHECK(cl::ds_normalized_product(p, 0.5f) == p);
    CHECK(cl::ds_discounted_betp(p, 0.5f, 0.7f) == p);
    CHECK(cl::ds_normalized_product(static_cast<double>(p), 0.5) == static_cast<double>(p));
  }
}

TEST_CASE("DS fusion: normalized product by hand") {
  // p = 0.8, w = 0.9: 0.72 / (0.72 + 0.02) = 0.972972...
  CHECK(cl::ds_normalized_product(0.8, 0.9) == doctest::Approx(0.72 / 0.74).epsilon(1e-15));
  // symmetric in its arguments, and w < 0.5 lowers the belief
  CHECK(cl::ds_normalized_product(0.9, 0.8) == doctest::Approx(0.72 / 0.74).epsilon(1e-15));
  CHECK(cl::ds_normalized_product(0.6, 0.2) == doctest::Approx(0.12 / (0.12 + 0.32)).epsilon(1e-15));
}

TEST_CASE("DS fusion: total conflict keeps the tracker's belief") {
  CHECK(cl::ds_normalized_product(1.0, 0.0) == 1.0);
  CHECK(cl::ds_normalized_product(0.0, 1.0) == 0.0);
}

TEST_CASE("DS fusion: reliability discounting by hand") {
  // p = 0.6, w = 0.9, alpha = 0.5: m2 = (0.45 target, 0.05 clutter, 0.5 frame);
  // m(target) = 0.6 * 0.45 + 0.6 * 0.5 = 0.57, m(clutter) = 0.4 * 0.05 + 0.4 * 0.5
  // = 0.22, K = 0.6 * 0.05 + 0.4 * 0.45 = 0.21 -> BetP = 0.57 / 0.79.
  CHECK(cl::ds_discounted_betp(0.6, 0.9, 0.5) == doctest::Approx(0.57 / 0.79).epsilon(1e-15));
  CHECK(1.0 - 0.21 == doctest::Approx(0.57 + 0.22));
  // alpha = 1 is the plain product, alpha = 0 ignores the classifier
  CHECK(cl::ds_discounted_betp(0.6, 0.9, 1.0) == cl::ds_normalized_product(0.6, 0.9));
  CHECK(cl::ds_discounted_betp(0.6, 0.9, 0.0) == 0.6);
  // discounting pulls the result towards the tracker
  CHECK(cl::ds_discounted_betp(0.6, 0.9, 0.5) < cl::ds_normalized_product(0.6, 0.9));
}

TEST_CASE("DS fusion: prior-odds correction of an imbalanced training set") {
  // pi = 0.2 (1:4): w = 0.5 is odds 1 = 4 x the prior odds 1/4 -> 0.8.
  CHECK(cl::correct_training_prior(0.5, 0.2) == doctest::Approx(0.8).epsilon(1e-15));
  // w = pi is no evidence at all
  CHECK(cl::correct_training_prior(0.2, 0.2) == doctest::Approx(0.5).epsilon(1e-15));
  // balanced training: identity, bit for bit
  CHECK(cl::correct_training_prior(0.3f, 0.5f) == 0.3f);
}

TEST_CASE("DS fusion: clutter log-factor turns p_FG into BetP and is 0 when they agree") {
  CHECK(cl::clutter_log_factor(0.3f, 0.3f) == 0.0f);
  // p = 0.5, BetP = 0.8: target odds x4, clutter weight / 4 -> ln(1/4)
  CHECK(cl::clutter_log_factor(0.5, 0.8) == doctest::Approx(std::log(0.25)).epsilon(1e-14));
  // certainties are clamped: finite
  CHECK(std::isfinite(cl::clutter_log_factor(0.0, 1.0)));
}

TEST_CASE("DS fusion: log-odds gain by hand, identity at gain 1 and at w = 0.5") {
  // w = 0.75 is odds 3; gain 2 -> odds 9 -> 0.9; gain 0.5 -> odds sqrt(3)
  CHECK(cl::scale_log_odds(0.75, 2.0) == doctest::Approx(0.9).epsilon(1e-12));
  CHECK(cl::scale_log_odds(0.75, 0.5) == doctest::Approx(std::sqrt(3.0) / (1.0 + std::sqrt(3.0))).epsilon(1e-12));
  // w = 0.25 (odds 1/3), gain 2 -> odds 1/9 -> 0.1
  CHECK(cl::scale_log_odds(0.25, 2.0) == doctest::Approx(0.1).epsilon(1e-12));
  CHECK(cl::scale_log_odds(0.3f, 1.0f) == 0.3f);
  CHECK(cl::scale_log_odds(0.5f, 3.0f) == 0.5f);
}
