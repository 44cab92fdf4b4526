// Two-point track initiation (seed 000 Sec. III-G; docs/algorithms/mfbp.md §Birth).
#pragma once

#include "mptrack/math/detmath.h"
#include "mptrack/mfbp/cubature.h"
#include "mptrack/model/inverse_gamma.h"

namespace mptrack::mfbp {

/// Position covariance J R J^T of the polar->Cartesian map at (r, theta),
/// J = [[cos, -r sin], [sin, r cos]], R = diag(sigma_r^2, sigma_az^2).
template <class T>
Mat2<T> cartesian_position_covariance(T range_m, T az_rad, T sigma_r, T sigma_az) {
  T s, c;
  dmath::dsincos(az_rad, s, c);
  Mat2<T> J;
  J << c, -range_m * s, s, range_m * c;
  Mat2<T> R = Mat2<T>::Zero();
  R(0, 0) = sigma_r * sigma_r;
  R(1, 1) = sigma_az * sigma_az;
  Mat2<T> P = J * R * J.transpose();
  P(0, 1) = P(1, 0) = T(0.5) * (P(0, 1) + P(1, 0));
  return P;
}

/// dt |v_max| of birth_range_gate.
template <class T>
T birth_reach(T dt_s, T v_max_x, T v_max_y) {
  return dt_s * std::sqrt(v_max_x * v_max_x + v_max_y * v_max_y);
}

/// birth_range_gate with its reach from birth_reach.
template <class T>
bool within_birth_reach(T r1_m, T r2_m, T reach) {
  const T dr = r2_m > r1_m ? r2_m - r1_m : r1_m - r2_m;
  const T r = r2_m > r1_m ? r2_m : r1_m;
  return !(dr > reach + T(1e-3) * r + T(1));
}

/// Necessary condition for birth_gate, on ranges alone: |r2 - r1| <= |p2 - p1|
/// (triangle inequality) <= dt |v_max|. The 1e-3 relative and 1 m slack cover
/// the rounding of r [cos, sin] in float, so no pair that passes birth_gate is
/// rejected here. Saves the two sines and cosines of every far pair.
/// In two parts, so that a search over many first points takes the reach
/// dt |v_max| once: birth_reach, then within_birth_reach.
template <class T>
bool birth_range_gate(T r1_m, T r2_m, T dt_s, T v_max_x, T v_max_y) {
  return within_birth_reach(r1_m, r2_m, birth_reach(dt_s, v_max_x, v_max_y));
}

/// True if a measurement pair passes the v_max box gate (docs/algorithms/mfbp.md
/// §Birth):
/// |dx| <= dt v_max_x and |dy| <= dt v_max_y.
template <class T>
bool birth_gate(const Vec2<T>& p1, const Vec2<T>& p2, T dt_s, T v_max_x, T v_max_y) {
  const T dx = p2(0) - p1(0);
  const T dy = p2(1) - p1(1);
  const T adx = dx < T(0) ? -dx : dx;
  const T ady = dy < T(0) ? -dy : dy;
  return adx <= dt_s * v_max_x && ady <= dt_s * v_max_y;
}

/// Initial state at the second point (docs/algorithms/mfbp.md §Birth): position p2,
/// velocity
/// (p2 - p1)/dt; P_pos = J R J^T at y2; velocity covariance
/// (P_pos1 + P_pos2)/dt^2; position-velocity cross term P_pos2/dt.
template <class T>
void two_point_state(T r1, T az1, T r2, T az2, T dt_s, T sigma_r, T sigma_az, T v_max_x, T v_max_y,
                     Vec4<T>& x, Mat4<T>& P) {
  const Vec2<T> p1 = model::cartesian_of_polar(r1, az1);
  const Vec2<T> p2 = model::cartesian_of_polar(r2, az2);
  const Mat2<T> P1 = cartesian_position_covariance(r1, az1, sigma_r, sigma_az);
  const Mat2<T> P2 = cartesian_position_covariance(r2, az2, sigma_r, sigma_az);
  const Vec2<T> v = (p2 - p1) / dt_s;
  x << p2(0), v(0), p2(1), v(1);
  Mat2<T> Pv = (P1 + P2) / (dt_s * dt_s);
  Mat2<T> Pc = P2 / dt_s;
  // Our choice (docs/algorithms/mfbp.md §Departures from the paper): two points a few
  // ms apart say nothing about the velocity: the difference formula gives a velocity
  // std of ~1e5 m/s, and after a few
  // updates the float covariance, with position-velocity correlation ~1,
  // is no longer positive definite (fuzz finding F13, docs/reliability.md).
  // Beyond 100 x v_max in std the v_max box prior (uniform: v_max^2 / 3)
  // is used instead, uncorrelated with the position. Real scan spacings stay
  // far below (S1 at 50 km: ~6 v_max).
  const T prior_x = v_max_x * v_max_x / T(3);
  const T prior_y = v_max_y * v_max_y / T(3);
  if (!(Pv(0, 0) <= T(1e4) * prior_x) || !(Pv(1, 1) <= T(1e4) * prior_y)) {
    Pv << prior_x, T(0), T(0), prior_y;
    Pc.setZero();
  }
  // State order [px, vx, py, vy]: position rows/cols {0, 2}, velocity {1, 3}.
  const int pos[2] = {0, 2};
  const int vel[2] = {1, 3};
  for (int a = 0; a < 2; ++a) {
    for (int b = 0; b < 2; ++b) {
      P(pos[a], pos[b]) = P2(a, b);
      P(vel[a], vel[b]) = Pv(a, b);
      P(pos[a], vel[b]) = Pc(a, b);
      P(vel[a], pos[b]) = Pc(b, a);
    }
  }
}

/// One-point state (docs/algorithms/mfbp.md §Birth, one-point birth inside
/// clutter): position y, P_pos = J R J^T at y; velocity 0 with the v_max box
/// prior v_max^2 / 3 per axis, uncorrelated with the position.
template <class T>
void one_point_state(T r, T az, T sigma_r, T sigma_az, T v_max_x, T v_max_y, Vec4<T>& x, Mat4<T>& P) {
  const Vec2<T> p = model::cartesian_of_polar(r, az);
  const Mat2<T> Pp = cartesian_position_covariance(r, az, sigma_r, sigma_az);
  x << p(0), T(0), p(1), T(0);
  P.setZero();
  P(0, 0) = Pp(0, 0);
  P(0, 2) = Pp(0, 1);
  P(2, 0) = Pp(1, 0);
  P(2, 2) = Pp(1, 1);
  P(1, 1) = v_max_x * v_max_x / T(3);
  P(3, 3) = v_max_y * v_max_y / T(3);
}

/// IG at birth (docs/algorithms/mfbp.md §Departures from the paper): a = shape,
/// b = factor mean(m^2 - d^2).
template <class T>
model::InverseGamma<T> birth_snr_belief(T m1, T m2, T d, T shape, T factor) {
  model::InverseGamma<T> ig;
  ig.a = shape;
  T mean_excess = T(0.5) * ((m1 * m1 - d * d) + (m2 * m2 - d * d));
  if (!(mean_excess > T(1e-3))) mean_excess = T(1e-3);
  ig.b = factor * mean_excess;
  return ig;
}

/// How unlikely amplitude m is for a source of mean total power varsigma
/// (docs/algorithms/mfbp.md §Birth, birth inside clutter): P(u > m^2 | u > d^2)
/// for the power u ~ Gamma(n, varsigma / n) above the threshold d, i.e.
/// e^-(x_m - x_d) sum_{l<n} x_m^l/l! / sum_{l<n} x_d^l/l!, x = n (.)^2 / varsigma
/// (the detection law of docs/algorithms/models.md §Detection probability,
/// n = 1 or 2). Swerling I: e^-((m^2 - d^2) / varsigma).
template <class T>
T amplitude_tail(T m, T d, T varsigma, int n) {
  const T tn = T(n);
  const T xm = tn * m * m / varsigma;
  const T xd = tn * d * d / varsigma;
  T tail = dmath::dexp(-(xm - xd));
  if (n == 2) tail *= (T(1) + xm) / (T(1) + xd);
  return tail;
}

}  // namespace mptrack::mfbp
