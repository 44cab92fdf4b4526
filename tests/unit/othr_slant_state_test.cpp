// The OTHR slant state of one path and its inverse (model/othr_slant_state.h):
// ground -> slant -> ground round trips for the four paths of seed 002,
// the covariance through J, the flat geometry as the identity, and the
// azimuth rate as the time derivative of the azimuth.
#include <doctest/doctest.h>

#include <cmath>

#include "mptrack/model/othr_slant_state.h"

using namespace mptrack::model;

namespace {

const OthrPath<double> kPaths[4] = {{100.0, 100.0}, {100.0, 260.0}, {260.0, 100.0}, {260.0, 260.0}};

OthrState<double> target1() {
  OthrState<double> x;
  x << 1700.0, 0.10, 0.48, 8.7e-5;  // seed 002 Sec. IV, target 1
  return x;
}

}  // namespace

TEST_CASE("othr slant state: ground -> slant -> ground returns the state on every seed 002 path") {
  for (const OthrPath<double>& p : kPaths) {
    OthrSlantState<double> s;
    OthrMat4<double> J;
    othr_ground_to_slant(target1(), p, 100.0, s, J);
    OthrState<double> x;
    OthrMat4<double> Px;
    REQUIRE(othr_slant_to_ground(s, OthrMat4<double>(OthrMat4<double>::Identity()), p, 100.0, x, Px));
    CHECK(x(0) == doctest::Approx(1700.0).epsilon(1e-12));
    CHECK(x(1) == doctest::Approx(0.10).epsilon(1e-10));
    CHECK(x(2) == doctest::Approx(0.48).epsilon(1e-12));
    CHECK(x(3) == doctest::Approx(8.7e-5).epsilon(1e-8));
  }
}

TEST_CASE("othr slant state: slant range, rate and azimuth of target 1 on EE match hand values") {
  OthrSlantState<double> s;
  OthrMat4<double> J;
  othr_ground_to_slant(target1(), kPaths[0], 100.0, s, J);
  // By hand from seed 002 eq. (57): r_a = sqrt(1700^2/4 + 100^2) = 855.862,
  // r_b = sqrt((1700^2 - 2 100 1700 sin 0.48 + 100^2)/4 + 100^2) = 834.116;
  // zeta = asin(1700 sin 0.48 / (2 r_a)) = asin(0.458616) = 0.476437.
  CHECK(s(0) == doctest::Approx(1689.978).epsilon(1e-6));
  CHECK(s(1) == doctest::Approx(0.099226).epsilon(1e-5));
  CHECK(s(2) == doctest::Approx(0.476437).epsilon(1e-6));
}

TEST_CASE("othr slant state: a ground covariance carried to slant and back is unchanged") {
  OthrMat4<double> Pg = OthrMat4<double>::Zero();
  Pg.diagonal() << 4.0, 1e-6, 4e-6, 1e-10;
  Pg(0, 2) = Pg(2, 0) = 1e-3;  // correlation 0.25
  OthrSlantState<double> s;
  OthrMat4<double> J;
  othr_ground_to_slant(target1(), kPaths[3], 100.0, s, J);
  const OthrMat4<double> Ps = J * Pg * J.transpose();
  OthrState<double> x;
  OthrMat4<double> back;
  REQUIRE(othr_slant_to_ground(s, Ps, kPaths[3], 100.0, x, back));
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      CAPTURE(r);
      CAPTURE(c);
      CHECK(back(r, c) == doctest::Approx(Pg(r, c)).epsilon(1e-7).scale(1e-12));
    }
  }
}

TEST_CASE("othr slant state: with no heights and no baseline the slant state is the ground state") {
  OthrState<double> x;
  x << 30.0, 0.01, 0.6, 1e-4;
  OthrSlantState<double> s;
  OthrMat4<double> J;
  othr_ground_to_slant(x, OthrPath<double>{}, 0.0, s, J);
  // r = 2 sqrt(g^2/4) = g, zeta = asin(sin theta) = theta, rates alike.
  CHECK(s(0) == doctest::Approx(30.0));
  CHECK(s(1) == doctest::Approx(0.01));
  CHECK(s(2) == doctest::Approx(0.6));
  CHECK(s(3) == doctest::Approx(1e-4));
}

TEST_CASE("othr slant state: the azimuth rate is the time derivative of the azimuth (finite difference)") {
  const OthrState<double> x0 = target1();
  const double dt = 1.0;  // [s]
  OthrState<double> x1 = x0;
  x1(0) += x0(1) * dt;
  x1(2) += x0(3) * dt;
  OthrSlantState<double> s0, s1;
  OthrMat4<double> J;
  othr_ground_to_slant(x0, kPaths[1], 100.0, s0, J);
  othr_ground_to_slant(x1, kPaths[1], 100.0, s1, J);
  CHECK((s1(2) - s0(2)) / dt == doctest::Approx(s0(3)).epsilon(1e-4));
}
