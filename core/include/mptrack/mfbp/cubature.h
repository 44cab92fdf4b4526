// Cubature transform of a Cartesian CV state through the polar measurement
// function h(x) = [sqrt(px^2 + py^2), atan2(py, px)] (spec 2.6, 3.2).
//
// Third-degree spherical-radial cubature: 2 n = 8 points x +- sqrt(n) L e_i
// with equal weights 1/8 (spec 3.2 [impl]: no negative weights). Azimuth
// deviations are wrapped to (-pi, pi] around h(x_hat) before averaging, so
// a track near the +-pi cut keeps a consistent mean.
#pragma once

#include <Eigen/Core>

#include "mptrack/math/detmath.h"
#include "mptrack/mfbp/cholesky.h"

namespace mptrack::mfbp {

template <class T> using Vec2 = Eigen::Matrix<T, 2, 1>;
template <class T> using Vec4 = Eigen::Matrix<T, 4, 1>;
template <class T> using Mat2 = Eigen::Matrix<T, 2, 2>;
template <class T> using Mat4 = Eigen::Matrix<T, 4, 4>;
template <class T> using Mat42 = Eigen::Matrix<T, 4, 2>;

template <class T> constexpr T kPi = T(3.14159265358979323846);
template <class T> constexpr T kTwoPi = T(6.28318530717958647692);

/// Wraps an angle difference to (-pi, pi]. A loop, not fmod: inputs are
/// differences of in-range angles, so at most one or two turns away.
template <class T>
T wrap_angle(T a) {
  for (int guard = 0; guard < 64 && a > kPi<T>; ++guard) a -= kTwoPi<T>;
  for (int guard = 0; guard < 64 && !(a > -kPi<T>); ++guard) a += kTwoPi<T>;
  return a;
}

/// h(x): [range m, azimuth rad] of state [px, vx, py, vy] (spec 2.6).
template <class T>
Vec2<T> polar_of_state(const Vec4<T>& x) {
  Vec2<T> z;
  z(0) = std::sqrt(x(0) * x(0) + x(2) * x(2));
  z(1) = dmath::datan2(x(2), x(0));
  return z;
}

/// h(x) with M = 2 rows [range m, azimuth rad] or M = 3 rows
/// [range m, azimuth rad, radial velocity m/s] (Doppler, when present).
template <class T, int M>
Eigen::Matrix<T, M, 1> measure_state(const Vec4<T>& x) {
  Eigen::Matrix<T, M, 1> z;
  const T r = std::sqrt(x(0) * x(0) + x(2) * x(2));
  z(0) = r;
  z(1) = dmath::datan2(x(2), x(0));
  if constexpr (M == 3) {
    z(2) = r > T(0) ? (x(0) * x(1) + x(2) * x(3)) / r : T(0);
  }
  return z;
}

/// Moments of h(x) for x ~ N(x_hat, P) (M = 2 or 3 rows, see measure_state):
/// predicted measurement z_hat, its covariance Sz (without R) and the
/// cross-covariance Cxz. Returns false if P is not positive definite
/// (nothing written then).
template <class T, int M>
bool cubature_moments(const Vec4<T>& x_hat, const Mat4<T>& P, Eigen::Matrix<T, M, 1>& z_hat,
                      Eigen::Matrix<T, M, M>& Sz, Eigen::Matrix<T, 4, M>& Cxz) {
  using VecM = Eigen::Matrix<T, M, 1>;
  Mat4<T> L;
  if (!cholesky<T, 4>(P, L)) return false;
  const T scale = T(2);  // sqrt(n), n = 4
  const VecM z_center = measure_state<T, M>(x_hat);

  Vec4<T> dx[8];
  VecM dz[8];
  VecM mean_dz = VecM::Zero();
  for (int p = 0; p < 8; ++p) {
    const int col = p >> 1;
    const T sign = (p & 1) ? T(-1) : T(1);
    dx[p] = sign * scale * L.col(col);
    dz[p] = measure_state<T, M>(x_hat + dx[p]) - z_center;
    dz[p](1) = wrap_angle(dz[p](1));
    mean_dz += dz[p];
  }
  mean_dz *= T(0.125);
  z_hat = z_center + mean_dz;
  z_hat(1) = wrap_angle(z_hat(1));
  Sz.setZero();
  Cxz.setZero();
  for (int p = 0; p < 8; ++p) {
    const VecM e = dz[p] - mean_dz;
    Sz += e * e.transpose();
    Cxz += dx[p] * e.transpose();  // the cubature points' x mean is exactly x_hat
  }
  Sz *= T(0.125);
  Cxz *= T(0.125);
  for (int r = 0; r < M; ++r) {
    for (int c = r + 1; c < M; ++c) Sz(r, c) = Sz(c, r) = T(0.5) * (Sz(r, c) + Sz(c, r));
  }
  return true;
}

/// The 2-row (position only) moments.
template <class T>
bool cubature_polar_moments(const Vec4<T>& x_hat, const Mat4<T>& P, Vec2<T>& z_hat,
                            Mat2<T>& Sz, Mat42<T>& Cxz) {
  return cubature_moments<T, 2>(x_hat, P, z_hat, Sz, Cxz);
}

}  // namespace mptrack::mfbp
