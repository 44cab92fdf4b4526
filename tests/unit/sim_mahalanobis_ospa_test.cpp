// OSPA with a Mahalanobis base distance in (range, range rate)
// (host-sim/src/eval/mahalanobis_ospa.h): one behaviour per case, distances
// worked out by hand: d = sqrt((dr / sigma_r)^2 + (drdot / sigma_rdot)^2),
// OSPA = ((1/n) [sum min(c, d)^p + c^p (n - m)])^(1/p), p = 2, c = 9.4.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include "eval/mahalanobis_ospa.h"
#include "sim_test_truth.h"

using namespace mptrack::sim;
namespace sc = mptrack::scenario;

namespace {

sc::TruthState truth(double x, double vx) {
  sc::TruthState t = sim_test::truth_at(1, x, 0.0, -1);
  t.x.vx = vx;
  return t;
}

TrackOut track(std::uint32_t id, double x, double vx, bool confirmed = true) {
  TrackOut t;
  t.id = id;
  t.px = x;
  t.vx = vx;
  t.confirmed = confirmed;
  return t;
}

MahalanobisOspaParams params() {
  MahalanobisOspaParams p;
  p.sigma_range_m = 15.0;
  p.sigma_range_rate_mps = 2.0;
  return p;
}

}  // namespace

TEST_CASE("range_and_rate: (3, 4) m moving (6, 8) m/s is 5 m away closing out at 10 m/s") {
  double r = 0.0, rdot = 0.0;
  range_and_rate(3.0, 6.0, 4.0, 8.0, r, rdot);
  CHECK(r == doctest::Approx(5.0));
  CHECK(rdot == doctest::Approx(10.0));
}

TEST_CASE("range_and_rate: the range rate at the sensor's own position is 0") {
  double r = 1.0, rdot = 1.0;
  range_and_rate(0.0, 3.0, 0.0, 4.0, r, rdot);
  CHECK(r == 0.0);
  CHECK(rdot == 0.0);
}

TEST_CASE("Mahalanobis OSPA: one pair 2 sigma off in range and 1 sigma in range rate is sqrt(5)") {
  MahalanobisOspa m(params());
  sc::SimScan s;
  s.truth.push_back(truth(1000.0, 3.0));
  EstimateOut e;
  e.tracks.push_back(track(1, 1030.0, 1.0));
  CHECK(m.evaluate(s, e) == doctest::Approx(std::sqrt(5.0)));
}

TEST_CASE("Mahalanobis OSPA: a velocity error alone counts (Euclidean position OSPA would be 0)") {
  MahalanobisOspa m(params());
  sc::SimScan s;
  s.truth.push_back(truth(1000.0, 3.0));
  EstimateOut e;
  e.tracks.push_back(track(1, 1000.0, -3.0));  // 6 m/s = 3 sigma
  CHECK(m.evaluate(s, e) == doctest::Approx(3.0));
}

TEST_CASE("Mahalanobis OSPA: a pair farther than c costs c = 9.4") {
  MahalanobisOspa m(params());
  sc::SimScan s;
  s.truth.push_back(truth(1000.0, 0.0));
  EstimateOut e;
  e.tracks.push_back(track(1, 1300.0, 0.0));  // 20 sigma
  CHECK(m.evaluate(s, e) == doctest::Approx(9.4));
}

TEST_CASE("Mahalanobis OSPA: an exact track plus a false one is c / sqrt(2)") {
  MahalanobisOspa m(params());
  sc::SimScan s;
  s.truth.push_back(truth(1000.0, 0.0));
  EstimateOut e;
  e.tracks.push_back(track(1, 1000.0, 0.0));
  e.tracks.push_back(track(2, 5000.0, 0.0));
  CHECK(m.evaluate(s, e) == doctest::Approx(9.4 / std::sqrt(2.0)));
}

TEST_CASE("Mahalanobis OSPA: tentative tracks are not scored") {
  MahalanobisOspa m(params());
  sc::SimScan s;
  s.truth.push_back(truth(1000.0, 0.0));
  EstimateOut e;
  e.tracks.push_back(track(1, 1000.0, 0.0, false));
  CHECK(m.evaluate(s, e) == doctest::Approx(9.4));
}

TEST_CASE("Mahalanobis OSPA: no truth and no track is 0") {
  MahalanobisOspa m(params());
  CHECK(m.evaluate(sc::SimScan{}, EstimateOut{}) == 0.0);
}

TEST_CASE("Mahalanobis OSPA: a non-positive base deviation is refused") {
  MahalanobisOspaParams p = params();
  p.sigma_range_rate_mps = 0.0;
  CHECK_THROWS_AS(MahalanobisOspa{p}, std::runtime_error);
}

TEST_CASE("mahalanobis_ospa_params: range from the scenario's range noise, range rate from its range-rate noise") {
  sc::ScenarioSpec spec;
  spec.sigma_range_m = 15.0;
  spec.othr.sigma_range_rate_mps = 0.05;
  const MahalanobisOspaParams p = mahalanobis_ospa_params(spec);
  CHECK(p.sigma_range_m == 15.0);
  CHECK(p.sigma_range_rate_mps == 0.05);
  CHECK(p.cutoff == 9.4);
  CHECK(p.order == 2.0);
}

TEST_CASE("mahalanobis_ospa_params: a Cartesian scenario's range deviation is its position noise") {
  sc::ScenarioSpec spec;
  spec.space = sc::MeasurementSpace::kCartesian;
  spec.sigma_xy_m = 10.0;
  CHECK(mahalanobis_ospa_params(spec).sigma_range_m == 10.0);
}
