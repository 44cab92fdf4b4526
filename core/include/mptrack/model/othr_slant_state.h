// The OTHR slant STATE of one propagation path and its map to and from the
// ground state (docs/algorithms/mptf.md §Slant to ground).
//
// A tracker that filters in slant coordinates (multipath track fusion,
// seed 002 Sec. IV) carries s = [r km, r_dot km/s, zeta rad, zeta_dot rad/s]:
// slant range with its rate and azimuth with its rate. The ground state is
// x = [g km, g_dot km/s, theta rad, theta_dot rad/s] (othr_measurement.h).
// Forward, with h = h^tau(x) of seed 002 eq. (57) and H = dh/dx:
//   s = [h_0, h_1, h_2, H_20 g_dot + H_22 theta_dot]
// (zeta_dot is the time derivative of zeta = h_2(g, theta)). Inverse:
//   (g, theta) from (r, zeta) by othr_invert's 2-D Newton iteration,
//   g_dot     = r_dot / H_11                 (r_dot is linear in g_dot),
//   theta_dot = (zeta_dot - H_20 g_dot) / H_22.
// Covariances go through the 4x4 Jacobian J = ds/dx at x,
//   J = [[H00, 0, H02, 0], [H10, H11, H12, 0], [H20, 0, H22, 0], [0, H20, 0, H22]],
// whose last row drops the second derivatives of zeta (they multiply the
// rates g_dot, theta_dot, whose products with the state spread are small
// against the azimuth rate's own variance): P_x = J^-1 P_s J^-T.
#pragma once

#include <cmath>
#include <cstddef>

#include <Eigen/Core>

#include "mptrack/model/othr_measurement.h"

namespace mptrack::model {

template <class T>
using OthrSlantState = Eigen::Matrix<T, 4, 1>;
template <class T>
using OthrMat4 = Eigen::Matrix<T, 4, 4>;

namespace othr_slant_detail {

/// A^-1 by Gauss-Jordan elimination with partial pivoting, plain loops in a
/// fixed order (Eigen's inverse() takes other code paths per target). False
/// if a pivot is zero or NaN.
template <class T>
bool invert4(const OthrMat4<T>& A, OthrMat4<T>& Ai) {
  OthrMat4<T> M = A;
  Ai.setIdentity();
  for (int c = 0; c < 4; ++c) {
    int piv = c;
    for (int r = c + 1; r < 4; ++r) {
      if (std::fabs(M(r, c)) > std::fabs(M(piv, c))) piv = r;
    }
    const T p = M(piv, c);
    if (!(p > T(0) || p < T(0))) return false;
    if (piv != c) {
      M.row(piv).swap(M.row(c));
      Ai.row(piv).swap(Ai.row(c));
    }
    for (int k = 0; k < 4; ++k) {
      M(c, k) /= p;
      Ai(c, k) /= p;
    }
    for (int r = 0; r < 4; ++r) {
      if (r == c) continue;
      const T f = M(r, c);
      for (int k = 0; k < 4; ++k) {
        M(r, k) -= f * M(c, k);
        Ai(r, k) -= f * Ai(c, k);
      }
    }
  }
  return true;
}

}  // namespace othr_slant_detail

/// J = ds/dx at x from the measurement Jacobian H of the same point.
template <class T>
OthrMat4<T> othr_slant_jacobian(const OthrJacobian<T>& H) {
  OthrMat4<T> J = OthrMat4<T>::Zero();
  J.template topRows<3>() = H;
  J(3, 1) = H(2, 0);
  J(3, 3) = H(2, 2);
  return J;
}

/// Ground state x to the slant state s of one path, and J = ds/dx.
template <class T>
void othr_ground_to_slant(const OthrState<T>& x, const OthrPath<T>& path, T baseline_km, OthrSlantState<T>& s,
                          OthrMat4<T>& J) {
  OthrMeas<T> y;
  OthrJacobian<T> H;
  othr_linearize(x, path, baseline_km, y, H);
  s << y(0), y(1), y(2), H(2, 0) * x(1) + H(2, 2) * x(3);
  J = othr_slant_jacobian(H);
}

/// Slant state s (covariance Ps) of one path to the ground state x (Px).
/// False if the Newton inversion fails (othr_invert) or J is singular;
/// x and Px are then unspecified.
template <class T>
bool othr_slant_to_ground(const OthrSlantState<T>& s, const OthrMat4<T>& Ps, const OthrPath<T>& path, T baseline_km,
                          OthrState<T>& x, OthrMat4<T>& Px, std::size_t iterations = 6) {
  const OthrMeas<T> y(s(0), s(1), s(2));
  if (!othr_invert(y, path, baseline_km, x, iterations)) return false;
  OthrMeas<T> z;
  OthrJacobian<T> H;
  othr_linearize(x, path, baseline_km, z, H);
  if (!(H(2, 2) > T(0) || H(2, 2) < T(0))) return false;
  x(3) = (s(3) - H(2, 0) * x(1)) / H(2, 2);
  const OthrMat4<T> J = othr_slant_jacobian(H);
  OthrMat4<T> Ji;
  if (!othr_slant_detail::invert4(J, Ji)) return false;
  const OthrMat4<T> JiP = Ji * Ps;
  Px = JiP * Ji.transpose();
  return true;
}

}  // namespace mptrack::model
