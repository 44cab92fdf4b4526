// The complex Cholesky and joint amplitude posterior (model/joint_amplitude.h)
// against Eigen's dense complex algebra (an independent implementation).
#include <doctest/doctest.h>

#include <complex>

#include <Eigen/Dense>

#include "mptrack/model/joint_amplitude.h"

namespace {

using mptrack::Status;
std::size_t u(int i) { return static_cast<std::size_t>(i); }
using mptrack::model::Cx;
using CMat = Eigen::Matrix<std::complex<double>, Eigen::Dynamic, Eigen::Dynamic>;

// A Hermitian positive definite matrix: A = G G^H + diag, G a fixed pattern.
CMat make_spd(int n) {
  CMat g(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) g(i, j) = {std::sin(1.3 * i + 0.7 * j), std::cos(0.4 * i * j + 0.2)};
  }
  CMat a = g * g.adjoint();
  for (int i = 0; i < n; ++i) a(i, i) += 0.5;
  return a;
}

template <std::size_t K>
void load(mptrack::model::JointAmplitude<double, K>& ja, const CMat& a) {
  REQUIRE(ja.reset(static_cast<std::size_t>(a.rows())) == Status::kOk);
  for (int i = 0; i < a.rows(); ++i) {
    for (int j = 0; j <= i; ++j) ja.lambda(u(i), u(j)) = Cx<double>{a(i, j).real(), a(i, j).imag()};
  }
}

}  // namespace

TEST_CASE("joint amplitude: mu = Lambda^-1 b, C = Lambda^-1 and ln|Lambda| match Eigen") {
  for (int n : {1, 2, 5}) {
    const CMat a = make_spd(n);
    Eigen::VectorXcd b(n);
    Cx<double> bc[8];
    for (int i = 0; i < n; ++i) {
      b(i) = {0.3 * i - 1.0, 0.5 + 0.1 * i * i};
      bc[u(i)] = {b(i).real(), b(i).imag()};
    }
    mptrack::model::JointAmplitude<double, 8> ja;
    load(ja, a);
    REQUIRE(ja.solve(bc) == Status::kOk);
    const Eigen::VectorXcd mu = a.ldlt().solve(b);
    const CMat inv = a.inverse();
    for (int i = 0; i < n; ++i) {
      CHECK(ja.mu(u(i)).re == doctest::Approx(mu(i).real()).epsilon(1e-10));
      CHECK(ja.mu(u(i)).im == doctest::Approx(mu(i).imag()).epsilon(1e-10));
      for (int j = 0; j < n; ++j) {
        CHECK(std::abs(ja.cov(u(i), u(j)).re - inv(i, j).real()) < 1e-10 * std::abs(inv(i, i)));
        CHECK(std::abs(ja.cov(u(i), u(j)).im - inv(i, j).imag()) < 1e-10 * std::abs(inv(i, i)));
      }
      CHECK(ja.cov(u(i), u(i)).im == 0.0);
    }
    CHECK(ja.log_det() == doctest::Approx(std::log(a.determinant().real())).epsilon(1e-10));
  }
}

TEST_CASE("joint amplitude: the factor satisfies L L^H = Lambda with a real positive diagonal") {
  const CMat a = make_spd(4);
  mptrack::model::JointAmplitude<double, 4> ja;
  load(ja, a);
  Cx<double> b[4] = {};
  REQUIRE(ja.solve(b) == Status::kOk);
  CMat l = CMat::Zero(4, 4);
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j <= i; ++j) l(i, j) = {ja.factor(u(i), u(j)).re, ja.factor(u(i), u(j)).im};
    CHECK(ja.factor(u(i), u(i)).re > 0.0);
    CHECK(ja.factor(u(i), u(i)).im == 0.0);
  }
  CHECK((l * l.adjoint() - a).norm() < 1e-12 * a.norm());
}

TEST_CASE("joint amplitude: a non-positive-definite precision and an oversize reset are refused") {
  mptrack::model::JointAmplitude<double, 2> ja;
  CHECK(ja.reset(3) == Status::kCapacityExceeded);
  REQUIRE(ja.reset(2) == Status::kOk);
  ja.lambda(0, 0) = {1.0, 0.0};
  ja.lambda(1, 0) = {2.0, 0.0};  // |off-diagonal| > diagonal: indefinite
  ja.lambda(1, 1) = {1.0, 0.0};
  Cx<double> b[2] = {};
  CHECK(ja.solve(b) == Status::kNumericalError);
}
