// The MIMO signal atom of seed 004 in whitened units (seed 004 eqs. (2)-(3), the
// path loss of its Table I; docs/algorithms/vmp.md §Signal model): one point
// target at p = (x, y) contributes to the whitened spectrum z[v][k]
// (frontend/mimo_spectrum.h)
//   s(p) = rho~(r) a(theta) (x) h(tau),
//   [a(theta)]_v = exp(j c_v sin theta),   c_v = 2 pi d (v - (N_V - 1)/2)   (centred array),
//   [h(tau)]_k   = U[k] exp(-j 2 pi f_k tau),  tau = 2 r / c,
//   theta = atan2(x, y) (from boresight +y),  sin theta = x / r,  cos theta = y / r,
//   rho~(r) = rho_scale / r^2,  rho_scale = sqrt(mean RCS) A G lambda / ((4 pi)^1.5 sigma_w),
// times a complex amplitude alpha' with E|alpha'|^2 = 1 (prior precision 1).
// The carrier phase is NOT in the atom (it is absorbed in alpha'); so
// ||s||^2 = rho~^2 N_V E_U is the mean component SNR, E_U = sum_k |U[k]|^2.
//
// Everything uses the separable form, O(N_V + K_B) or O(N_V K_B) per call:
// - s^H r and the Jacobian projections J^H r through two per-channel sums;
// - Gram entries s_1^H s_2 = rho~_1 rho~_2 D(u_2 - u_1) R_U(tau_2 - tau_1),
//   D(du) = sum_v exp(j c_v du), R_U(dt) = sum_k |U_k|^2 exp(-j 2 pi f_k dt);
// - the Fisher matrix B = Re{J^H J} in closed form (E_U, F_1 = sum f_k |U_k|^2,
//   F_2 = sum f_k^2 |U_k|^2, sum c_v, sum c_v^2), diagonal in (r, theta) for a centred
//   array, mapped to (x, y).
// rho~ is FROZEN in the derivatives by default (docs/algorithms/vmp.md §Corrections: the
// literal derivative of the path loss extracts range from echo power, which a
// Swerling target does not carry); `literal` adds the -2/r rho~ term back.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include <Eigen/Core>

#include "mptrack/math/constants.h"
#include "mptrack/math/detmath.h"
#include "mptrack/model/complex_value.h"

namespace mptrack::model {

/// Speed of light [m/s] (exact, SI definition).
template <class T>
inline constexpr T kLightSpeed_mps = T(299792458.0);

/// Everything of the atom that does not depend on the target: the chirp
/// spectrum at the kept bins and the array. N_V channels, K_B bins.
template <class T, std::size_t NV, std::size_t KB>
class MimoAtomBasis {
 public:
  static constexpr std::size_t kNumVirtual = NV;
  static constexpr std::size_t kNumBins = KB;
  static constexpr std::size_t kSize = NV * KB;

  /// u, f: K_B values (frontend/mimo_spectrum.h); spacing d [wavelengths];
  /// rho_scale [m^2] so that rho~(r) = rho_scale / r^2.
  void init(const T* u_re, const T* u_im, const T* f_hz, T spacing_wavelengths, T rho_scale_m2) {
    e_u_ = T(0);
    f1_ = T(0);
    f2_ = T(0);
    for (std::size_t k = 0; k < KB; ++k) {
      u_[k] = {u_re[k], u_im[k]};
      u2_[k] = cx_norm2(u_[k]);
      f_[k] = f_hz[k];
      e_u_ += u2_[k];
      f1_ += f_[k] * u2_[k];
      f2_ += f_[k] * f_[k] * u2_[k];
    }
    sum_c_ = T(0);
    sum_c2_ = T(0);
    const T centre = T(0.5) * static_cast<T>(NV - 1);
    for (std::size_t v = 0; v < NV; ++v) {
      c_[v] = dmath::kTwoPi<T> * spacing_wavelengths * (static_cast<T>(v) - centre);
      sum_c_ += c_[v];
      sum_c2_ += c_[v] * c_[v];
    }
    rho_scale_ = rho_scale_m2;
  }

  /// rho~(r) [-] at range r [m].
  T rho(T r_m) const { return rho_scale_ / (r_m * r_m); }
  T rho_scale() const { return rho_scale_; }
  /// E_U = sum_k |U_k|^2 (the chirp energy in the kept band, samples).
  T e_u() const { return e_u_; }
  T f1() const { return f1_; }
  T f2() const { return f2_; }
  T sum_c2() const { return sum_c2_; }
  T sum_c() const { return sum_c_; }
  T c(std::size_t v) const { return c_[v]; }
  T f(std::size_t k) const { return f_[k]; }
  T u2(std::size_t k) const { return u2_[k]; }
  Cx<T> u(std::size_t k) const { return u_[k]; }

  /// D(du) = sum_v exp(j c_v du) (real when the array is centred).
  Cx<T> array_kernel(T du) const {
    Cx<T> d{};
    for (std::size_t v = 0; v < NV; ++v) {
      T s = T(0);
      T co = T(1);
      dmath::dsincos(c_[v] * du, s, co);
      d = cx_add(d, Cx<T>{co, s});
    }
    return d;
  }

