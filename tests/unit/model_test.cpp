// Unit tests of the shared models (core/include/mptrack/model/): values
// derived by hand in the comments, or independent computations (explicit
// inverses, finite differences).
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include <Eigen/Core>
#include <Eigen/LU>

#include "mptrack/math/detmath.h"
#include "mptrack/mfbp/mfbp_params.h"
#include "mptrack/model/amplitude_iggm.h"
#include "mptrack/model/cholesky.h"
#include "mptrack/model/clutter_mode.h"
#include "mptrack/model/cv_motion.h"
#include "mptrack/model/inverse_gamma.h"
#include "mptrack/model/mahalanobis.h"
#include "mptrack/model/measurement_validator.h"
#include "mptrack/model/polar_measurement.h"
#include "mptrack/model/spd_guard.h"
#include "mptrack/rfs/rfs_params.h"

using namespace mptrack;
using namespace mptrack::model;

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;
}  // namespace

// --- cv_motion.h ---

TEST_CASE("cv_predict of P = I over dt = 2 s with q = 0.5 m^2/s^4, entries by hand") {
  // Per axis F P F^T = [[1 + dt^2, dt], [dt, 1]] = [[5, 2], [2, 1]];
  // Q = q [[dt^4/4, dt^3/2], [dt^3/2, dt^2]] = 0.5 [[4, 4], [4, 4]] = [[2, 2], [2, 2]].
  CvState<double> x(1.0, 3.0, -2.0, -1.0);
  CvCovariance<double> P = CvCovariance<double>::Identity();
  cv_predict(x, P, 2.0, 0.5);
  CHECK(x(0) == 7.0);  // 1 + 2 * 3
  CHECK(x(1) == 3.0);
  CHECK(x(2) == -4.0);  // -2 + 2 * -1
  CHECK(x(3) == -1.0);
  for (int b = 0; b < 4; b += 2) {
    CHECK(P(b, b) == 7.0);
    CHECK(P(b, b + 1) == 4.0);
    CHECK(P(b + 1, b) == 4.0);
    CHECK(P(b + 1, b + 1) == 3.0);
  }
  CHECK(P(0, 2) == 0.0);  // no cross-axis terms
  CHECK(P(1, 3) == 0.0);
}

TEST_CASE("cv_transition gives the F and Q whose F P F^T + Q cv_predict writes out") {
  CvCovariance<double> F;
  CvCovariance<double> Q;
  cv_transition(2.0, 0.5, F, Q);
  CHECK(F(0, 1) == 2.0);
  CHECK(F(2, 3) == 2.0);
  CHECK(F(1, 0) == 0.0);
  CHECK(Q(0, 0) == 2.0);
  CHECK(Q(0, 1) == 2.0);
  CHECK(Q(1, 1) == 2.0);
  CHECK(Q(0, 2) == 0.0);
  CvCovariance<double> P;
  P << 2.0, 0.3, 0.1, 0.0, 0.3, 1.0, 0.0, 0.2, 0.1, 0.0, 3.0, -0.4, 0.0, 0.2, -0.4, 0.5;
  const CvCovariance<double> full = F * P * F.transpose() + Q;
  CvState<double> x = CvState<double>::Zero();
  cv_predict(x, P, 2.0, 0.5);
  CHECK((P - full).cwiseAbs().maxCoeff() < 1e-12);
}

// --- cholesky.h ---

TEST_CASE("Cholesky of a 3x3 with a known integer factor, its solve and whitening") {
  // L = [[2, 0, 0], [1, 3, 0], [-1, 1, 2]] gives A = L L^T below.
  Eigen::Matrix3d A;
  A << 4, 2, -2, 2, 10, 2, -2, 2, 6;
  Eigen::Matrix3d L;
  REQUIRE(cholesky<double, 3>(A, L));
  Eigen::Matrix3d expected;
  expected << 2, 0, 0, 1, 3, 0, -1, 1, 2;
  CHECK(L == expected);
  // A [1, 1, 1]^T = [4, 14, 6]^T.
  const Eigen::Vector3d x = cholesky_solve<double, 3, 1>(L, Eigen::Vector3d(4, 14, 6));
  CHECK(x(0) == doctest::Approx(1.0));
  CHECK(x(1) == doctest::Approx(1.0));
  CHECK(x(2) == doctest::Approx(1.0));
  // L^-1 [4, 14, 6]: y0 = 4/2 = 2, y1 = (14 - 2)/3 = 4, y2 = (6 + 2 - 4)/2 = 2.
  const Eigen::Vector3d y = cholesky_whiten<double, 3>(L, Eigen::Vector3d(4, 14, 6));
  CHECK(y(0) == 2.0);
  CHECK(y(1) == 4.0);
  CHECK(y(2) == 2.0);
}

