// Unit tests of the GNN baseline's filter pieces against independent
// computations: generic matrix algebra, finite differences, the textbook
// covariance update.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <limits>

#include <Eigen/LU>

#include "mptrack/gnn/gnn_track.h"
#include "mptrack/gnn/polar_ekf.h"
#include "mptrack/model/cv_motion.h"

using Mat4 = Eigen::Matrix<double, 4, 4>;
using Vec4 = Eigen::Matrix<double, 4, 1>;

namespace {

constexpr double kPi = 3.14159265358979323846;

Mat4 spd_example() {
  Mat4 a;
  a << 2.0, 0.3, -0.1, 0.05, 0.1, 1.5, 0.2, -0.3, 0.0, 0.4, 3.0, 0.1, 0.2, 0.0, -0.5, 0.8;
  return a * a.transpose() + 0.1 * Mat4::Identity();
}

}  // namespace

TEST_CASE("cv_predict equals F P F^T + Q built as full matrices") {
  const double dt = 0.25;
  const double sa = 2.0;
  Vec4 x(1.0, 2.0, -3.0, 0.5);
  Mat4 P = spd_example();
  Mat4 F = Mat4::Identity();
  F(0, 1) = dt;
  F(2, 3) = dt;
  Mat4 Q = Mat4::Zero();
  const double q = sa * sa;
  Q(0, 0) = Q(2, 2) = q * std::pow(dt, 4) / 4.0;
  Q(0, 1) = Q(1, 0) = Q(2, 3) = Q(3, 2) = q * std::pow(dt, 3) / 2.0;
  Q(1, 1) = Q(3, 3) = q * dt * dt;
  const Vec4 x_ref = F * x;
  const Mat4 P_ref = F * P * F.transpose() + Q;
  mptrack::model::cv_predict(x, P, dt, sa * sa);
  CHECK((x - x_ref).cwiseAbs().maxCoeff() < 1e-15);
  CHECK((P - P_ref).cwiseAbs().maxCoeff() < 1e-13);
}

TEST_CASE("polar_predict gives the range/azimuth of the state and a Jacobian matching finite differences") {
  const Vec4 x(30.0, 1.0, 40.0, -2.0);
  const Mat4 P = spd_example();
  const auto pred = mptrack::gnn::polar_predict(x, P, 0.2, 0.01);
  REQUIRE(pred.valid);
  CHECK(pred.z_hat(0) == doctest::Approx(50.0).epsilon(1e-15));
  CHECK(pred.z_hat(1) == doctest::Approx(std::atan2(40.0, 30.0)).epsilon(1e-14));
  const double h = 1e-6;
  for (int k = 0; k < 4; ++k) {
    Vec4 xp = x;
    Vec4 xm = x;
    xp(k) += h;
    xm(k) -= h;
    const double dr = (std::hypot(xp(0), xp(2)) - std::hypot(xm(0), xm(2))) / (2 * h);
    const double da = (std::atan2(xp(2), xp(0)) - std::atan2(xm(2), xm(0))) / (2 * h);
    CHECK(pred.H(0, k) == doctest::Approx(dr).epsilon(1e-7));
    CHECK(pred.H(1, k) == doctest::Approx(da).epsilon(1e-7));
  }
  Eigen::Matrix2d R = Eigen::Matrix2d::Zero();
  R(0, 0) = 0.04;
  R(1, 1) = 1e-4;
  const Eigen::Matrix2d S_ref = pred.H * P * pred.H.transpose() + R;
  CHECK((pred.S - S_ref).cwiseAbs().maxCoeff() < 1e-12);
  CHECK((pred.S * pred.S_inv - Eigen::Matrix2d::Identity()).cwiseAbs().maxCoeff() < 1e-12);
}

TEST_CASE("polar_predict refuses to linearise at the origin") {
  const Vec4 x(0.0, 1.0, 0.0, 1.0);
  CHECK_FALSE(mptrack::gnn::polar_predict(x, spd_example(), 0.2, 0.01).valid);
}

