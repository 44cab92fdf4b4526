// The MIMO atom model (model/mimo_atom.h) and the whitened spectrum
// (frontend/mimo_spectrum.h) against independent computations: finite
// differences of the materialised atom, direct inner products of length
// N_V K_B, and a noiseless echo synthesised sample by sample.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "mptrack/frontend/mimo_spectrum.h"
#include "mptrack/model/mimo_atom.h"
#include "mptrack/model/mimo_range_angle_map.h"

namespace {

using Caps = mptrack::frontend::Seed004RadarCaps;
using Spectrum = mptrack::frontend::MimoSpectrum<double, Caps>;
constexpr std::size_t kNV = Spectrum::kNumVirtual;
constexpr std::size_t kKB = Spectrum::kNumBins;
using Basis = mptrack::model::MimoAtomBasis<double, kNV, kKB>;
using Atom = mptrack::model::MimoAtom<double, kNV, kKB>;
using mptrack::model::Cx;

constexpr double kC = 299792458.0;
constexpr double kSigmaW2 = 1.380649e-23 * 290.0 * 32e6;  // model A noise [V^2]

struct Fixture {
  std::unique_ptr<Spectrum> spec = std::make_unique<Spectrum>();
  Basis basis;
  Fixture() {
    mptrack::frontend::MimoSpectrumConfig c;
    c.noise_variance_v2 = kSigmaW2;
    REQUIRE(spec->init(c) == mptrack::Status::kOk);
    basis.init(spec->u_re(), spec->u_im(), spec->f_hz(), 0.5, 2.0e4);
  }
};

// s as a dense vector (planar), from the separable factors.
void materialise(const Atom& at, std::vector<double>& re, std::vector<double>& im) {
  re.assign(kNV * kKB, 0.0);
  im.assign(kNV * kKB, 0.0);
  mptrack::model::atom_accumulate(at, Cx<double>{1.0, 0.0}, re.data(), im.data());
}

// Brute-force Jacobian column by central differences of the atom. frozen:
// rho~ held at the centre value.
void jacobian_column(const Basis& b, double x, double y, int axis, bool frozen, std::vector<double>& re,
                     std::vector<double>& im) {
  const double h = 1e-4;
  Atom c;
  mptrack::model::make_atom(b, x, y, -1.0, c);
  const double rho = frozen ? c.rho : -1.0;
  Atom p, m;
  mptrack::model::make_atom(b, x + (axis == 0 ? h : 0.0), y + (axis == 1 ? h : 0.0), rho, p);
  mptrack::model::make_atom(b, x - (axis == 0 ? h : 0.0), y - (axis == 1 ? h : 0.0), rho, m);
  std::vector<double> pr, pi, mr, mi;
  materialise(p, pr, pi);
  materialise(m, mr, mi);
  re.resize(pr.size());
  im.resize(pr.size());
  for (std::size_t i = 0; i < pr.size(); ++i) {
    re[i] = (pr[i] - mr[i]) / (2 * h);
    im[i] = (pi[i] - mi[i]) / (2 * h);
  }
}

// Re{a^H b}, a^H b.
Cx<double> dot(const std::vector<double>& ar, const std::vector<double>& ai, const std::vector<double>& br,
               const std::vector<double>& bi) {
  Cx<double> s{};
  for (std::size_t i = 0; i < ar.size(); ++i) {
    s.re += ar[i] * br[i] + ai[i] * bi[i];
    s.im += ar[i] * bi[i] - ai[i] * br[i];
  }
  return s;
}

void check_fisher(const Fixture& f, double x, double y, bool literal) {
  std::vector<double> jxr, jxi, jyr, jyi;
  jacobian_column(f.basis, x, y, 0, !literal, jxr, jxi);
  jacobian_column(f.basis, x, y, 1, !literal, jyr, jyi);
  Atom at;
  mptrack::model::make_atom(f.basis, x, y, -1.0, at);
  const auto b = mptrack::model::atom_fisher(f.basis, at, literal);
  const double bxx = dot(jxr, jxi, jxr, jxi).re;
  const double bxy = dot(jxr, jxi, jyr, jyi).re;
  const double byy = dot(jyr, jyi, jyr, jyi).re;
  const double scale = std::max(bxx, byy);
  CHECK(b(0, 0) == doctest::Approx(bxx).epsilon(1e-5));
  CHECK(b(1, 1) == doctest::Approx(byy).epsilon(1e-5));
  CHECK(std::abs(b(0, 1) - bxy) < 1e-5 * scale);
  CHECK(b(1, 0) == b(0, 1));
}

}  // namespace

TEST_CASE("MIMO atom: closed-form Fisher Re{J^H J} (frozen rho~) equals the brute-force product") {
  Fixture f;
  check_fisher(f, 20.4, 20.6, false);   // 45 deg, 29 m (the crossing)
  check_fisher(f, -8.0, 30.0, false);   // negative bearing
  check_fisher(f, 45.0, 12.0, false);   // 75 deg
}