  /// R_U(dt) = sum_k |U_k|^2 exp(-j 2 pi f_k dt), dt [s].
  Cx<T> range_kernel(T dt_s) const {
    Cx<T> r{};
    for (std::size_t k = 0; k < KB; ++k) {
      T s = T(0);
      T co = T(1);
      dmath::dsincos(-dmath::kTwoPi<T> * f_[k] * dt_s, s, co);
      r = cx_add(r, Cx<T>{u2_[k] * co, u2_[k] * s});
    }
    return r;
  }

 private:
  std::array<Cx<T>, KB> u_{};
  std::array<T, KB> u2_{};
  std::array<T, KB> f_{};
  std::array<T, NV> c_{};
  T e_u_ = T(0), f1_ = T(0), f2_ = T(0), sum_c_ = T(0), sum_c2_ = T(0), rho_scale_ = T(0);
};

/// One evaluated atom: geometry plus its separable factors a (N_V) and h (K_B).
template <class T, std::size_t NV, std::size_t KB>
struct MimoAtom {
  T x = T(0), y = T(1);          ///< position [m]
  T r = T(1);                    ///< range [m]
  T sin_t = T(0), cos_t = T(1);  ///< sin, cos of the bearing from +y
  T tau_s = T(0);                ///< two-way delay [s]
  T rho = T(0);                  ///< rho~ used (frozen or rho~(r)) [-]
  std::array<Cx<T>, NV> a{};
  std::array<Cx<T>, KB> h{};
};

/// s^H r and the Jacobian projections (J_x^H r, J_y^H r) of one atom.
template <class T>
struct AtomProjection {
  Cx<T> s;   ///< s^H r
  Cx<T> jx;  ///< (ds/dx)^H r
  Cx<T> jy;  ///< (ds/dy)^H r
};

/// Evaluates the atom at (x, y) [m] (r > 0). rho < 0: rho~(r) of the basis;
/// otherwise that value (frozen amplitude scale).
template <class T, std::size_t NV, std::size_t KB>
void make_atom(const MimoAtomBasis<T, NV, KB>& b, T x, T y, T rho, MimoAtom<T, NV, KB>& at) {
  at.x = x;
  at.y = y;
  at.r = std::sqrt(x * x + y * y);
  at.sin_t = x / at.r;
  at.cos_t = y / at.r;
  at.tau_s = T(2) * at.r / kLightSpeed_mps<T>;
  at.rho = rho < T(0) ? b.rho(at.r) : rho;
  for (std::size_t v = 0; v < NV; ++v) {
    T s = T(0);
    T c = T(1);
    dmath::dsincos(b.c(v) * at.sin_t, s, c);
    at.a[v] = {c, s};
  }
  for (std::size_t k = 0; k < KB; ++k) {
    T s = T(0);
    T c = T(1);
    dmath::dsincos(-dmath::kTwoPi<T> * b.f(k) * at.tau_s, s, c);
    at.h[k] = cx_mul(b.u(k), Cx<T>{c, s});
  }
}

/// ||s||^2 = rho~^2 N_V E_U (|a_v| = 1).
template <class T, std::size_t NV, std::size_t KB>
T atom_norm2(const MimoAtomBasis<T, NV, KB>& b, const MimoAtom<T, NV, KB>& at) {
  return at.rho * at.rho * static_cast<T>(NV) * b.e_u();
}

/// s^H r for r planar [v * K_B + k].
template <class T, std::size_t NV, std::size_t KB>
Cx<T> atom_inner(const MimoAtom<T, NV, KB>& at, const T* r_re, const T* r_im) {
  Cx<T> acc{};
  for (std::size_t v = 0; v < NV; ++v) {
    Cx<T> g{};
    for (std::size_t k = 0; k < KB; ++k) g = cx_add(g, cx_cmul(at.h[k], Cx<T>{r_re[v * KB + k], r_im[v * KB + k]}));
    acc = cx_add(acc, cx_cmul(at.a[v], g));
  }
  return cx_scale(acc, at.rho);
}

/// s^H r and J^H r (seed 004 App. B, derivatives of docs/algorithms/vmp.md §Signal model):
///   (ds/dr)^H r  = rho~ (2/c) sum_v a_v^* (j 2 pi) sum_k f_k h_k^* r_vk  [+ (-2/r) s^H r if literal]
///   (ds/dth)^H r = rho~ sum_v (-j c_v cos th) a_v^* sum_k h_k^* r_vk
///   J_x = sin th d_r + cos th / r d_th,   J_y = cos th d_r - sin th / r d_th.
template <class T, std::size_t NV, std::size_t KB>
AtomProjection<T> atom_project(const MimoAtomBasis<T, NV, KB>& b, const MimoAtom<T, NV, KB>& at, const T* r_re,
                               const T* r_im, bool literal = false) {
  Cx<T> s{};
  Cx<T> dr{};
  Cx<T> dth{};
  for (std::size_t v = 0; v < NV; ++v) {
    Cx<T> g{};
    Cx<T> gf{};
    for (std::size_t k = 0; k < KB; ++k) {
      const Cx<T> p = cx_cmul(at.h[k], Cx<T>{r_re[v * KB + k], r_im[v * KB + k]});
      g = cx_add(g, p);
      gf = cx_add(gf, cx_scale(p, b.f(k)));
    }
    const Cx<T> ag = cx_cmul(at.a[v], g);
    s = cx_add(s, ag);
    dr = cx_add(dr, cx_cmul(at.a[v], gf));
    // -j c_v cos th * ag = (c_v cos th ag.im, -c_v cos th ag.re)
    const T w = b.c(v) * at.cos_t;
    dth = cx_add(dth, Cx<T>{w * ag.im, -w * ag.re});
  }
  s = cx_scale(s, at.rho);
  // j 2 pi (2/c) rho~ * dr
  const T kr = dmath::kTwoPi<T> * T(2) / kLightSpeed_mps<T> * at.rho;
  Cx<T> d_r{-kr * dr.im, kr * dr.re};
  if (literal) d_r = cx_add(d_r, cx_scale(s, T(-2) / at.r));
  const Cx<T> d_t = cx_scale(dth, at.rho);
  AtomProjection<T> out;
  out.s = s;
  out.jx = cx_add(cx_scale(d_r, at.sin_t), cx_scale(d_t, at.cos_t / at.r));
  out.jy = cx_sub(cx_scale(d_r, at.cos_t), cx_scale(d_t, at.sin_t / at.r));
  return out;
}

/// s_1^H s_2 by the separable closed form rho~_1 rho~_2 D(u_2 - u_1) R_U(tau_2 - tau_1).
template <class T, std::size_t NV, std::size_t KB>
Cx<T> atom_gram(const MimoAtomBasis<T, NV, KB>& b, const MimoAtom<T, NV, KB>& a1, const MimoAtom<T, NV, KB>& a2) {
  const Cx<T> d = b.array_kernel(a2.sin_t - a1.sin_t);
  const Cx<T> r = b.range_kernel(a2.tau_s - a1.tau_s);
  return cx_scale(cx_mul(d, r), a1.rho * a2.rho);
}

/// Fisher matrix B = Re{J^H J} in (x, y) [1/m^2], closed form:
///   B_rr = rho~^2 N_V (4 pi / c)^2 F_2   [+ rho~^2 N_V E_U 4 / r^2 if literal]
///   B_tt = rho~^2 cos^2 th sum_v c_v^2 E_U
///   B_rt = -rho~^2 (4 pi / c) cos th F_1 sum_v c_v   (0 for a centred array)
/// mapped by M = d(r, th)/d(x, y) = [[sin th, cos th], [cos th / r, -sin th / r]]: B = M^T B_rt M.
template <class T, std::size_t NV, std::size_t KB>
Eigen::Matrix<T, 2, 2> atom_fisher(const MimoAtomBasis<T, NV, KB>& b, const MimoAtom<T, NV, KB>& at,
                                   bool literal = false) {
  const T rho2 = at.rho * at.rho;
  const T k4 = T(2) * dmath::kTwoPi<T> / kLightSpeed_mps<T>;  // 4 pi / c [s/m]
  T brr = rho2 * static_cast<T>(NV) * k4 * k4 * b.f2();
  if (literal) brr += rho2 * static_cast<T>(NV) * b.e_u() * T(4) / (at.r * at.r);
  const T btt = rho2 * at.cos_t * at.cos_t * b.sum_c2() * b.e_u();
  const T brt = -rho2 * k4 * at.cos_t * b.f1() * b.sum_c();
  // M^T Bp M written out (fixed order): M = [[m00, m01], [m10, m11]].
  const T m00 = at.sin_t, m01 = at.cos_t, m10 = at.cos_t / at.r, m11 = -at.sin_t / at.r;
  const T p00 = brr * m00 + brt * m10, p01 = brr * m01 + brt * m11;  // Bp M, first row
  const T p10 = brt * m00 + btt * m10, p11 = brt * m01 + btt * m11;  // second row
  Eigen::Matrix<T, 2, 2> out;
  out(0, 0) = m00 * p00 + m10 * p10;
  out(0, 1) = m00 * p01 + m10 * p11;
  out(1, 0) = out(0, 1);
  out(1, 1) = m01 * p01 + m11 * p11;
  return out;
}

/// r += coef s (planar, N_V K_B values).
template <class T, std::size_t NV, std::size_t KB>
void atom_accumulate(const MimoAtom<T, NV, KB>& at, Cx<T> coef, T* r_re, T* r_im) {
  const Cx<T> c = cx_scale(coef, at.rho);
  for (std::size_t v = 0; v < NV; ++v) {
    const Cx<T> ca = cx_mul(c, at.a[v]);
    for (std::size_t k = 0; k < KB; ++k) {
      const Cx<T> x = cx_mul(ca, at.h[k]);
      r_re[v * KB + k] += x.re;
      r_im[v * KB + k] += x.im;
    }
  }
}

}  // namespace mptrack::model
