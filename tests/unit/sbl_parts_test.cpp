// Parts of the SBL detector against independent computations in the whitened
// domain: the joint Gauss-Newton normal equations (sbl/joint_gauss_newton.h)
// against a finite-difference Jacobian of the materialised model, and the
// single-component refinement (sbl/position_refine.h) on a noiseless atom.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "mptrack/frontend/mimo_spectrum.h"
#include "mptrack/model/mimo_atom.h"
#include "mptrack/sbl/joint_gauss_newton.h"
#include "mptrack/sbl/position_refine.h"

namespace {

using Caps = mptrack::frontend::Seed004RadarCaps;
using Spectrum = mptrack::frontend::MimoSpectrum<double, Caps>;
constexpr std::size_t kNV = Spectrum::kNumVirtual;
constexpr std::size_t kKB = Spectrum::kNumBins;
constexpr std::size_t kN = kNV * kKB;
using Basis = mptrack::model::MimoAtomBasis<double, kNV, kKB>;
using Atom = mptrack::model::MimoAtom<double, kNV, kKB>;
using mptrack::model::Cx;
using Vec = std::vector<Cx<double>>;

struct Fixture {
  std::unique_ptr<Spectrum> spec = std::make_unique<Spectrum>();
  Basis basis;
  Fixture() {
    mptrack::frontend::MimoSpectrumConfig c;
    c.noise_variance_v2 = 1.380649e-23 * 290.0 * 32e6;
    REQUIRE(spec->init(c) == mptrack::Status::kOk);
    basis.init(spec->u_re(), spec->u_im(), spec->f_hz(), 0.5, 2.0e4);
  }
};

// coef * s(x, y) with rho~ held at rho, as a dense vector.
Vec atom_vec(const Basis& b, double x, double y, double rho, Cx<double> coef) {
  Atom at;
  mptrack::model::make_atom(b, x, y, rho, at);
  std::vector<double> re(kN, 0.0), im(kN, 0.0);
  mptrack::model::atom_accumulate(at, coef, re.data(), im.data());
  Vec v(kN);
  for (std::size_t i = 0; i < kN; ++i) v[i] = {re[i], im[i]};
  return v;
}

double re_dot(const Vec& a, const Vec& b) {
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i].re * b[i].re + a[i].im * b[i].im;
  return s;
}

}  // namespace

TEST_CASE("SBL joint Gauss-Newton: normal matrix and gradient equal Re{D^H D}, Re{D^H e} of a brute-force Jacobian") {
  Fixture f;
  const double px[2] = {14.2, 15.9}, py[2] = {25.0, 26.3};
  const Cx<double> mu[2] = {{0.8, -0.4}, {-0.3, 1.1}};
  const double gamma[2] = {0.7, 2.5};
  Atom atoms[2];
  for (int k = 0; k < 2; ++k) mptrack::model::make_atom(f.basis, px[k], py[k], -1.0, atoms[k]);
  // An arbitrary residual e.
  std::vector<double> er(kN), ei(kN);
  for (std::size_t i = 0; i < kN; ++i) {
    er[i] = std::sin(0.31 * static_cast<double>(i));
    ei[i] = std::cos(0.017 * static_cast<double>(i * i % 101));
  }
  Vec e(kN);
  for (std::size_t i = 0; i < kN; ++i) e[i] = {er[i], ei[i]};
  // Columns of D = d(sum mu_k s_k)/d(Re mu_k, Im mu_k, x_k, y_k), rho~ frozen.
  std::vector<Vec> cols;
  const double h = 1e-5;
  for (int k = 0; k < 2; ++k) {
    const double rho = atoms[k].rho;
    cols.push_back(atom_vec(f.basis, px[k], py[k], rho, {1.0, 0.0}));
    cols.push_back(atom_vec(f.basis, px[k], py[k], rho, {0.0, 1.0}));
    for (int axis = 0; axis < 2; ++axis) {
      const Vec p = atom_vec(f.basis, px[k] + (axis == 0 ? h : 0.0), py[k] + (axis == 1 ? h : 0.0), rho, mu[k]);
      const Vec m = atom_vec(f.basis, px[k] - (axis == 0 ? h : 0.0), py[k] - (axis == 1 ? h : 0.0), rho, mu[k]);
      Vec d(kN);
      for (std::size_t i = 0; i < kN; ++i) d[i] = {(p[i].re - m[i].re) / (2 * h), (p[i].im - m[i].im) / (2 * h)};
      cols.push_back(d);
    }
  }
  auto gn = std::make_unique<mptrack::sbl::JointGaussNewton<double, kNV, kKB, 4>>();
  gn->linearise(f.basis, atoms, mu, gamma, 2, er.data(), ei.data());
  for (std::size_t i = 0; i < 8; ++i) {
    const double diag_scale = std::sqrt(re_dot(cols[i], cols[i]));
    double g = re_dot(cols[i], e);
    if (i % 4 == 0) g -= gamma[i / 4] * mu[i / 4].re;
    if (i % 4 == 1) g -= gamma[i / 4] * mu[i / 4].im;
    CHECK(std::abs(gn->gradient(i) - g) < 1e-6 * diag_scale * std::sqrt(re_dot(e, e)));
    for (std::size_t j = 0; j <= i; ++j) {
      double n = re_dot(cols[i], cols[j]);
      if (i == j && i % 4 < 2) n += gamma[i / 4];
      const double scale = diag_scale * std::sqrt(re_dot(cols[j], cols[j]));
      CHECK(std::abs(gn->normal(i, j) - n) < 1e-6 * scale);
    }
  }
}

TEST_CASE("SBL refinement: a noiseless atom is found from 0.6 m away, concentrated and with known amplitude") {
  Fixture f;
  const double x0 = -12.0, y0 = 33.0;
  Atom truth;
  mptrack::model::make_atom(f.basis, x0, y0, -1.0, truth);
  const Cx<double> alpha{0.6, 0.9};
  std::vector<double> zr(kN, 0.0), zi(kN, 0.0);
  mptrack::model::atom_accumulate(truth, alpha, zr.data(), zi.data());
  mptrack::sbl::RefineLimits<double> lim;
  lim.steps = 20;
  lim.tolerance_m = 1e-9;
  for (bool concentrated : {true, false}) {
    Atom at;
    mptrack::model::make_atom(f.basis, x0 + 0.5, y0 - 0.35, truth.rho, at);  // same frozen rho~
    const double moved = mptrack::sbl::refine_position(f.basis, at, zr.data(), zi.data(), alpha,
                                                       mptrack::model::cx_norm2(alpha), concentrated, lim);
    CHECK(moved == doctest::Approx(std::hypot(0.5, 0.35)).epsilon(1e-6));
    CHECK(std::abs(at.x - x0) < 1e-6);
    CHECK(std::abs(at.y - y0) < 1e-6);
  }
}

TEST_CASE("SBL: the Gram entry from stored factors equals the closed-form separable Gram") {
  Fixture f;
  Atom a1, a2;
  mptrack::model::make_atom(f.basis, 14.2, 25.0, -1.0, a1);
  mptrack::model::make_atom(f.basis, -3.0, 41.0, -1.0, a2);
  for (const Atom* b : {&a1, &a2}) {
    const Cx<double> direct = mptrack::sbl::gram_from_factors(a1, *b);
    const Cx<double> closed = mptrack::model::atom_gram(f.basis, a1, *b);
    const double scale = mptrack::model::atom_norm2(f.basis, a1);
    CHECK(std::abs(direct.re - closed.re) < 1e-12 * scale);
    CHECK(std::abs(direct.im - closed.im) < 1e-12 * scale);
  }
}