TEST_CASE("MIMO atom: literal Fisher (rho~(r) differentiated) equals the brute-force product") {
  Fixture f;
  check_fisher(f, 10.0, 10.0, true);
  check_fisher(f, 30.0, 60.0, true);
}

TEST_CASE("MIMO atom: Jacobian projections J^H r equal finite differences of s^H r") {
  Fixture f;
  // An arbitrary residual: another atom plus a deterministic pattern.
  std::vector<double> rr(kNV * kKB), ri(kNV * kKB);
  for (std::size_t i = 0; i < rr.size(); ++i) {
    rr[i] = std::sin(0.37 * static_cast<double>(i));
    ri[i] = std::cos(0.11 * static_cast<double>(i * i % 97));
  }
  Atom other;
  mptrack::model::make_atom(f.basis, 20.0, 21.0, -1.0, other);
  mptrack::model::atom_accumulate(other, Cx<double>{0.3, -0.2}, rr.data(), ri.data());
  for (bool literal : {false, true}) {
    Atom at;
    mptrack::model::make_atom(f.basis, 20.4, 20.6, -1.0, at);
    const auto pr = mptrack::model::atom_project(f.basis, at, rr.data(), ri.data(), literal);
    const Cx<double> s0 = mptrack::model::atom_inner(at, rr.data(), ri.data());
    CHECK(pr.s.re == doctest::Approx(s0.re).epsilon(1e-12));
    CHECK(pr.s.im == doctest::Approx(s0.im).epsilon(1e-12));
    for (int axis = 0; axis < 2; ++axis) {
      std::vector<double> jr, ji;
      jacobian_column(f.basis, 20.4, 20.6, axis, !literal, jr, ji);
      const Cx<double> fd = dot(jr, ji, rr, ri);
      const Cx<double> an = axis == 0 ? pr.jx : pr.jy;
      const double scale = std::sqrt(mptrack::model::cx_norm2(fd));
      CHECK(std::abs(an.re - fd.re) < 1e-5 * scale);
      CHECK(std::abs(an.im - fd.im) < 1e-5 * scale);
    }
  }
}

TEST_CASE("MIMO atom: separable Gram s1^H s2 equals the direct inner product") {
  Fixture f;
  const double pts[][4] = {{20.4, 20.6, 20.2, 20.9}, {10.0, 31.0, 14.0, 14.0}, {-5.0, 40.0, 30.0, 25.0}};
  for (const auto& p : pts) {
    Atom a1, a2;
    mptrack::model::make_atom(f.basis, p[0], p[1], -1.0, a1);
    mptrack::model::make_atom(f.basis, p[2], p[3], -1.0, a2);
    std::vector<double> s2r, s2i;
    materialise(a2, s2r, s2i);
    const Cx<double> direct = mptrack::model::atom_inner(a1, s2r.data(), s2i.data());
    const Cx<double> closed = mptrack::model::atom_gram(f.basis, a1, a2);
    const double scale = mptrack::model::atom_norm2(f.basis, a1) + mptrack::model::atom_norm2(f.basis, a2);
    CHECK(std::abs(closed.re - direct.re) < 1e-10 * scale);
    CHECK(std::abs(closed.im - direct.im) < 1e-10 * scale);
  }
  // ||s||^2 closed form.
  Atom a;
  mptrack::model::make_atom(f.basis, 12.0, 25.0, -1.0, a);
  std::vector<double> sr, si;
  materialise(a, sr, si);
  CHECK(mptrack::model::atom_norm2(f.basis, a) == doctest::Approx(dot(sr, si, sr, si).re).epsilon(1e-12));
}

