// Building blocks of the MF-BP tracker (seed 000): amplitude model, IG
// belief, cubature moments, loopy BP against exact enumeration, visibility
// HMM against brute force, Normal-Wishart update against Bishop 10.60-10.63.
#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <vector>

#include <Eigen/LU>

#include "mptrack/mfbp/amplitude_model.h"
#include "mptrack/mfbp/association_bp.h"
#include "mptrack/mfbp/cubature.h"
#include "mptrack/mfbp/normal_wishart.h"
#include "mptrack/mfbp/target_filter.h"
#include "mptrack/mfbp/visibility_hmm.h"
#include "mptrack/model/cholesky.h"
#include "mptrack/model/inverse_gamma.h"

using namespace mptrack;
using namespace mptrack::mfbp;

TEST_CASE("mfbp Pd Swerling I equals exp(-d^2/(1+snr)) and matches hand-computed values") {
  const double d = 0.715;
  // exp(-d^2 / (1 + snr)) by hand (d = 0.715, n = 1): snr 0 -> 0.600, 1 -> 0.774, 10/3 -> 0.889, 30 -> 0.984
  CHECK(detection_probability(1.0 + 0.0, d, 1, PdModel::kExact) == doctest::Approx(0.600).epsilon(0.002));
  CHECK(detection_probability(1.0 + 1.0, d, 1, PdModel::kExact) == doctest::Approx(0.774).epsilon(0.002));
  CHECK(detection_probability(1.0 + 10.0 / 3.0, d, 1, PdModel::kExact) == doctest::Approx(0.889).epsilon(0.002));
  CHECK(detection_probability(1.0 + 30.0, d, 1, PdModel::kExact) == doctest::Approx(0.984).epsilon(0.002));
  CHECK(detection_probability(1.0 + 1.0, d, 1, PdModel::kPaper) ==
        doctest::Approx(std::exp(-d * d / 2.0)).epsilon(1e-12));
}

TEST_CASE("mfbp Pd Swerling III exact Gamma(2) tail vs the paper approximation") {
  const double d = 0.715;
  // docs/algorithms/models.md §Detection probability: at SNR 10/3 the paper gives 0.790,
  // the exact form 0.976.
  CHECK(detection_probability(1.0 + 10.0 / 3.0, d, 2, PdModel::kExact) == doctest::Approx(0.976).epsilon(0.002));
  CHECK(detection_probability(1.0 + 10.0 / 3.0, d, 2, PdModel::kPaper) == doctest::Approx(0.790).epsilon(0.002));
  // float agrees with double
  CHECK(detection_probability(1.0f + 10.0f / 3.0f, 0.715f, 2, PdModel::kExact) ==
        doctest::Approx(0.976).epsilon(0.002));
}

TEST_CASE("mfbp expected amplitude log-likelihood equals -n(ln b - psi(a)) - n(m^2-d^2)a/b") {
  // a = 3, b = 4: psi(3) = 3/2 - gamma_Euler = 0.9227843350984671.
  const double e_log = std::log(4.0) - 0.9227843350984671;
  const double want = -e_log - (4.0 - 0.715 * 0.715) * 0.75;
  CHECK(expected_amplitude_loglik(2.0, 0.715, 3.0, 4.0, 1, AmpLoglik::kExact) ==
        doctest::Approx(want).epsilon(1e-9));
  // n = 2 doubles both terms
  CHECK(expected_amplitude_loglik(2.0, 0.715, 3.0, 4.0, 2, AmpLoglik::kExact) ==
        doctest::Approx(2.0 * want).epsilon(1e-9));
}

TEST_CASE("mfbp IG forgetting keeps the mean and the conjugate update converges to the true power") {
  model::InverseGamma<double> ig;
  ig.a = 3.0;
  ig.b = 8.0;  // mean 4
  const auto p = ig.predicted(1.05);
  CHECK(p.mean() == doctest::Approx(4.0).epsilon(1e-12));
  CHECK(p.a < ig.a);
  // Fully assigned Swerling-I measurements: E[m^2 - d^2] = varsigma for the
  // truncated exponential power, so feed the expectation varsigma = 5.
  for (int k = 0; k < 2000; ++k) ig.update(1.0, 5.0);
  CHECK(ig.mean() == doctest::Approx(5.0).epsilon(2e-3));
  CHECK(ig.snr() == doctest::Approx(4.0).epsilon(3e-3));
}

