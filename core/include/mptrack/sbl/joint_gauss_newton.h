// One joint Gauss-Newton step over the amplitudes and positions of all K
// components of a frame (docs/algorithms/sbl.md §Joint refinement):
//   minimise  J = ||z - sum_k mu_k s(p_k)||^2 + sum_k gamma_k |mu_k|^2
// over theta = (Re mu_k, Im mu_k, x_k, y_k)_k with rho~ frozen. Refining one
// position at a time against the residual of the others converges slowly when
// two atoms are nearly collinear (two echoes in one resolution cell: each
// move shifts the other's optimum), so the step is taken jointly:
//   D = d m / d theta,  columns s_k, j s_k, mu_k J_x,k, mu_k J_y,k,
//   (Re{D^H D} + diag(gamma)) delta = Re{D^H e} - gamma mu,   e = z - m.
// Every column is a combination of three separable vectors per component,
//   b0 = a (x) h,  b1 = a (x) (f h),  b2 = (c a) (x) h
// (model/mimo_atom.h: d_r s = -j (4 pi / c) rho~ b1, d_theta s = j rho~ cos(theta) b2),
// so Re{D^H D} needs only the 3 x 3 products b_m,j^H b_n,k = (array sum)(range sum),
// O(N_V + K_B) per pair. The step is capped (largest position move <= max_step),
// halved up to 4 times while J does not decrease, and solved by the Cholesky of
// model/joint_amplitude.h (real symmetric as Hermitian) with a small
// Levenberg-Marquardt damping.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include "mptrack/math/constants.h"
#include "mptrack/model/complex_value.h"
#include "mptrack/model/joint_amplitude.h"
#include "mptrack/model/mimo_atom.h"

namespace mptrack::sbl {

/// s_j^H s_k from the stored factors: rho_j rho_k (sum_v a_j^* a_k)(sum_k h_j^* h_k),
/// the separable Gram of model/mimo_atom.h without its N_V + K_B sin/cos.
template <class T, std::size_t NV, std::size_t KB>
model::Cx<T> gram_from_factors(const model::MimoAtom<T, NV, KB>& aj, const model::MimoAtom<T, NV, KB>& ak) {
  model::Cx<T> a{};
  for (std::size_t v = 0; v < NV; ++v) a = model::cx_add(a, model::cx_cmul(aj.a[v], ak.a[v]));
  model::Cx<T> h{};
  for (std::size_t q = 0; q < KB; ++q) h = model::cx_add(h, model::cx_cmul(aj.h[q], ak.h[q]));
  return model::cx_scale(model::cx_mul(a, h), aj.rho * ak.rho);
}

template <class T, std::size_t NV, std::size_t KB, std::size_t KMax>
class JointGaussNewton {
  using Cx = model::Cx<T>;
  using Atom = model::MimoAtom<T, NV, KB>;
  using Basis = model::MimoAtomBasis<T, NV, KB>;
  static constexpr std::size_t kP = 4 * KMax;  ///< parameters per frame at most
  static constexpr T kFScale = T(1e-6);        ///< f_k in MHz inside the products (float range)

 public:
  /// e = z - sum mu_k s_k into (r_re, r_im); returns ||e||^2 + sum gamma |mu|^2.
  static T residual(const Atom* atoms, const Cx* mu, const T* gamma, std::size_t n, const T* z_re, const T* z_im,
                    T* r_re, T* r_im) {
    for (std::size_t i = 0; i < NV * KB; ++i) {
      r_re[i] = z_re[i];
      r_im[i] = z_im[i];
    }
    T prior = T(0);
    for (std::size_t k = 0; k < n; ++k) {
      model::atom_accumulate(atoms[k], model::cx_scale(mu[k], T(-1)), r_re, r_im);
      prior += gamma[k] * model::cx_norm2(mu[k]);
    }
    T e2 = T(0);
    for (std::size_t i = 0; i < NV * KB; ++i) e2 += r_re[i] * r_re[i] + r_im[i] * r_im[i];
    return e2 + prior;
  }

