// Cubature transform of a Cartesian CV state through the polar measurement
// function h(x) of model/polar_measurement.h (docs/algorithms/models.md
// §Polar measurement model).
//
// Third-degree spherical-radial cubature: 2 n = 8 points x +- sqrt(n) L e_i
// with equal weights 1/8 (docs/algorithms/models.md §Polar measurement model: no
// negative weights). Azimuth deviations are wrapped to (-pi, pi] around h(x_hat)
// before averaging, so a track near the +-pi cut keeps a consistent mean.
#pragma once

#include <Eigen/Core>

#include "mptrack/math/detmath.h"
#include "mptrack/model/cholesky.h"
#include "mptrack/model/polar_measurement.h"

namespace mptrack::mfbp {

template <class T> using Vec2 = Eigen::Matrix<T, 2, 1>;
template <class T> using Vec4 = Eigen::Matrix<T, 4, 1>;
template <class T> using Mat2 = Eigen::Matrix<T, 2, 2>;
template <class T> using Mat4 = Eigen::Matrix<T, 4, 4>;
template <class T> using Mat42 = Eigen::Matrix<T, 4, 2>;

namespace detail {

/// cubature_moments() below; kCross = false skips the cross-covariance
/// (the callers that only gate or score, never update, do not use it).
template <class T, int M, bool kCross>
bool cubature_moments_impl(const Vec4<T>& x_hat, const Mat4<T>& P, Eigen::Matrix<T, M, 1>& z_hat,
                           Eigen::Matrix<T, M, M>& Sz, Eigen::Matrix<T, 4, M>* Cxz) {
  using VecM = Eigen::Matrix<T, M, 1>;
  Mat4<T> L;
  if (!model::cholesky<T, 4>(P, L)) return false;
  const T scale = T(2);  // sqrt(n), n = 4
  const VecM z_center = model::polar_measure<T, M>(x_hat);

  Vec4<T> dx[8];
  VecM dz[8];
  VecM mean_dz = VecM::Zero();
  for (int p = 0; p < 8; ++p) {
    const int col = p >> 1;
    const T sign = (p & 1) ? T(-1) : T(1);
    dx[p] = sign * scale * L.col(col);
    dz[p] = model::polar_measure<T, M>(x_hat + dx[p]) - z_center;
    dz[p](1) = model::wrap_angle(dz[p](1));
    mean_dz += dz[p];
  }
  mean_dz *= T(0.125);
  z_hat = z_center + mean_dz;
  z_hat(1) = model::wrap_angle(z_hat(1));
  Sz.setZero();
  if constexpr (kCross) Cxz->setZero();
  for (int p = 0; p < 8; ++p) {
    const VecM e = dz[p] - mean_dz;
    Sz += e * e.transpose();
    if constexpr (kCross) *Cxz += dx[p] * e.transpose();  // the cubature points' x mean is exactly x_hat
  }
  Sz *= T(0.125);
  if constexpr (kCross) *Cxz *= T(0.125);
  for (int r = 0; r < M; ++r) {
    for (int c = r + 1; c < M; ++c) Sz(r, c) = Sz(c, r) = T(0.5) * (Sz(r, c) + Sz(c, r));
  }
  return true;
}

}  // namespace detail

/// Moments of h(x) for x ~ N(x_hat, P) (M = 2 or 3 rows, see model::polar_measure):
/// predicted measurement z_hat, its covariance Sz (without R) and the
/// cross-covariance Cxz. Returns false if P is not positive definite
/// (nothing written then).
template <class T, int M>
bool cubature_moments(const Vec4<T>& x_hat, const Mat4<T>& P, Eigen::Matrix<T, M, 1>& z_hat,
                      Eigen::Matrix<T, M, M>& Sz, Eigen::Matrix<T, 4, M>& Cxz) {
  return detail::cubature_moments_impl<T, M, true>(x_hat, P, z_hat, Sz, &Cxz);
}

/// z_hat and Sz of cubature_moments() (the same bits) without the
/// cross-covariance.
template <class T, int M>
bool cubature_measurement_moments(const Vec4<T>& x_hat, const Mat4<T>& P, Eigen::Matrix<T, M, 1>& z_hat,
                                  Eigen::Matrix<T, M, M>& Sz) {
  return detail::cubature_moments_impl<T, M, false>(x_hat, P, z_hat, Sz, nullptr);
}

/// The 2-row (position only) moments.
template <class T>
bool cubature_polar_moments(const Vec4<T>& x_hat, const Mat4<T>& P, Vec2<T>& z_hat,
                            Mat2<T>& Sz, Mat42<T>& Cxz) {
  return cubature_moments<T, 2>(x_hat, P, z_hat, Sz, Cxz);
}

}  // namespace mptrack::mfbp