TEST_CASE("mfbp cubature moments match the linearised polar map for a small covariance") {
  Vec4<double> x(10000.0, 5.0, 3000.0, -2.0);
  Mat4<double> P = Mat4<double>::Zero();
  P.diagonal() << 4.0, 1.0, 9.0, 1.0;
  Vec2<double> z;
  Mat2<double> Sz;
  Mat42<double> C;
  REQUIRE(cubature_polar_moments(x, P, z, Sz, C));
  const double r = std::hypot(x(0), x(2));
  CHECK(z(0) == doctest::Approx(r).epsilon(1e-6));  // + curvature bias ~ var/(2r)
  CHECK(z(1) == doctest::Approx(std::atan2(x(2), x(0))).epsilon(1e-8));
  Eigen::Matrix<double, 2, 4> H = Eigen::Matrix<double, 2, 4>::Zero();
  H(0, 0) = x(0) / r;
  H(0, 2) = x(2) / r;
  H(1, 0) = -x(2) / (r * r);
  H(1, 2) = x(0) / (r * r);
  const Mat2<double> S_lin = H * P * H.transpose();
  const Mat42<double> C_lin = P * H.transpose();
  CHECK(Sz(0, 0) == doctest::Approx(S_lin(0, 0)).epsilon(1e-3));
  CHECK(Sz(1, 1) == doctest::Approx(S_lin(1, 1)).epsilon(1e-3));
  CHECK(Sz(0, 1) == doctest::Approx(S_lin(0, 1)).epsilon(1e-2));
  CHECK(C(0, 0) == doctest::Approx(C_lin(0, 0)).epsilon(1e-3));
  CHECK(C(2, 1) == doctest::Approx(C_lin(2, 1)).epsilon(1e-3));
}

TEST_CASE("mfbp cubature update with a linear-looking case equals the Kalman update") {
  // Target on the +x axis: range ~ px, azimuth ~ py / r, so the update is
  // close to a linear Kalman update with H = [[1,0,0,0],[0,0,1/r,0]].
  Vec4<double> x(20000.0, 0.0, 0.0, 0.0);
  Mat4<double> P = Mat4<double>::Identity() * 100.0;
  Mat2<double> R = Mat2<double>::Zero();
  R(0, 0) = 400.0;
  R(1, 1) = 1e-6;
  Vec2<double> y(20010.0, 0.0005);
  Vec4<double> xk = x;
  Mat4<double> Pk = P;
  CHECK_FALSE(cubature_update(xk, Pk, y, R));
  // Linear Kalman
  const double r = 20000.0;
  Eigen::Matrix<double, 2, 4> H = Eigen::Matrix<double, 2, 4>::Zero();
  H(0, 0) = 1.0;
  H(1, 2) = 1.0 / r;
  const Mat2<double> S = H * P * H.transpose() + R;
  const Eigen::Matrix<double, 4, 2> K = P * H.transpose() * S.inverse();
  const Vec4<double> x_lin = x + K * (y - Vec2<double>(r, 0.0));
  CHECK(xk(0) == doctest::Approx(x_lin(0)).epsilon(1e-4));
  CHECK(xk(2) == doctest::Approx(x_lin(2)).epsilon(1e-3));
  CHECK(Pk(0, 0) == doctest::Approx(80.0).epsilon(1e-3));  // 100*400/500
}