  /// One step from (atoms, mu); on success atoms and mu hold the new point and
  /// (r_re, r_im) its residual. Returns the largest position move [m] (0 if
  /// no step decreased J).
  T step(const Basis& b, Atom* atoms, Cx* mu, const T* gamma, std::size_t n, const T* z_re, const T* z_im, T* r_re,
         T* r_im, T max_step_m) {
    const T cost0 = residual(atoms, mu, gamma, n, z_re, z_im, r_re, r_im);
    linearise(b, atoms, mu, gamma, n, r_re, r_im);
    if (!solve(4 * n)) return T(0);
    T largest = T(0);
    for (std::size_t k = 0; k < n; ++k) {
      const T m = std::sqrt(delta_[4 * k + 2] * delta_[4 * k + 2] + delta_[4 * k + 3] * delta_[4 * k + 3]);
      if (m > largest) largest = m;
    }
    T scale = largest > max_step_m ? max_step_m / largest : T(1);
    for (int halving = 0; halving <= 4; ++halving) {
      bool ok = true;
      for (std::size_t k = 0; k < n && ok; ++k) {
        const T nx = atoms[k].x + scale * delta_[4 * k + 2];
        const T ny = atoms[k].y + scale * delta_[4 * k + 3];
        ok = ny > T(0);
        if (ok) model::make_atom(b, nx, ny, atoms[k].rho, trial_[k]);
        trial_mu_[k] = Cx{mu[k].re + scale * delta_[4 * k], mu[k].im + scale * delta_[4 * k + 1]};
      }
      if (ok && residual(trial_.data(), trial_mu_.data(), gamma, n, z_re, z_im, r_re, r_im) < cost0) {
        for (std::size_t k = 0; k < n; ++k) {
          atoms[k] = trial_[k];
          mu[k] = trial_mu_[k];
        }
        return scale * largest;
      }
      scale *= T(0.5);
    }
    (void)residual(atoms, mu, gamma, n, z_re, z_im, r_re, r_im);
    return T(0);
  }

  /// The normal equations (9) of docs/algorithms/sbl.md at (atoms, mu) with
  /// residual r = z - sum mu_k s_k: normal(i, j) (lower triangle, i >= j) and
  /// gradient(i), parameter order (Re mu_k, Im mu_k, x_k, y_k)_k.
  void linearise(const Basis& b, const Atom* atoms, const Cx* mu, const T* gamma, std::size_t n, const T* r_re,
                 const T* r_im) {
    for (std::size_t k = 0; k < n; ++k) column_weights(atoms[k], mu[k], w_[k]);
    build_gradient(b, atoms, mu, gamma, n, r_re, r_im);
    normal_matrix(b, atoms, gamma, n);
  }
  T normal(std::size_t i, std::size_t j) const { return nrm_[i * kP + j].re; }
  T gradient(std::size_t i) const { return g_[i].re; }

 private:
  /// Weights of the 4 columns of component k on (b0, b1, b2).
  static void column_weights(const Atom& at, Cx mu, std::array<std::array<Cx, 3>, 4>& w) {
    const Cx kr{T(0), -T(2) * dmath::kTwoPi<T> / model::kLightSpeed_mps<T> * at.rho / kFScale};  // -j 4 pi rho / c
    const Cx kt{T(0), at.rho * at.cos_t};                                                          // j rho cos
    const Cx jx1 = model::cx_scale(kr, at.sin_t);
    const Cx jx2 = model::cx_scale(kt, at.cos_t / at.r);
    const Cx jy1 = model::cx_scale(kr, at.cos_t);
    const Cx jy2 = model::cx_scale(kt, -at.sin_t / at.r);
    w[0] = {Cx{at.rho, T(0)}, Cx{}, Cx{}};
    w[1] = {Cx{T(0), at.rho}, Cx{}, Cx{}};
    w[2] = {Cx{}, model::cx_mul(mu, jx1), model::cx_mul(mu, jx2)};
    w[3] = {Cx{}, model::cx_mul(mu, jy1), model::cx_mul(mu, jy2)};
  }

  /// Re{D^H e} - gamma mu (mu entries).
  void build_gradient(const Basis& b, const Atom* atoms, const Cx* mu, const T* gamma, std::size_t n, const T* r_re,
                const T* r_im) {
    for (std::size_t k = 0; k < n; ++k) {
      const Atom& at = atoms[k];
      std::array<Cx, 3> be{};  // b_m^H e
      for (std::size_t v = 0; v < NV; ++v) {
        Cx g{};
        Cx gf{};
        for (std::size_t q = 0; q < KB; ++q) {
          const Cx p = model::cx_cmul(at.h[q], Cx{r_re[v * KB + q], r_im[v * KB + q]});
          g = model::cx_add(g, p);
          gf = model::cx_add(gf, model::cx_scale(p, b.f(q) * kFScale));
        }
        const Cx ag = model::cx_cmul(at.a[v], g);
        be[0] = model::cx_add(be[0], ag);
        be[1] = model::cx_add(be[1], model::cx_cmul(at.a[v], gf));
        be[2] = model::cx_add(be[2], model::cx_scale(ag, b.c(v)));
      }
      for (std::size_t a = 0; a < 4; ++a) {
        T s = T(0);
        for (std::size_t m = 0; m < 3; ++m) s += model::cx_cmul(w_[k][a][m], be[m]).re;
        g_[4 * k + a] = Cx{s, T(0)};
      }
      g_[4 * k].re -= gamma[k] * mu[k].re;
      g_[4 * k + 1].re -= gamma[k] * mu[k].im;
    }
  }

