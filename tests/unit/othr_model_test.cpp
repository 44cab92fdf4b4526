// Unit tests of the OTHR multipath measurement model
// (core/include/mptrack/model/othr_measurement.h, seed 002 eq. (57)):
// reference values computed independently in double with std:: functions
// (std::asin, not the datan2 route the model takes), the Jacobian against
// central finite differences, and the slant -> ground inverse.
#include <doctest/doctest.h>

#include <cmath>

#include "mptrack/model/othr_measurement.h"

using namespace mptrack::model;

namespace {

constexpr double kBaselineKm = 100.0;
constexpr double kHeightE = 100.0;
constexpr double kHeightF = 260.0;

// The four paths EE, EF, FE, FF as (transmit, receive) heights.
const OthrPath<double> kPaths[4] = {
    {kHeightE, kHeightE}, {kHeightE, kHeightF}, {kHeightF, kHeightE}, {kHeightF, kHeightF}};

// Target 1 of the seed 002 scenario at its first scan.
OthrState<double> target1() {
  OthrState<double> x;
  x << 1700.0, 0.10, 0.48, 8.7e-5;
  return x;
}

// eq. (57) written out with std:: functions, independently of the model.
OthrMeas<double> reference_h(const OthrState<double>& x, const OthrPath<double>& p, double d) {
  const double g = x(0), s = std::sin(x(2));
  const double ra = std::sqrt(g * g / 4 + p.rx_height_km * p.rx_height_km);
  const double rb = std::sqrt((g * g - 2 * d * g * s + d * d) / 4 + p.tx_height_km * p.tx_height_km);
  OthrMeas<double> y;
  y << ra + rb, x(1) / 4 * (g / ra + (g - d * s) / rb), std::asin(g * s / (2 * ra));
  return y;
}

}  // namespace

TEST_CASE("othr_measure matches eq. (57) written out independently, on every path") {
  for (const auto& p : kPaths) {
    const OthrMeas<double> y = othr_measure(target1(), p, kBaselineKm);
    const OthrMeas<double> ref = reference_h(target1(), p, kBaselineKm);
    CHECK(y(0) == doctest::Approx(ref(0)).epsilon(1e-13));
    CHECK(y(1) == doctest::Approx(ref(1)).epsilon(1e-13));
    CHECK(y(2) == doctest::Approx(ref(2)).epsilon(1e-12));
  }
}

TEST_CASE("othr_measure: EE slant range at target 1 is the hand value 1689.978 km") {
  // r_a = sqrt(850^2 + 100^2) = 855.862; r_b = sqrt((1700^2 - 2*100*1700*sin 0.48
  // + 100^2)/4 + 100^2) = 834.116 (sin 0.48 = 0.461779); sum 1689.978.
  const OthrMeas<double> y = othr_measure(target1(), kPaths[0], kBaselineKm);
  CHECK(y(0) == doctest::Approx(1689.978).epsilon(1e-6));
  CHECK(y(1) == doctest::Approx(0.099226).epsilon(1e-5));
  CHECK(y(2) == doctest::Approx(0.476437).epsilon(1e-6));
}

TEST_CASE("othr_measure: the azimuth depends on the receive height only") {
  const OthrMeas<double> ee = othr_measure(target1(), kPaths[0], kBaselineKm);
  const OthrMeas<double> fe = othr_measure(target1(), kPaths[2], kBaselineKm);
  const OthrMeas<double> ef = othr_measure(target1(), kPaths[1], kBaselineKm);
  CHECK(ee(2) == fe(2));
  CHECK(ee(0) < fe(0));  // higher transmit reflection: longer leg
  CHECK(ef(2) < ee(2));  // higher receive reflection: smaller elevation-projected azimuth
}

TEST_CASE("othr_measure: zero heights and baseline give the ground state itself") {
  const OthrPath<double> flat{0.0, 0.0};
  const OthrMeas<double> y = othr_measure(target1(), flat, 0.0);
  CHECK(y(0) == doctest::Approx(1700.0).epsilon(1e-14));
  CHECK(y(1) == doctest::Approx(0.10).epsilon(1e-14));
  CHECK(y(2) == doctest::Approx(0.48).epsilon(1e-12));
}

TEST_CASE("othr_linearize: Jacobian equals central finite differences on every path") {
  // Steps scaled to each state axis; the tolerance covers the O(step^2) error.
  const double step[4] = {1e-3, 1e-6, 1e-6, 1e-7};
  OthrState<double> x = target1();
  x(1) = -0.2;  // a non-trivial range rate makes the r_dot row informative
  for (const auto& p : kPaths) {
    OthrMeas<double> y;
    OthrJacobian<double> H;
    othr_linearize(x, p, kBaselineKm, y, H);
    const OthrMeas<double> y0 = othr_measure(x, p, kBaselineKm);
    for (int r = 0; r < 3; ++r) CHECK(y(r) == doctest::Approx(y0(r)).epsilon(1e-14));
    for (int c = 0; c < 4; ++c) {
      OthrState<double> xp = x, xm = x;
      xp(c) += step[c];
      xm(c) -= step[c];
      const OthrMeas<double> fd =
          (othr_measure(xp, p, kBaselineKm) - othr_measure(xm, p, kBaselineKm)) / (2 * step[c]);
      for (int r = 0; r < 3; ++r) {
        CAPTURE(r);
        CAPTURE(c);
        CHECK(H(r, c) == doctest::Approx(fd(r)).epsilon(1e-6).scale(1e-9));
      }
    }
  }
}

TEST_CASE("othr_linearize: the float instantiation agrees with double to float precision") {
  OthrState<float> xf = target1().cast<float>();
  OthrMeas<float> yf;
  OthrJacobian<float> Hf;
  const OthrPath<float> ff{260.0f, 260.0f};
  othr_linearize(xf, ff, 100.0f, yf, Hf);
  OthrMeas<double> yd;
  OthrJacobian<double> Hd;
  othr_linearize(target1(), kPaths[3], kBaselineKm, yd, Hd);
  CHECK(yf(0) == doctest::Approx(yd(0)).epsilon(1e-6));
  CHECK(yf(2) == doctest::Approx(yd(2)).epsilon(1e-5));
  CHECK(Hf(0, 0) == doctest::Approx(Hd(0, 0)).epsilon(1e-5));
  CHECK(Hf(2, 2) == doctest::Approx(Hd(2, 2)).epsilon(1e-5));
}

TEST_CASE("othr_invert recovers g, g_dot and theta from an exact measurement on every path") {
  for (const auto& p : kPaths) {
    const OthrMeas<double> y = othr_measure(target1(), p, kBaselineKm);
    OthrState<double> x;
    REQUIRE(othr_invert(y, p, kBaselineKm, x));
    CHECK(x(0) == doctest::Approx(1700.0).epsilon(1e-9));
    CHECK(x(1) == doctest::Approx(0.10).epsilon(1e-9));
    CHECK(x(2) == doctest::Approx(0.48).epsilon(1e-9));
    CHECK(x(3) == 0.0);
  }
}

TEST_CASE("othr_invert refuses a measurement that has no ground point") {
  OthrMeas<double> y;
  y << -10.0, 0.0, 0.5;  // negative slant range
  OthrState<double> x;
  CHECK_FALSE(othr_invert(y, kPaths[0], kBaselineKm, x));
}