TEST_CASE("mfbp RTS with zero process noise and no data reproduces the filtered state") {
  Vec4<double> xf(100.0, 10.0, -50.0, 2.0);
  Mat4<double> Pf = Mat4<double>::Identity();
  Vec4<double> xs;
  Mat4<double> Ps;
  Vec4<double> xn = xf;
  Mat4<double> Pn = Pf;
  CHECK_FALSE(cv_predict(xn, Pn, 1.25, 0.01));
  CHECK_FALSE(rts_step(xf, Pf, xn, Pn, 1.25, 0.01, xs, Ps));
  for (int i = 0; i < 4; ++i) CHECK(xs(i) == doctest::Approx(xf(i)).epsilon(1e-9));
  CHECK(Ps(0, 0) == doctest::Approx(1.0).epsilon(1e-9));
}

namespace {

struct BpCase {
  std::size_t nt = 0, nc = 0, nm = 0;  // nc includes the uniform (source 0)
  std::vector<double> theta_t0;        // nt
  std::vector<std::vector<double>> theta_t;  // nt x nm (linear; 0 = not gated)
  std::vector<std::vector<double>> theta_c;  // nc x nm (linear)
  std::vector<double> theta_c0;              // nc (theta_c0[0] = 0)
};

struct Marginals {
  std::vector<std::vector<double>> t;  // nt x (nm + 1), column 0 = missed
  std::vector<std::vector<double>> c;  // nc x nm
  std::vector<double> c0;              // nc
};

// Exact marginals by enumerating every feasible association (the brute-force reference
// the BP marginals are checked against).
Marginals enumerate(const BpCase& bc) {
  Marginals m;
  m.t.assign(bc.nt, std::vector<double>(bc.nm + 1, 0.0));
  m.c.assign(bc.nc, std::vector<double>(bc.nm, 0.0));
  m.c0.assign(bc.nc, 0.0);
  const std::size_t ns = bc.nt + bc.nc;
  std::vector<std::size_t> src(bc.nm, 0);
  double total = 0.0;
  for (;;) {
    bool feasible = true;
    std::vector<int> used_t(bc.nt, 0), used_c(bc.nc, 0);
    double w = 1.0;
    for (std::size_t j = 0; j < bc.nm && feasible; ++j) {
      if (src[j] < bc.nt) {
        if (used_t[src[j]]++) feasible = false;
        w *= bc.theta_t[src[j]][j];
      } else {
        used_c[src[j] - bc.nt]++;
        w *= bc.theta_c[src[j] - bc.nt][j];
      }
    }
    if (feasible && w > 0.0) {
      for (std::size_t i = 0; i < bc.nt; ++i) w *= used_t[i] ? 1.0 : bc.theta_t0[i];
      for (std::size_t c = 1; c < bc.nc; ++c) w *= used_c[c] ? 1.0 : (1.0 + bc.theta_c0[c]);
      total += w;
      for (std::size_t i = 0; i < bc.nt; ++i) {
        if (!used_t[i]) m.t[i][0] += w;
      }
      for (std::size_t j = 0; j < bc.nm; ++j) {
        if (src[j] < bc.nt) {
          m.t[src[j]][j + 1] += w;
        } else {
          m.c[src[j] - bc.nt][j] += w;
        }
      }
      for (std::size_t c = 1; c < bc.nc; ++c) {
        if (!used_c[c]) m.c0[c] += w * bc.theta_c0[c] / (1.0 + bc.theta_c0[c]);
      }
    }
    std::size_t pos = 0;
    while (pos < bc.nm && ++src[pos] == ns) src[pos++] = 0;
    if (pos == bc.nm) break;
  }
  for (auto& row : m.t) for (auto& v : row) v /= total;
  for (auto& row : m.c) for (auto& v : row) v /= total;
  for (auto& v : m.c0) v /= total;
  return m;
}

double max_bp_error(const BpCase& bc, double damping, std::size_t* iterations) {
  static AssociationBp<double, 4, 8, 4, 32> bp;  // static: the object is large
  REQUIRE(bp.reset(bc.nm, bc.nc) == Status::kOk);
  for (std::size_t c = 0; c < bc.nc; ++c) {
    bp.set_clutter_absent(c, bc.theta_c0[c]);
    for (std::size_t j = 0; j < bc.nm; ++j) {
      if (bc.theta_c[c][j] > 0.0) bp.set_clutter_log(c, j, std::log(bc.theta_c[c][j]));
    }
  }
  for (std::size_t i = 0; i < bc.nt; ++i) {
    REQUIRE(bp.add_target(bc.theta_t0[i]) == Status::kOk);
    for (std::size_t j = 0; j < bc.nm; ++j) {
      if (bc.theta_t[i][j] > 0.0) REQUIRE(bp.add_edge(j, std::log(bc.theta_t[i][j])) == Status::kOk);
    }
  }
  const auto res = bp.run(damping, 1e-9, 5000);
  *iterations = res.iterations;
  CHECK(res.converged);
  const Marginals ex = enumerate(bc);
  double err = 0.0;
  for (std::size_t i = 0; i < bc.nt; ++i) {
    err = std::max(err, std::fabs(bp.missed_belief(i) - ex.t[i][0]));
    for (std::size_t e = bp.edge_begin(i); e < bp.edge_end(i); ++e) {
      err = std::max(err, std::fabs(bp.edge_belief(e) - ex.t[i][bp.edge_meas(e) + 1]));
    }
  }
  for (std::size_t c = 0; c < bc.nc; ++c) {
    for (std::size_t j = 0; j < bc.nm; ++j) err = std::max(err, std::fabs(bp.clutter_belief(c, j) - ex.c[c][j]));
    if (c > 0) err = std::max(err, std::fabs(bp.clutter_absent_belief(c) - ex.c0[c]));
  }
  // Beliefs are normalised: each target's row and each measurement's column sum to 1.
  for (std::size_t i = 0; i < bc.nt; ++i) {
    double s = bp.missed_belief(i);
    for (std::size_t e = bp.edge_begin(i); e < bp.edge_end(i); ++e) s += bp.edge_belief(e);
    CHECK(s == doctest::Approx(1.0).epsilon(1e-9));
  }
  return err;
}

BpCase spec_case() {
  BpCase bc;
  bc.nt = 2;
  bc.nc = 3;
  bc.nm = 4;
  bc.theta_t0 = {0.3, 0.8};
  bc.theta_t = {{2.0, 0.7, 0.0, 0.1}, {0.5, 1.5, 0.9, 0.0}};
  bc.theta_c = {{0.2, 0.2, 0.2, 0.2}, {0.6, 0.05, 0.0, 0.4}, {0.0, 0.3, 0.8, 0.5}};
  bc.theta_c0 = {0.0, 1.0, 1.0};
  return bc;
}

}  // namespace

