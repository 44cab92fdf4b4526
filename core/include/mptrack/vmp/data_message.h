// The data message Z_n -> Phi_{k,n} projected onto a Gaussian in position
// (seed 004 eq. (19), App. B eqs. (30)-(34); docs/algorithms/vmp.md §Data message).
//
// With r~_k = mu_k^* z - sum_{j != k} xi_j (mu_k^* mu_j + C_jk) s_j (the C_jk terms
// that eq. (32) leaves out are included: they are exact under the mean-field
// model) and e_k = xi_k (|mu_k|^2 + C_kk), the KL projection gives
//   mean   m = argmax l(m),  l(m) = 2 xi_k Re{s(m)^H r~_k} - e_k ||s(m)||^2,
//   precision Omega = 2 e_k B(m),  B = Re{J^H J}  (P* = Omega^-1, the conditional CRB).
// The atom does not depend on velocity, so the message is 2-D (zero velocity
// precision). The mean is found by Gauss-Newton from the predicted position,
// step P* grad l, with the safeguards of docs/algorithms/vmp.md §Numerics: step capped
// at max_step, halved (up to `backtracks` times) while l decreases, stop below
// tol; no message (position held) when e_k < min_energy. rho~ is frozen at the
// start position (model/mimo_atom.h), so ||s||^2 is constant along the search.
#pragma once

#include <cmath>
#include <cstddef>

#include <Eigen/Core>

#include "mptrack/model/mimo_atom.h"

namespace mptrack::vmp {

template <class T>
struct MessageSettings {
  std::size_t iterations = 8;  ///< Gauss-Newton iterations
  T max_step_m = T(1);         ///< step cap [m]
  T tol_m = T(1e-3);           ///< stop when the step is shorter [m]
  std::size_t backtracks = 4;  ///< step halvings while l decreases
  T min_energy = T(1e-3);      ///< e_k below this: no message
  T min_precision = T(1e-6);   ///< eigenvalue floor of Omega [1/m^2]
  T max_precision = T(1e8);    ///< eigenvalue cap of Omega [1/m^2]
  bool literal = false;        ///< differentiate rho~(r) too
  bool diagonal = false;       ///< keep only diag(Omega) (the paper's diagonal restriction)
};

template <class T>
struct PositionMessage {
  bool valid = false;
  Eigen::Matrix<T, 2, 1> m = Eigen::Matrix<T, 2, 1>::Zero();      ///< (x, y) [m]
  Eigen::Matrix<T, 2, 2> omega = Eigen::Matrix<T, 2, 2>::Zero();  ///< precision [1/m^2]
  std::size_t iterations = 0;
  bool repaired = false;  ///< Omega's eigenvalues were clamped
};

/// Clamps the eigenvalues of the symmetric 2 x 2 w into [lo, hi]; true if it
/// had to (w then rebuilt from its eigen decomposition).
template <class T>
bool clamp_precision(Eigen::Matrix<T, 2, 2>& w, T lo, T hi) {
  const T a = w(0, 0), b = w(0, 1), d = w(1, 1);
  const T half_tr = T(0.5) * (a + d);
  const T disc = std::sqrt(T(0.25) * (a - d) * (a - d) + b * b);
  const T l1 = half_tr + disc, l2 = half_tr - disc;
  if (l2 >= lo && l1 <= hi && l1 == l1) return false;
  const T c1 = l1 < lo ? lo : (l1 > hi ? hi : l1);
  const T c2 = l2 < lo ? lo : (l2 > hi ? hi : l2);
  // Eigenvector of l1: (b, l1 - a) or (l1 - d, b), whichever is longer.
  T ux = b, uy = l1 - a;
  if (ux * ux + uy * uy < (l1 - d) * (l1 - d) + b * b) {
    ux = l1 - d;
    uy = b;
  }
  const T n2 = ux * ux + uy * uy;
  if (!(n2 > T(0))) {
    w << c1, T(0), T(0), c2;
    return true;
  }
  const T inv = T(1) / std::sqrt(n2);
  ux *= inv;
  uy *= inv;
  w(0, 0) = c1 * ux * ux + c2 * uy * uy;
  w(0, 1) = (c1 - c2) * ux * uy;
  w(1, 0) = w(0, 1);
  w(1, 1) = c1 * uy * uy + c2 * ux * ux;
  return true;
}

/// The message for one object. atom: holds the atom at the result; trial:
/// scratch (both caller-owned, so the search uses no stack array).
template <class T, std::size_t NV, std::size_t KB>
PositionMessage<T> data_message(const model::MimoAtomBasis<T, NV, KB>& basis, T x0, T y0, const T* rt_re,
                                const T* rt_im, T xi, T e, const MessageSettings<T>& s,
                                model::MimoAtom<T, NV, KB>& atom, model::MimoAtom<T, NV, KB>& trial) {
  PositionMessage<T> out;
  out.m << x0, y0;
  model::make_atom(basis, x0, y0, T(-1), atom);
  if (!(e >= s.min_energy)) return out;
  const T rho = atom.rho;  // frozen
  auto proj = model::atom_project(basis, atom, rt_re, rt_im, s.literal);
  T ell = T(2) * xi * proj.s.re;  // e ||s||^2 is constant: dropped
  for (std::size_t it = 0; it < s.iterations; ++it) {
    const Eigen::Matrix<T, 2, 2> h = T(2) * e * model::atom_fisher(basis, atom, s.literal);
    const T gx = T(2) * xi * proj.jx.re;
    const T gy = T(2) * xi * proj.jy.re;
    const T det = h(0, 0) * h(1, 1) - h(0, 1) * h(1, 0);
    if (!(det > T(0))) break;
    T dx = (h(1, 1) * gx - h(0, 1) * gy) / det;
    T dy = (h(0, 0) * gy - h(1, 0) * gx) / det;
    const T len = std::sqrt(dx * dx + dy * dy);
    if (len > s.max_step_m) {
      dx *= s.max_step_m / len;
      dy *= s.max_step_m / len;
    }
    bool accepted = false;
    for (std::size_t b = 0; b <= s.backtracks; ++b) {
      const T nx = out.m(0) + dx, ny = out.m(1) + dy;
      if (ny > T(0)) {
        model::make_atom(basis, nx, ny, rho, trial);
        const auto p = model::atom_project(basis, trial, rt_re, rt_im, s.literal);
        const T l = T(2) * xi * p.s.re;
        if (l >= ell) {
          ell = l;
          proj = p;
          atom = trial;
          out.m << nx, ny;
          accepted = true;
          break;
        }
      }
      dx *= T(0.5);
      dy *= T(0.5);
    }
    out.iterations = it + 1;
    if (!accepted || std::sqrt(dx * dx + dy * dy) < s.tol_m) break;
  }
  out.omega = T(2) * e * model::atom_fisher(basis, atom, s.literal);
  if (s.diagonal) out.omega(0, 1) = out.omega(1, 0) = T(0);
  out.repaired = clamp_precision(out.omega, s.min_precision, s.max_precision);
  out.valid = true;
  return out;
}

}  // namespace mptrack::vmp