  /// Lower triangle of Re{D^H D} + diag(gamma on the amplitude entries).
  void normal_matrix(const Basis& b, const Atom* atoms, const T* gamma, std::size_t n) {
    for (std::size_t j = 0; j < n; ++j) {
      for (std::size_t k = 0; k <= j; ++k) {
        std::array<std::array<Cx, 3>, 3> gm{};
        pair_products(b, atoms[j], atoms[k], gm);
        for (std::size_t a = 0; a < 4; ++a) {
          for (std::size_t c = 0; c < 4; ++c) {
            if (j == k && c > a) continue;
            T s = T(0);
            for (std::size_t m = 0; m < 3; ++m) {
              Cx inner{};
              for (std::size_t q = 0; q < 3; ++q) inner = model::cx_add(inner, model::cx_mul(gm[m][q], w_[k][c][q]));
              s += model::cx_cmul(w_[j][a][m], inner).re;
            }
            nrm_[(4 * j + a) * kP + 4 * k + c] = Cx{s, T(0)};
          }
        }
      }
      nrm_[(4 * j) * kP + 4 * j].re += gamma[j];
      nrm_[(4 * j + 1) * kP + 4 * j + 1].re += gamma[j];
    }
  }

  /// gm[m][q] = b_m(j)^H b_q(k) from the array sums A_p = sum c_v^p a_j^* a_k and
  /// the range sums H_p = sum f_k^p h_j^* h_k, p = 0, 1, 2.
  static void pair_products(const Basis& b, const Atom& aj, const Atom& ak, std::array<std::array<Cx, 3>, 3>& gm) {
    std::array<Cx, 3> A{};
    std::array<Cx, 3> H{};
    for (std::size_t v = 0; v < NV; ++v) {
      const Cx p = model::cx_cmul(aj.a[v], ak.a[v]);
      A[0] = model::cx_add(A[0], p);
      A[1] = model::cx_add(A[1], model::cx_scale(p, b.c(v)));
      A[2] = model::cx_add(A[2], model::cx_scale(p, b.c(v) * b.c(v)));
    }
    for (std::size_t q = 0; q < KB; ++q) {
      const Cx p = model::cx_cmul(aj.h[q], ak.h[q]);
      const T f = b.f(q) * kFScale;
      H[0] = model::cx_add(H[0], p);
      H[1] = model::cx_add(H[1], model::cx_scale(p, f));
      H[2] = model::cx_add(H[2], model::cx_scale(p, f * f));
    }
    gm[0] = {model::cx_mul(A[0], H[0]), model::cx_mul(A[0], H[1]), model::cx_mul(A[1], H[0])};
    gm[1] = {model::cx_mul(A[0], H[1]), model::cx_mul(A[0], H[2]), model::cx_mul(A[1], H[1])};
    gm[2] = {model::cx_mul(A[1], H[0]), model::cx_mul(A[1], H[1]), model::cx_mul(A[2], H[0])};
  }

  /// delta = (N + lambda diag N)^-1 g, lambda = 1e-6, raised tenfold (up to 3
  /// times) if the factorisation fails.
  bool solve(std::size_t p) {
    for (std::size_t i = 0; i < p; ++i) diag_[i] = nrm_[i * kP + i].re;
    T lm = T(1e-6);
    for (int attempt = 0; attempt < 4; ++attempt) {
      for (std::size_t i = 0; i < p; ++i) nrm_[i * kP + i].re = diag_[i] + lm * diag_[i];
      if (model::complex_cholesky(nrm_.data(), p, kP, l_.data())) {
        std::array<Cx, kP> x{};
        model::complex_cholesky_solve(l_.data(), p, kP, g_.data(), x.data());
        for (std::size_t i = 0; i < p; ++i) delta_[i] = x[i].re;
        return true;
      }
      lm *= T(10);
    }
    return false;
  }

  std::array<std::array<std::array<Cx, 3>, 4>, KMax> w_{};
  std::array<Cx, kP * kP> nrm_{};
  std::array<T, kP> diag_{};
  std::array<Cx, kP * kP> l_{};
  std::array<Cx, kP> g_{};
  std::array<T, kP> delta_{};
  std::array<Atom, KMax> trial_{};
  std::array<Cx, KMax> trial_mu_{};
};

}  // namespace mptrack::sbl
