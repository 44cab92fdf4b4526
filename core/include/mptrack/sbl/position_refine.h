// Gauss-Newton refinement of one component's position (x, y) against a
// residual, with rho~ frozen (docs/algorithms/sbl.md §Gauss-Newton; the
// data-message mean of seed 004 App. B, eqs. (30)-(34)):
//   l(m) = 2 Re{mu^* s(m)^H r} - e ||s(m)||^2,   e = |mu|^2 + C_kk,
//   grad l = 2 Re{mu^* J^H r}   (Re{J^H s} = 0 with rho~ frozen),
//   step   = (2 e B)^-1 grad l = B^-1 Re{mu^* J^H r} / e,   B = Re{J^H J}.
// "Concentrated" mode (a new component, amplitude unknown) re-estimates
// mu = s^H r / ||s||^2, e = |mu|^2 at every step, i.e. maximises |s^H r|^2.
// Safeguards: step capped at max_step, halved up to 4 times while the
// objective decreases (then the position is held), held when the component
// SNR e ||s||^2 < 1e-3 (the component is effectively absent).
#pragma once

#include <cmath>
#include <cstddef>

#include <Eigen/Core>

#include "mptrack/model/complex_value.h"
#include "mptrack/model/mimo_atom.h"

namespace mptrack::sbl {

using model::Cx;

template <class T>
struct RefineLimits {
  std::size_t steps = 8;   ///< Gauss-Newton steps
  T tolerance_m = T(1e-3);  ///< stop when the accepted step is shorter [m]
  T max_step_m = T(1);      ///< step cap [m]
};

/// Objective of the refinement at an atom: |s^H r|^2 (concentrated) or
/// Re{mu^* s^H r} (fixed amplitude), from the projection p = s^H r.
template <class T>
T refine_objective(Cx<T> p, Cx<T> mu, bool concentrated) {
  return concentrated ? model::cx_norm2(p) : mu.re * p.re + mu.im * p.im;
}

/// Moves `at` (rho~ held at at.rho) towards the maximum of l(m) over (x, y).
/// Returns the distance moved [m]. r is the residual the component explains
/// (planar, N_V K_B values).
template <class T, std::size_t NV, std::size_t KB>
T refine_position(const model::MimoAtomBasis<T, NV, KB>& b, model::MimoAtom<T, NV, KB>& at, const T* r_re,
                  const T* r_im, Cx<T> mu, T e, bool concentrated, const RefineLimits<T>& lim) {
  const T x0 = at.x;
  const T y0 = at.y;
  const T norm2 = model::atom_norm2(b, at);
  model::AtomProjection<T> pr = model::atom_project(b, at, r_re, r_im);
  model::MimoAtom<T, NV, KB> trial;
  for (std::size_t it = 0; it < lim.steps; ++it) {
    if (concentrated) {
      mu = model::cx_scale(pr.s, T(1) / norm2);
      e = model::cx_norm2(mu);
    }
    if (!(e * norm2 >= T(1e-3))) break;
    const T gx = mu.re * pr.jx.re + mu.im * pr.jx.im;  // Re{mu^* J_x^H r}
    const T gy = mu.re * pr.jy.re + mu.im * pr.jy.im;
    const Eigen::Matrix<T, 2, 2> fb = model::atom_fisher(b, at);
    const T det = fb(0, 0) * fb(1, 1) - fb(0, 1) * fb(1, 0);
    if (!(det > T(0))) break;
    T dx = (fb(1, 1) * gx - fb(0, 1) * gy) / (det * e);
    T dy = (fb(0, 0) * gy - fb(1, 0) * gx) / (det * e);
    const T len = std::sqrt(dx * dx + dy * dy);
    if (!(len == len)) break;
    if (len > lim.max_step_m) {
      dx *= lim.max_step_m / len;
      dy *= lim.max_step_m / len;
    }
    const T f0 = refine_objective(pr.s, mu, concentrated);
    bool accepted = false;
    for (int halving = 0; halving <= 4 && !accepted; ++halving) {
      const T nx = at.x + dx;
      const T ny = at.y + dy;
      if (ny > T(0)) {
        model::make_atom(b, nx, ny, at.rho, trial);
        const model::AtomProjection<T> pt = model::atom_project(b, trial, r_re, r_im);
        // Concentrated: compare |s^H r|^2; fixed: Re{mu^* s^H r} (||s||^2 is constant).
        if (refine_objective(pt.s, mu, concentrated) >= f0) {
          at = trial;
          pr = pt;
          accepted = true;
          break;
        }
      }
      dx *= T(0.5);
      dy *= T(0.5);
    }
    if (!accepted) break;
    if (std::sqrt(dx * dx + dy * dy) < lim.tolerance_m) break;
  }
  const T mx = at.x - x0;
  const T my = at.y - y0;
  return std::sqrt(mx * mx + my * my);
}

}  // namespace mptrack::sbl