TEST_CASE("is_spd rejects indefinite, NaN and infinite matrices") {
  Eigen::Matrix2d indefinite;
  indefinite << 1, 2, 2, 1;  // eigenvalues -1, 3
  CHECK_FALSE(is_spd(indefinite));
  CHECK(is_spd(Eigen::Matrix2d(Eigen::Matrix2d::Identity())));
  Eigen::Matrix2d nan_p = Eigen::Matrix2d::Identity();
  nan_p(1, 1) = kNaN;
  CHECK_FALSE(is_spd(nan_p));
  Eigen::Matrix2d inf_p = Eigen::Matrix2d::Identity();
  inf_p(0, 0) = kInf;
  CHECK_FALSE(is_spd(inf_p));
}

// --- spd_guard.h ---

TEST_CASE("keep_spd leaves a well-conditioned SPD matrix untouched and symmetrises") {
  Eigen::Matrix3d A;
  A << 4, 2, -2, 2, 10, 2, -2, 2, 6;
  Eigen::Matrix3d P = A;
  CHECK_FALSE(keep_spd(P, 1e-6));
  CHECK(P == A);
  P(0, 1) = 2.5;  // asymmetric: both become (2.5 + 2) / 2
  CHECK_FALSE(keep_spd(P, 1e-6));
  CHECK(P(0, 1) == 2.25);
  CHECK(P(1, 0) == 2.25);
}

TEST_CASE("keep_spd repairs a singular matrix by diagonal loading") {
  Eigen::Matrix2d P;
  P << 1, 1, 1, 1;  // rank one
  CHECK(keep_spd(P, 1e-6));
  CHECK(is_well_conditioned_spd(P));
  CHECK(P(0, 1) == 1.0);  // loading keeps the correlation term
  CHECK(P(0, 0) > 1.0);
}

TEST_CASE("keep_spd treats a near-singular pivot as singular (F14) and loads until it is not") {
  // Correlation 0.99999: pivot^2 = 1 - 0.99999^2 = 2e-5 < 1e-4 * 1. A plain
  // Cholesky accepts it; the guard does not. Loads 1e-6, 1e-5 fail
  // (pivot^2 ~ 2.2e-5, 4.2e-5), 1e-4 passes (pivot^2 ~ 2.4e-4 >= 1.0001e-4).
  // Each load is 10^k 1e-6 times the current largest diagonal:
  // 1 + 1e-6 + 1.000001e-5 + 1.000011e-4 = 1.00011100111.
  Eigen::Matrix2d P;
  P << 1, 0.99999, 0.99999, 1;
  CHECK(is_spd(P));
  CHECK_FALSE(is_well_conditioned_spd(P));
  CHECK(keep_spd(P, 1e-6));
  CHECK(P(0, 0) == doctest::Approx(1.00011100111).epsilon(1e-12));
  CHECK(P(1, 1) == doctest::Approx(1.00011100111).epsilon(1e-12));
  CHECK(P(0, 1) == 0.99999);
}

TEST_CASE("keep_spd falls back to the floored diagonal when loading cannot help") {
  Eigen::Matrix2d P;
  P << 1, kNaN, kNaN, -3;
  CHECK(keep_spd(P, 0.25));
  CHECK(P(0, 1) == 0.0);
  CHECK(P(1, 0) == 0.0);
  CHECK(is_well_conditioned_spd(P));
  CHECK(P(0, 0) >= 1.0);
  CHECK(P(1, 1) >= 0.25);
}