// Loopy BP is approximate. This case is deliberately ambiguous (every
// target has 3 plausible measurements and competes with 2 components);
// the largest marginal error measured is 0.0221, so the bound is 0.025.
TEST_CASE("mfbp loopy BP marginals match exact enumeration (2 targets, 2 components + uniform, 4 meas)") {
  std::size_t it = 0;
  const double err = max_bp_error(spec_case(), 0.5, &it);
  CHECK(err <= 0.025);
  CHECK(it > 1);
}

TEST_CASE("mfbp loopy BP with the paper damping 0.9 reaches the same fixed point") {
  std::size_t it = 0;
  CHECK(max_bp_error(spec_case(), 0.9, &it) <= 0.025);
}

TEST_CASE("mfbp BP without targets matches the exact mixture") {
  BpCase bc = spec_case();
  bc.nt = 0;
  bc.theta_t0.clear();
  bc.theta_t.clear();
  std::size_t it = 0;
  // Components and measurements still form loops (each component sees every
  // measurement), so BP is approximate; measured error 2.6e-4.
  CHECK(max_bp_error(bc, 0.5, &it) <= 1e-3);
}

TEST_CASE("mfbp BP on a well-separated case (each target has one dominant measurement)") {
  BpCase bc = spec_case();
  bc.theta_t = {{6.0, 0.1, 0.0, 0.05}, {0.1, 0.05, 5.0, 0.0}};
  std::size_t it = 0;
  CHECK(max_bp_error(bc, 0.9, &it) <= 0.02);
}

