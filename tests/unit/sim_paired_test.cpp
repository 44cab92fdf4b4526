// Paired Monte Carlo differences (host-sim/src/eval/paired.h) on
// hand-computed values.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "eval/paired.h"

using mptrack::sim::PairedDifference;
using mptrack::sim::paired_difference;
using mptrack::sim::paired_difference_text;

TEST_CASE("paired difference: mean and standard error of the run-by-run differences") {
  // Differences 2, 3, 0: mean 5/3; sample variance ((1/3)^2 + (4/3)^2 + (5/3)^2) / 2 = 7/3;
  // standard error sqrt(7/3) / sqrt(3) = sqrt(7) / 3.
  const PairedDifference d = paired_difference({3.0, 5.0, 4.0}, {1.0, 2.0, 4.0});
  CHECK(d.runs == 3);
  CHECK(d.mean == doctest::Approx(5.0 / 3.0));
  CHECK(d.standard_error == doctest::Approx(std::sqrt(7.0) / 3.0));
}

TEST_CASE("paired difference: counts the runs where a is strictly lower, ties not") {
  const PairedDifference d = paired_difference({1.0, 5.0, 4.0, 0.5}, {2.0, 2.0, 4.0, 3.0});
  CHECK(d.a_lower == 2);
}

TEST_CASE("paired difference: a constant offset has zero standard error, whatever the scene spread") {
  // Scenes of very different difficulty, one tracker always 1.5 m better: the
  // unpaired spread is large, the paired one is 0.
  const PairedDifference d = paired_difference({10.0, 101.0, 41.0}, {11.5, 102.5, 42.5});
  CHECK(d.mean == doctest::Approx(-1.5));
  CHECK(d.standard_error == doctest::Approx(0.0).epsilon(1e-12));
  CHECK(d.a_lower == 3);
}

TEST_CASE("paired difference: inputs of different length or empty compare nothing") {
  CHECK(paired_difference({1.0, 2.0}, {1.0}).runs == 0);
  CHECK(paired_difference({}, {}).runs == 0);
  CHECK(paired_difference_text(paired_difference({1.0, 2.0}, {1.0}), 2) == "n/a");
}

TEST_CASE("paired difference: one run has a mean and no standard error") {
  const PairedDifference d = paired_difference({7.0}, {4.0});
  CHECK(d.runs == 1);
  CHECK(d.mean == doctest::Approx(3.0));
  CHECK(d.standard_error == 0.0);
  CHECK(paired_difference_text(d, 1) == "+3.0 +- 0.0 (lower in 0 of 1)");
}
