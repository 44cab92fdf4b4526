// Cavity moments of the MF-BP association (mfbp/cavity.h): removing a
// pseudo-measurement from a Gaussian belief in measurement space.
#include <doctest/doctest.h>

#include <Eigen/LU>

#include "mptrack/mfbp/cavity.h"

using namespace mptrack::mfbp;

// Hand-derived, per axis (diagonal): a belief of variance s that came from a
// cavity of variance c and a measurement of variance r (weight 1) satisfies
// 1/s = 1/c + 1/r, mean z = (z_c/c + y/r) s. With s = 2, r = 4: c = 4 and
// z = (z_c + y)/2, so z_c = z - (y - z) = z - e. Azimuth axis: s = 0.5,
// r = 1 -> c = 1, same mirror. All values are exact in binary.
TEST_CASE("mfbp cavity removes an equal-precision measurement: variance doubles, mean mirrors") {
  Vec2<double> z(1000.0, 0.25);
  Mat2<double> Sz;
  Sz << 2.0, 0.0, 0.0, 0.5;
  const Vec2<double> e_bar(1.0, 0.125);  // y_bar - z_hat
  const Vec2<double> r_inv(0.25, 1.0);   // R = diag(4, 1)
  REQUIRE(remove_pseudo_measurement(z, Sz, e_bar, 1.0, r_inv));
  CHECK(z(0) == 999.0);
  CHECK(z(1) == 0.125);
  CHECK(Sz(0, 0) == 4.0);
  CHECK(Sz(1, 1) == 1.0);
  CHECK(Sz(0, 1) == 0.0);
  CHECK(Sz(1, 0) == 0.0);
}

// Weight w scales the removed information (R / w): with w = 0.5 the
// measurement variance is 8, so 1/c = 1/2 - 1/8 = 3/8, c = 8/3, and
// z_c = z - c (w/r) e = z - (8/3)(1/8) e = z - e/3.
TEST_CASE("mfbp cavity with a fractional association weight removes w R^-1 only") {
  Vec2<double> z(0.0, 0.0);
  Mat2<double> Sz;
  Sz << 2.0, 0.0, 0.0, 0.5;
  const Vec2<double> e_bar(3.0, 0.0);
  REQUIRE(remove_pseudo_measurement(z, Sz, e_bar, 0.5, Vec2<double>(0.25, 1.0)));
  CHECK(Sz(0, 0) == doctest::Approx(8.0 / 3.0).epsilon(1e-14));
  CHECK(z(0) == doctest::Approx(-1.0).epsilon(1e-14));
  // azimuth: 1/c = 2 - 0.5 = 1.5
  CHECK(Sz(1, 1) == doctest::Approx(1.0 / 1.5).epsilon(1e-14));
}

// Correlated belief against the textbook information form computed with a
// general inverse: S_cav = (Sz^-1 - w R^-1)^-1, z_cav = S_cav (Sz^-1 z - w R^-1 y).
TEST_CASE("mfbp cavity of a correlated belief equals the information-form division") {
  const Vec2<double> z0(20000.0, 0.5);
  Mat2<double> Sz0;
  Sz0 << 150.0, 0.02, 0.02, 3.0e-5;
  const double w = 0.8;
  const Vec2<double> r_inv(1.0 / 400.0, 1.0 / 1.0966e-4);
  const Vec2<double> y(20030.0, 0.503);
  Mat2<double> Rinv = Mat2<double>::Zero();
  Rinv(0, 0) = r_inv(0);
  Rinv(1, 1) = r_inv(1);
  const Mat2<double> S_ref = (Sz0.inverse() - w * Rinv).inverse();
  const Vec2<double> z_ref = S_ref * (Sz0.inverse() * z0 - w * Rinv * y);

  Vec2<double> z = z0;
  Mat2<double> Sz = Sz0;
  REQUIRE(remove_pseudo_measurement(z, Sz, Vec2<double>(y - z0), w, r_inv));
  CHECK(z(0) == doctest::Approx(z_ref(0)).epsilon(1e-10));
  CHECK(z(1) == doctest::Approx(z_ref(1)).epsilon(1e-10));
  CHECK(Sz(0, 0) == doctest::Approx(S_ref(0, 0)).epsilon(1e-10));
  CHECK(Sz(0, 1) == doctest::Approx(S_ref(0, 1)).epsilon(1e-10));
  CHECK(Sz(1, 1) == doctest::Approx(S_ref(1, 1)).epsilon(1e-10));
  // The cavity is wider than the belief on both axes.
  CHECK(Sz(0, 0) > Sz0(0, 0));
  CHECK(Sz(1, 1) > Sz0(1, 1));
}

// A belief tighter than the removed measurement allows (Sz^-1 - w R^-1 not
// positive definite: here Sz = R, w = 2) is left unchanged.
TEST_CASE("mfbp cavity refuses a non-positive-definite division and leaves the moments") {
  Vec2<double> z(100.0, 0.1);
  Mat2<double> Sz;
  Sz << 4.0, 0.0, 0.0, 1.0;
  REQUIRE_FALSE(remove_pseudo_measurement(z, Sz, Vec2<double>(1.0, 0.0), 2.0, Vec2<double>(0.25, 1.0)));
  CHECK(z(0) == 100.0);
  CHECK(z(1) == 0.1);
  CHECK(Sz(0, 0) == 4.0);
  CHECK(Sz(1, 1) == 1.0);
}

TEST_CASE("mfbp cavity in float matches double on the equal-precision case") {
  Vec2<float> z(1000.0f, 0.25f);
  Mat2<float> Sz;
  Sz << 2.0f, 0.0f, 0.0f, 0.5f;
  REQUIRE(remove_pseudo_measurement(z, Sz, Vec2<float>(1.0f, 0.125f), 1.0f, Vec2<float>(0.25f, 1.0f)));
  CHECK(z(0) == 999.0f);
  CHECK(z(1) == 0.125f);
  CHECK(Sz(0, 0) == 4.0f);
}
