// Polar measurement model of the CV state [px, vx, py, vy] (seed 000 eq. (3),
// seed 004 Sec. II):
//   h(x) = [ r, theta (, r_dot) ],  r = sqrt(px^2 + py^2) [m],
//   theta = atan2(py, px) [rad],   r_dot = (px vx + py vy) / r [m/s],
// its Jacobian for the (range, azimuth) rows
//   H = [[ px/r,    0, py/r,    0],
//        [-py/r^2,  0, px/r^2,  0]],
// the azimuth wrap of residuals, and the polar -> Cartesian position map
// p = r [cos theta, sin theta] used by track initiation and births.
// The update algorithms (EKF, cubature) stay with their trackers. Only
// dmath is used for transcendental functions (fixed bits on every target).
#pragma once

#include <cmath>

#include <Eigen/Core>

#include "mptrack/math/constants.h"
#include "mptrack/math/detmath.h"
#include "mptrack/model/cv_motion.h"

namespace mptrack::model {

/// Wraps an angle difference to (-pi, pi] [rad]. A loop, not fmod: inputs
/// are differences of in-range angles, so at most one or two turns away
/// (the guard bounds the work for garbage input; NaN passes through).
template <class T>
T wrap_angle(T a) {
  for (int guard = 0; guard < 64 && a > dmath::kPi<T>; ++guard) a -= dmath::kTwoPi<T>;
  for (int guard = 0; guard < 64 && !(a > -dmath::kPi<T>); ++guard) a += dmath::kTwoPi<T>;
  return a;
}

/// h(x) with M = 2 rows [range m, azimuth rad] or M = 3 rows
/// [range m, azimuth rad, radial velocity m/s] (0 at r = 0).
template <class T, int M>
Eigen::Matrix<T, M, 1> polar_measure(const CvState<T>& x) {
  static_assert(M == 2 || M == 3, "polar measurement has 2 or 3 rows");
  Eigen::Matrix<T, M, 1> z;
  const T r = std::sqrt(x(0) * x(0) + x(2) * x(2));
  z(0) = r;
  z(1) = dmath::datan2(x(2), x(0));
  if constexpr (M == 3) {
    z(2) = r > T(0) ? (x(0) * x(1) + x(2) * x(3)) / r : T(0);
  }
  return z;
}

/// h(x) = [range m, azimuth rad].
template <class T>
Eigen::Matrix<T, 2, 1> polar_of_state(const CvState<T>& x) {
  Eigen::Matrix<T, 2, 1> z;
  z(0) = std::sqrt(x(0) * x(0) + x(2) * x(2));
  z(1) = dmath::datan2(x(2), x(0));
  return z;
}

/// h(x) and its (range, azimuth) Jacobian H at x, given r2 = px^2 + py^2
/// (the caller may floor it away from 0, where H has a 1/r^2 term).
template <class T>
void polar_linearize(const CvState<T>& x, T r2, Eigen::Matrix<T, 2, 1>& z_hat,
                     Eigen::Matrix<T, 2, 4>& H) {
  const T r = std::sqrt(r2);
  z_hat(0) = r;
  z_hat(1) = dmath::datan2(x(2), x(0));
  H.setZero();
  H(0, 0) = x(0) / r;
  H(0, 2) = x(2) / r;
  H(1, 0) = -x(2) / r2;
  H(1, 2) = x(0) / r2;
}

/// Cartesian position [x m, y m] of the polar point (range_m, azimuth_rad).
template <class T>
Eigen::Matrix<T, 2, 1> cartesian_of_polar(T range_m, T azimuth_rad) {
  T s;
  T c;
  dmath::dsincos(azimuth_rad, s, c);
  return Eigen::Matrix<T, 2, 1>(range_m * c, range_m * s);
}

}  // namespace mptrack::model