TEST_CASE("polar_innovation wraps the azimuth difference across +-pi") {
  const Vec4 x(-10.0, 0.0, 0.01, 0.0);  // azimuth just below +pi
  const auto pred = mptrack::gnn::polar_predict(x, spd_example(), 0.2, 0.01);
  REQUIRE(pred.valid);
  const double z_az = -kPi + 0.002;  // just above -pi: 0.002 + 0.001 rad away
  const auto nu = mptrack::gnn::polar_innovation(10.5, z_az, pred);
  CHECK(nu(0) == doctest::Approx(10.5 - std::hypot(10.0, 0.01)).epsilon(1e-12));
  CHECK(nu(1) == doctest::Approx(z_az + 2 * kPi - std::atan2(0.01, -10.0)).epsilon(1e-9));
  CHECK(std::fabs(nu(1)) < 0.01);
}

TEST_CASE("Joseph-form update equals the textbook EKF update in double") {
  Vec4 x(30.0, 1.0, 40.0, -2.0);
  Mat4 P = spd_example();
  const auto pred = mptrack::gnn::polar_predict(x, P, 0.2, 0.01);
  REQUIRE(pred.valid);
  const Eigen::Vector2d nu(0.3, -0.004);
  const Eigen::Matrix<double, 4, 2> K = P * pred.H.transpose() * pred.S.inverse();
  const Vec4 x_ref = x + K * nu;
  const Mat4 P_ref = (Mat4::Identity() - K * pred.H) * P;
  mptrack::gnn::polar_update(x, P, nu, pred, 0.2, 0.01);
  CHECK((x - x_ref).cwiseAbs().maxCoeff() < 1e-12);
  CHECK((P - P_ref).cwiseAbs().maxCoeff() < 1e-10);
}

TEST_CASE("polar_initiate puts the measurement at zero velocity with covariance J R J^T") {
  Vec4 x;
  Mat4 P;
  const double r = 50.0;
  const double az = 0.7;
  mptrack::gnn::polar_initiate(r, az, 0.2, 0.01, 10.0, x, P);
  CHECK(x(0) == doctest::Approx(r * std::cos(az)).epsilon(1e-14));
  CHECK(x(2) == doctest::Approx(r * std::sin(az)).epsilon(1e-14));
  CHECK(x(1) == 0.0);
  CHECK(x(3) == 0.0);
  Eigen::Matrix2d J;
  J << std::cos(az), -r * std::sin(az), std::sin(az), r * std::cos(az);
  const Eigen::Matrix2d C = J * Eigen::Vector2d(0.04, 1e-4).asDiagonal() * J.transpose();
  CHECK(P(0, 0) == doctest::Approx(C(0, 0)).epsilon(1e-12));
  CHECK(P(0, 2) == doctest::Approx(C(0, 1)).epsilon(1e-12));
  CHECK(P(2, 2) == doctest::Approx(C(1, 1)).epsilon(1e-12));
  CHECK(P(1, 1) == 100.0);
  CHECK(P(3, 3) == 100.0);
  CHECK(P(0, 1) == 0.0);
}

TEST_CASE("M-of-N logic: 3 hits in 5 confirms, a tentative track dies when 3 of 5 is out of reach") {
  mptrack::gnn::GnnTrack<float> t;
  mptrack::gnn::record_scan(t, true);   // birth
  mptrack::gnn::record_scan(t, true);
  CHECK_FALSE(mptrack::gnn::passes_confirmation(t, 3, 5));
  mptrack::gnn::record_scan(t, false);
  CHECK_FALSE(mptrack::gnn::should_delete(t, 3, 5, 5));  // 2 hits + 2 scans left
  mptrack::gnn::record_scan(t, true);
  CHECK(mptrack::gnn::passes_confirmation(t, 3, 5));
  mptrack::gnn::GnnTrack<float> u;
  mptrack::gnn::record_scan(u, true);
  mptrack::gnn::record_scan(u, false);
  mptrack::gnn::record_scan(u, false);
  CHECK_FALSE(mptrack::gnn::should_delete(u, 3, 5, 5));  // 1 hit + 2 left = 3
  mptrack::gnn::record_scan(u, false);
  CHECK(mptrack::gnn::should_delete(u, 3, 5, 5));  // 1 hit + 1 left < 3
  u.confirmed = true;  // a confirmed track survives until max_misses
  CHECK_FALSE(mptrack::gnn::should_delete(u, 3, 5, 5));
  CHECK(u.consecutive_misses == 3);
  mptrack::gnn::record_scan(u, false);
  mptrack::gnn::record_scan(u, false);
  CHECK(mptrack::gnn::should_delete(u, 3, 5, 5));
}