// --- mahalanobis.h ---

TEST_CASE("mahalanobis2 equals e^T C^-1 e with the explicit inverse") {
  // C = [[4, 1], [1, 2]], C^-1 = 1/7 [[2, -1], [-1, 4]]; e = (1, 2):
  // d^2 = (2 - 4 + 16) / 7 = 2.
  Eigen::Matrix2d C;
  C << 4, 1, 1, 2;
  double d2 = -1.0;
  REQUIRE(mahalanobis2(Eigen::Vector2d(1, 2), C, d2));
  CHECK(d2 == doctest::Approx(2.0).epsilon(1e-15));
  const Eigen::Vector2d e(-0.3, 5.0);
  REQUIRE(mahalanobis2(e, C, d2));
  CHECK(d2 == doctest::Approx(e.dot(C.inverse() * e)).epsilon(1e-14));
}

TEST_CASE("mahalanobis2 rejects an invalid covariance and leaves d2 untouched") {
  Eigen::Matrix2d indefinite;
  indefinite << 1, 2, 2, 1;  // det -3
  Eigen::Matrix2d negative = -Eigen::Matrix2d::Identity();  // det 1 > 0 but C00 < 0
  Eigen::Matrix2d nan_c = Eigen::Matrix2d::Identity();
  nan_c(0, 1) = kNaN;
  double d2 = 42.0;
  CHECK_FALSE(mahalanobis2(Eigen::Vector2d(1, 1), indefinite, d2));
  CHECK_FALSE(mahalanobis2(Eigen::Vector2d(1, 1), negative, d2));
  CHECK_FALSE(mahalanobis2(Eigen::Vector2d(1, 1), nan_c, d2));
  CHECK(d2 == 42.0);
}

TEST_CASE("mahalanobis_n of a 4x4 equals e^T C^-1 e; a singular C is rejected") {
  Eigen::Matrix4d C;
  C << 4, 1, 0, 0.5, 1, 3, 0.2, 0, 0, 0.2, 2, 0.1, 0.5, 0, 0.1, 1;
  const Eigen::Vector4d e(1, -2, 0.5, 3);
  double d2 = 0.0;
  REQUIRE(mahalanobis_n<double, 4>(e, C, d2));
  CHECK(d2 == doctest::Approx(e.dot(C.inverse() * e)).epsilon(1e-13));
  Eigen::Matrix4d singular = Eigen::Matrix4d::Zero();
  singular(0, 0) = 1.0;
  d2 = 7.0;
  CHECK_FALSE(mahalanobis_n<double, 4>(e, singular, d2));
  CHECK(d2 == 7.0);
}

// --- inverse_gamma.h ---

TEST_CASE("IG forgetting keeps the mean and lowers the shape") {
  // a = 21, b = 400: mean 20. u = 1.25: a = (21 + 0.25) / 1.25 = 17,
  // b = 320, mean 320 / 16 = 20.
  InverseGamma<double> ig;
  ig.a = 21.0;
  ig.b = 400.0;
  const InverseGamma<double> p = ig.predicted(1.25);
  CHECK(p.a == doctest::Approx(17.0));
  CHECK(p.b == doctest::Approx(320.0));
  CHECK(p.mean() == doctest::Approx(20.0).epsilon(1e-14));
  InverseGamma<double> c = ig;
  forget_clamped(c, 1.25, 2.01);  // 17 >= 2.01: no clamp, the same numbers
  CHECK(c.a == p.a);
  CHECK(c.b == p.b);
}

TEST_CASE("IG forget_clamped raises the shape to the floor and keeps the mean") {
  // a = 2.5, b = 3 (mean 2); u = 1.25: a = 2.2, b = 2.4; floor 3: a = 3,
  // b = 2 (3 - 1) = 4.
  InverseGamma<double> ig;
  ig.a = 2.5;
  ig.b = 3.0;
  forget_clamped(ig, 1.25, 3.0);
  CHECK(ig.a == 3.0);
  CHECK(ig.b == doctest::Approx(4.0).epsilon(1e-14));
  CHECK(ig.mean() == doctest::Approx(2.0).epsilon(1e-14));
}