TEST_CASE("mfbp BP without non-uniform clutter (pure one-to-one) matches enumeration") {
  BpCase bc = spec_case();
  bc.nc = 1;
  bc.theta_c.resize(1);
  bc.theta_c0.resize(1);
  std::size_t it = 0;
  // Same one-to-one BP as Williams & Lau; measured error 0.0219.
  CHECK(max_bp_error(bc, 0.5, &it) <= 0.025);
}

TEST_CASE("mfbp BP in float stays within 1e-4 of double") {
  static AssociationBp<float, 4, 8, 4, 32> bpf;
  static AssociationBp<double, 4, 8, 4, 32> bpd;
  const BpCase bc = spec_case();
  REQUIRE(bpf.reset(bc.nm, bc.nc) == Status::kOk);
  REQUIRE(bpd.reset(bc.nm, bc.nc) == Status::kOk);
  for (std::size_t c = 0; c < bc.nc; ++c) {
    bpf.set_clutter_absent(c, static_cast<float>(bc.theta_c0[c]));
    bpd.set_clutter_absent(c, bc.theta_c0[c]);
    for (std::size_t j = 0; j < bc.nm; ++j) {
      if (bc.theta_c[c][j] > 0.0) {
        bpf.set_clutter_log(c, j, static_cast<float>(std::log(bc.theta_c[c][j])));
        bpd.set_clutter_log(c, j, std::log(bc.theta_c[c][j]));
      }
    }
  }
  for (std::size_t i = 0; i < bc.nt; ++i) {
    REQUIRE(bpf.add_target(static_cast<float>(bc.theta_t0[i])) == Status::kOk);
    REQUIRE(bpd.add_target(bc.theta_t0[i]) == Status::kOk);
    for (std::size_t j = 0; j < bc.nm; ++j) {
      if (bc.theta_t[i][j] > 0.0) {
        REQUIRE(bpf.add_edge(j, static_cast<float>(std::log(bc.theta_t[i][j]))) == Status::kOk);
        REQUIRE(bpd.add_edge(j, std::log(bc.theta_t[i][j])) == Status::kOk);
      }
    }
  }
  (void)bpf.run(0.9f, 1e-6f, 1000);
  (void)bpd.run(0.9, 1e-9, 1000);
  for (std::size_t i = 0; i < bc.nt; ++i) {
    CHECK(static_cast<double>(bpf.missed_belief(i)) == doctest::Approx(bpd.missed_belief(i)).epsilon(1e-4));
  }
  for (std::size_t j = 0; j < bc.nm; ++j) {
    CHECK(std::fabs(static_cast<double>(bpf.clutter_belief(0, j)) - bpd.clutter_belief(0, j)) < 1e-4);
  }
}

TEST_CASE("mfbp visibility forward-backward equals brute force over 3 scans") {
  const double ps = 0.8, pb = 0.15, pred0 = 0.5;
  const double xi1[3] = {5.0, 0.1, 2.0};
  const double xi0[3] = {0.5, 1.0, 0.7};
  double filt[3], smooth[3], extr[3];
  visibility_forward_backward(pred0, xi1, xi0, 3, ps, pb, filt, smooth, extr);
  // Brute force: P(s0,s1,s2) ∝ p(s0) prod T(s_k|s_k-1) prod Xi_k(s_k)
  double marg[3] = {0, 0, 0}, total = 0;
  double filt_bf0 = 0, filt_bf0_tot = 0;
  for (int s0 = 0; s0 < 2; ++s0) {
    for (int s1 = 0; s1 < 2; ++s1) {
      for (int s2 = 0; s2 < 2; ++s2) {
        auto tr = [&](int to, int from) {
          const double p1 = from ? ps : pb;
          return to ? p1 : 1.0 - p1;
        };
        const int s[3] = {s0, s1, s2};
        double w = (s0 ? pred0 : 1 - pred0);
        for (int k = 0; k < 3; ++k) {
          w *= s[k] ? xi1[k] : xi0[k];
          if (k > 0) w *= tr(s[k], s[k - 1]);
        }
        total += w;
        for (int k = 0; k < 3; ++k) marg[k] += s[k] ? w : 0.0;
      }
    }
  }
  filt_bf0 = pred0 * xi1[0];
  filt_bf0_tot = filt_bf0 + (1 - pred0) * xi0[0];
  for (int k = 0; k < 3; ++k) CHECK(smooth[k] == doctest::Approx(marg[k] / total).epsilon(1e-12));
  CHECK(filt[0] == doctest::Approx(filt_bf0 / filt_bf0_tot).epsilon(1e-12));
  CHECK(smooth[2] == doctest::Approx(filt[2]).epsilon(1e-12));  // last scan: smoothed = filtered
}