TEST_CASE("MIMO spectrum: a noiseless echo gives s^H z = ||s||^2 at the truth") {
  Fixture f;
  // Echo of amplitude A0 [V] at (x, y), synthesised as the ADC would see it:
  // y_v[i] = A0 a_v u(i / f_s - tau), u(t) = exp(j pi kappa (t - t_mid)^2) on the chirp.
  const double x = 17.3, y = 23.9;
  const double r = std::sqrt(x * x + y * y);
  const double tau = 2 * r / kC;
  const double fs = 32e6, kappa = 20e6 / 3.6e-6;
  const std::size_t len = 115;  // round(3.6 us * 32 MHz)
  const double t_mid = 0.5 * static_cast<double>(len - 1) / fs;
  const double a0 = 3e-6;
  mptrack::frontend::RadarCube<Caps> cube;
  for (std::size_t v = 0; v < kNV; ++v) {
    const double ph = 3.141592653589793 * (static_cast<double>(v) - 4.0) * (x / r);
    for (std::size_t i = 0; i < Caps::kNumSamples; ++i) {
      const double t = static_cast<double>(i) / fs - tau;
      if (t < -0.5 / fs || !(t < (static_cast<double>(len) - 0.5) / fs)) continue;
      const double q = 3.141592653589793 * kappa * (t - t_mid) * (t - t_mid) + ph;
      const std::size_t o = mptrack::frontend::RadarCube<Caps>::offset(0, v / 3, v % 3, i);
      cube.iq[o] = static_cast<float>(a0 * std::cos(q));
      cube.iq[o + 1] = static_cast<float>(a0 * std::sin(q));
    }
  }
  REQUIRE(f.spec->process(cube) == mptrack::Status::kOk);
  Atom at;
  mptrack::model::make_atom(f.basis, x, y, a0 / std::sqrt(kSigmaW2), at);
  const Cx<double> c = mptrack::model::atom_inner(at, f.spec->z_re(), f.spec->z_im());
  const double n2 = mptrack::model::atom_norm2(f.basis, at);
  // In-band truncation (99.4 % of the chirp energy) and the fractional delay
  // leave the match within 1 %.
  CHECK(c.re == doctest::Approx(n2).epsilon(0.01));
  CHECK(std::abs(c.im) < 0.01 * n2);
  // E_U: the chirp energy is L samples, 99 % of it in band.
  CHECK(f.basis.e_u() > 0.99 * static_cast<double>(len) * 0.99);
  CHECK(f.basis.e_u() < static_cast<double>(len));

  // The residual map finds the echo within one grid cell.
  mptrack::model::MimoRangeAngleMap<double, kNV, kKB, 96, 64> map;
  REQUIRE(map.init(f.basis, 3.0, 100.0, 1.17, 0.97, 1.0 / 32.0));
  map.evaluate(f.basis, f.spec->z_re(), f.spec->z_im());
  const auto pk = map.best([](double, double, double p) { return p; });
  REQUIRE(pk.found);
  CHECK(std::abs(pk.range_m - r) < 1.17);
  CHECK(std::abs(pk.sin_t - x / r) < 1.0 / 32.0);
  // The one-call form agrees, and an exclusion around the peak moves it.
  const auto pk2 = map.best(f.basis, f.spec->z_re(), f.spec->z_im(), [](double, double, double p) { return p; });
  CHECK(pk2.range_m == pk.range_m);
  CHECK(pk2.sin_t == pk.sin_t);
  const auto pk3 = map.best([](double, double, double p) { return p; }, &pk, 1, 3.75, 1.0 / 9.0);
  REQUIRE(pk3.found);
  CHECK((std::abs(pk3.range_m - pk.range_m) >= 3.75 || std::abs(pk3.sin_t - pk.sin_t) >= 1.0 / 9.0));
  CHECK(pk3.beam_power < pk.beam_power);
}

TEST_CASE("MIMO range/angle map: every cell's beam power equals |s^H r|^2 / rho~^2 of the atom on that cell") {
  // A float map (the board's) against the double atom inner product: the
  // phasor recurrence between exact re-seeds must stay within float rounding.
  Fixture f;
  std::vector<double> re(kNV * kKB), im(kNV * kKB);
  for (std::size_t i = 0; i < re.size(); ++i) {  // a deterministic, non-trivial residual
    re[i] = std::cos(0.37 * static_cast<double>(i)) + 0.2 * std::sin(0.011 * static_cast<double>(i * i));
    im[i] = std::sin(0.53 * static_cast<double>(i)) - 0.1 * std::cos(0.007 * static_cast<double>(i * i));
  }
  using BasisF = mptrack::model::MimoAtomBasis<float, kNV, kKB>;
  std::vector<float> u_re(kKB), u_im(kKB), fk(kKB), rf(re.size()), imf(im.size());
  for (std::size_t k = 0; k < kKB; ++k) {
    u_re[k] = static_cast<float>(f.spec->u_re()[k]);
    u_im[k] = static_cast<float>(f.spec->u_im()[k]);
    fk[k] = static_cast<float>(f.spec->f_hz()[k]);
  }
  for (std::size_t i = 0; i < re.size(); ++i) {
    rf[i] = static_cast<float>(re[i]);
    imf[i] = static_cast<float>(im[i]);
  }
  BasisF bf;
  bf.init(u_re.data(), u_im.data(), fk.data(), 0.5f, 2.0e4f);
  mptrack::model::MimoRangeAngleMap<float, kNV, kKB, 96, 64> map;
  REQUIRE(map.init(bf, 3.0f, 100.0f, 1.17f, 0.97f, 1.0f / 32.0f));
  int cells = 0;
  double worst = 0.0;
  (void)map.best(bf, rf.data(), imf.data(), [&](float r, float u, float p) {
    const double rd = static_cast<double>(r), ud = static_cast<double>(u);
    Atom at;
    mptrack::model::make_atom(f.basis, rd * ud, rd * std::sqrt(1.0 - ud * ud), -1.0, at);
    const Cx<double> c = mptrack::model::atom_inner(at, re.data(), im.data());
    const double direct = (c.re * c.re + c.im * c.im) / (at.rho * at.rho);
    // Relative to the cell's scale: the map's float sum over N_V K_B terms.
    const double scale = static_cast<double>(kNV * kKB) * 115.0;
    worst = std::max(worst, std::abs(static_cast<double>(p) - direct) / scale);
    ++cells;
    return p;
  });
  CHECK(cells == static_cast<int>(map.range_cells() * map.angle_cells()));
  CHECK(worst < 1e-6);  // measured 6e-8
}