TEST_CASE("IG moments: E[1/s] = a/b, E[ln s] = ln b - psi(a), snr = mean - 1 clamped") {
  InverseGamma<double> ig;
  ig.a = 1.0;
  ig.b = std::exp(1.0);
  // psi(1) = -Euler gamma: E[ln s] = 1 + 0.5772156649...
  CHECK(ig.mean_log() == doctest::Approx(1.5772156649015329).epsilon(1e-12));
  CHECK(ig.mean_inverse() == doctest::Approx(1.0 / std::exp(1.0)));
  ig.a = 5.0;
  ig.b = 40.0;  // mean 10
  CHECK(ig.snr() == doctest::Approx(9.0));
  ig.b = 2.0;  // mean 0.5 < 1
  CHECK(ig.snr() == 0.0);
  ig.update(2.0, 6.0);
  CHECK(ig.a == 7.0);
  CHECK(ig.b == 8.0);
  const InverseGamma<double> w = inverse_gamma_with_mean(10.0, 3.0);
  CHECK(w.mean() == doctest::Approx(10.0));
}

TEST_CASE("IGGM Swerling I detection probability is (b / (b + d^2))^a") {
  InverseGamma<double> p;
  p.a = 3.0;
  p.b = 200.0;
  CHECK(target_detection_probability(p, 2.0, 1) ==
        doctest::Approx(std::pow(200.0 / 204.0, 3.0)).epsilon(1e-12));
}

// --- polar_measurement.h ---

TEST_CASE("polar h(x) of a 3-4-5 state, with radial velocity") {
  // x = [3, 1, 4, -2]: r = 5, theta = atan2(4, 3), r_dot = (3 - 8) / 5 = -1.
  const CvState<double> x(3.0, 1.0, 4.0, -2.0);
  const Eigen::Vector3d z = polar_measure<double, 3>(x);
  CHECK(z(0) == 5.0);
  CHECK(z(1) == doctest::Approx(std::atan2(4.0, 3.0)).epsilon(1e-15));
  CHECK(z(2) == doctest::Approx(-1.0).epsilon(1e-15));
  const Eigen::Vector2d z2 = polar_of_state(x);
  CHECK(z2(0) == z(0));
  CHECK(z2(1) == z(1));
}

TEST_CASE("polar Jacobian matches central finite differences") {
  const CvState<double> x(3.0, 1.0, 4.0, -2.0);
  Eigen::Vector2d z_hat;
  Eigen::Matrix<double, 2, 4> H;
  polar_linearize(x, 25.0, z_hat, H);
  // By hand: [[3/5, 0, 4/5, 0], [-4/25, 0, 3/25, 0]].
  CHECK(H(0, 0) == doctest::Approx(0.6));
  CHECK(H(1, 0) == doctest::Approx(-0.16));
  const double h = 1e-6;
  for (int k = 0; k < 4; ++k) {
    CvState<double> xp = x;
    CvState<double> xm = x;
    xp(k) += h;
    xm(k) -= h;
    const Eigen::Vector2d d = (polar_of_state(xp) - polar_of_state(xm)) / (2 * h);
    CHECK(H(0, k) == doctest::Approx(d(0)).epsilon(1e-8));
    CHECK(H(1, k) == doctest::Approx(d(1)).epsilon(1e-8));
  }
}

TEST_CASE("wrap_angle maps to (-pi, pi]; cartesian_of_polar inverts h") {
  CHECK(wrap_angle(1.5 * kPi) == doctest::Approx(-0.5 * kPi));
  CHECK(wrap_angle(-1.5 * kPi) == doctest::Approx(0.5 * kPi));
  CHECK(wrap_angle(-dmath::kPi<double>) == dmath::kPi<double>);  // -pi is outside
  CHECK(wrap_angle(dmath::kPi<double>) == dmath::kPi<double>);
  CHECK(wrap_angle(0.25) == 0.25);
  const Eigen::Vector2d p = cartesian_of_polar(5.0, std::atan2(4.0, 3.0));
  CHECK(p(0) == doctest::Approx(3.0).epsilon(1e-14));
  CHECK(p(1) == doctest::Approx(4.0).epsilon(1e-14));
}