TEST_CASE("mfbp Normal-Wishart update equals Bishop 10.60-10.63") {
  NormalWishart<double> nw;
  nw.mu = Vec2<double>(20000.0, 0.5);
  nw.c = 2.0;
  nw.nu = 5.0;
  nw.w_inv << 4e6, 10.0, 10.0, 0.01;
  const Vec2<double> ys[3] = {Vec2<double>(20500.0, 0.52), Vec2<double>(19800.0, 0.47),
                              Vec2<double>(20300.0, 0.55)};
  const double a[3] = {1.0, 0.5, 0.25};
  NwStats<double> st;
  st.ref = nw.mu;
  for (int k = 0; k < 3; ++k) st.add(ys[k], a[k]);
  NormalWishart<double> post = nw;
  post.update(st);
  // Bishop: N, x_bar, S; c' = c + N; mu' = (c mu + N x_bar)/c'; nu' = nu + N;
  // W'^-1 = W^-1 + N S + c N/(c+N) (x_bar - mu)(x_bar - mu)^T
  double N = 0;
  Vec2<double> xb = Vec2<double>::Zero();
  for (int k = 0; k < 3; ++k) { N += a[k]; xb += a[k] * ys[k]; }
  xb /= N;
  Mat2<double> S = Mat2<double>::Zero();
  for (int k = 0; k < 3; ++k) S += a[k] * (ys[k] - xb) * (ys[k] - xb).transpose();
  const Vec2<double> mu = (nw.c * nw.mu + N * xb) / (nw.c + N);
  const Mat2<double> winv = nw.w_inv + S + nw.c * N / (nw.c + N) * (xb - nw.mu) * (xb - nw.mu).transpose();
  CHECK(post.c == doctest::Approx(nw.c + N));
  CHECK(post.nu == doctest::Approx(nw.nu + N));
  CHECK(post.mu(0) == doctest::Approx(mu(0)).epsilon(1e-12));
  CHECK(post.mu(1) == doctest::Approx(mu(1)).epsilon(1e-12));
  CHECK(post.w_inv(0, 0) == doctest::Approx(winv(0, 0)).epsilon(1e-10));
  CHECK(post.w_inv(0, 1) == doctest::Approx(winv(0, 1)).epsilon(1e-8));
  CHECK(post.w_inv(1, 1) == doctest::Approx(winv(1, 1)).epsilon(1e-10));
  // Mean-preserving forgetting keeps E[D^-1] (docs/algorithms/mfbp.md §Departures from the
  // paper).
  const auto pred = post.predicted(0.99, NwForgetting::kMeanPreserving);
  CHECK(pred.expected_covariance()(0, 0) == doctest::Approx(post.expected_covariance()(0, 0)).epsilon(1e-12));
}

TEST_CASE("model cholesky_whiten is forward substitution: L^-1 b") {
  // L = [[2, 0], [1, 3]], b = [4, 7]: y0 = 4 / 2 = 2, y1 = (7 - 1 * 2) / 3 = 5/3.
  Eigen::Matrix2d L;
  L << 2.0, 0.0, 1.0, 3.0;
  const Eigen::Vector2d y = model::cholesky_whiten<double, 2>(L, Eigen::Vector2d(4.0, 7.0));
  CHECK(y(0) == 2.0);
  CHECK(y(1) == doctest::Approx(5.0 / 3.0).epsilon(1e-15));
}