// --- measurement_validator.h ---

namespace {
MeasurementValidator<double> thresholded() {
  MeasurementValidator<double> v;
  v.min0 = 10;
  v.max0 = 100;
  v.min1 = -1;
  v.max1 = 1;
  v.amplitude = AmplitudeRule::kThresholded;
  v.threshold = 2;
  v.max_amplitude = 50;
  return v;
}
Measurement<double> good() {
  Measurement<double> m;
  m.range_m = 50;
  m.azimuth_rad = 0.5;
  m.amplitude = 3;
  return m;
}
}  // namespace

TEST_CASE("validator accepts a measurement inside every bound, bounds included") {
  const MeasurementValidator<double> v = thresholded();
  CHECK(v.valid(good()));
  Measurement<double> m = good();
  m.range_m = 10;
  m.azimuth_rad = 1;
  m.amplitude = 50;
  CHECK(v.valid(m));
}

TEST_CASE("validator rejects each field on its own") {
  const MeasurementValidator<double> v = thresholded();
  Measurement<double> m = good();
  m.range_m = kNaN;
  CHECK_FALSE(v.valid(m));
  m = good();
  m.range_m = 100.5;
  CHECK_FALSE(v.valid(m));
  m = good();
  m.azimuth_rad = kInf;
  CHECK_FALSE(v.valid(m));
  m = good();
  m.azimuth_rad = -1.01;
  CHECK_FALSE(v.valid(m));
  m = good();
  m.amplitude = kNaN;
  CHECK_FALSE(v.valid(m));
  m = good();
  m.amplitude = 2;  // exactly the threshold: rejected
  CHECK_FALSE(v.valid(m));
  m = good();
  m.amplitude = 50.5;
  CHECK_FALSE(v.valid(m));
}

TEST_CASE("validator amplitude rules: ignored, positive; Doppler span") {
  MeasurementValidator<double> v = thresholded();
  Measurement<double> m = good();
  m.amplitude = kNaN;
  v.amplitude = AmplitudeRule::kIgnored;
  CHECK(v.valid(m));
  v.amplitude = AmplitudeRule::kPositive;
  CHECK_FALSE(v.valid(m));
  m.amplitude = 0.5;  // below the threshold, fine when amplitude is not modelled
  CHECK(v.valid(m));
  m.amplitude = 0.0;
  CHECK_FALSE(v.valid(m));
  v = thresholded();
  v.check_doppler = true;
  v.doppler_span_mps = 20;
  m = good();
  m.doppler_mps = 20;
  CHECK(v.valid(m));
  m.doppler_mps = -20.5;
  CHECK_FALSE(v.valid(m));
  m.doppler_mps = kNaN;
  CHECK_FALSE(v.valid(m));
}

// --- clutter_mode.h ---

TEST_CASE("one ClutterMode: MF-BP spellings alias, each tracker rejects modes it lacks") {
  CHECK(ClutterMode::kEstimate == ClutterMode::kEstimatedMap);
  CHECK(ClutterMode::kUniformKnownRate == ClutterMode::kKnownRateUniform);
  CHECK(ClutterMode::kKnown == ClutterMode::kKnownMap);
  RfsFilterParams<double> gm;
  CHECK(gm.validate() == Status::kOk);
  gm.clutter_mode = ClutterMode::kKnownMap;
  CHECK(gm.validate() == Status::kInvalidArgument);
  gm.clutter_mode = ClutterMode::kKnownRateUniform;
  CHECK(gm.validate() == Status::kInvalidArgument);
  MfbpParams<double> mf;
  CHECK(mf.validate() == Status::kOk);
  mf.clutter_mode = ClutterMode::kEstimatedUniform;
  CHECK(mf.validate() == Status::kInvalidArgument);
  mf.clutter_mode = ClutterMode::kKnownUniform;
  CHECK(mf.validate() == Status::kInvalidArgument);
}
