// Measurement models of the GM filters (GM-PHD, GM-CPHD, CBMeMBer): polar
// (range, azimuth) of model/polar_measurement.h, linearised at the
// predicted mean (EKF, the usual GM-PHD treatment of a nonlinear h), or
// Cartesian position as in seed 001 eq. (87): H = [1 0 0 0; 0 0 1 0],
// R = sigma^2 I.
//
// measurement.h carries (range, azimuth) only, so a Cartesian sensor's
// (x, y) arrives as its polar form and is converted back here
// (x = r cos az, y = r sin az, deterministic dsincos).
#pragma once

#include <cmath>
#include <cstdint>

#include <Eigen/Core>

#include "mptrack/math/detmath.h"
#include "mptrack/measurement.h"
#include "mptrack/model/mahalanobis.h"
#include "mptrack/model/polar_measurement.h"
#include "mptrack/tracker_params.h"

namespace mptrack::rfs {

template <class T>
using Vec2 = Eigen::Matrix<T, 2, 1>;
template <class T>
using Mat2 = Eigen::Matrix<T, 2, 2>;
template <class T>
using Vec4 = Eigen::Matrix<T, 4, 1>;
template <class T>
using Mat4 = Eigen::Matrix<T, 4, 4>;
template <class T>
using Mat24 = Eigen::Matrix<T, 2, 4>;

/// The sensor geometry and noise, fixed at init().
template <class T>
struct MeasurementModel {
  MeasurementSpace space = MeasurementSpace::kPolar;
  Mat2<T> R = Mat2<T>::Identity();  ///< measurement noise covariance [m^2 | rad^2]

  /// z as the filter uses it (Cartesian: converted from the polar fields).
  Vec2<T> vector_of(const Measurement<T>& y) const {
    Vec2<T> z;
    if (space == MeasurementSpace::kPolar) {
      z << y.range_m, y.azimuth_rad;
    } else {
      z = model::cartesian_of_polar(y.range_m, y.azimuth_rad);
    }
    return z;
  }

  /// h(x) and its Jacobian at x (state [px, vx, py, vy]).
  void linearize(const Vec4<T>& x, Vec2<T>& z_hat, Mat24<T>& H) const {
    H.setZero();
    if (space == MeasurementSpace::kCartesian) {
      z_hat << x(0), x(2);
      H(0, 0) = T(1);
      H(1, 2) = T(1);
      return;
    }
    const T r2raw = x(0) * x(0) + x(2) * x(2);
    const T r2 = r2raw > T(1e-6) ? r2raw : T(1e-6);  // the origin is outside every polar region
    model::polar_linearize(x, r2, z_hat, H);
  }

  /// z - z_hat, azimuth wrapped to (-pi, pi].
  Vec2<T> residual(const Vec2<T>& z, const Vec2<T>& z_hat) const {
    Vec2<T> v = z - z_hat;
    if (space == MeasurementSpace::kPolar) v(1) = model::wrap_angle(v(1));
    return v;
  }

  /// Position (px, py) of z and its covariance (J R J^T for polar): used to
  /// place a birth component on a measurement.
  void position_of(const Vec2<T>& z, Vec2<T>& p, Mat2<T>& cov) const {
    if (space == MeasurementSpace::kCartesian) {
      p = z;
      cov = R;
      return;
    }
    T s = T(0);
    T c = T(0);
    dmath::dsincos(z(1), s, c);
    p << z(0) * c, z(0) * s;
    // Cross-range spread floored at 1e-3 x the range std (as in the GNN's
    // polar_initiate): at r -> 0 J R J^T is rank one. Binds only below
    // r = 1e-3 sigma_r / sigma_az.
    const T r_floor = T(1e-3) * std::sqrt(R(0, 0) / R(1, 1));
    const T r_cov = z(0) > r_floor ? z(0) : r_floor;
    Mat2<T> J;
    J << c, -r_cov * s, s, r_cov * c;
    cov = J * R * J.transpose();
  }
};

/// Inverse and log-determinant of a 2x2 SPD matrix by the explicit formula
/// (fixed operation order). False if not SPD.
template <class T>
bool invert_spd2(const Mat2<T>& S, Mat2<T>& S_inv, T& log_det) {
  const T det = model::det2(S);
  if (!(det > T(0)) || !(S(0, 0) > T(0))) return false;
  S_inv << S(1, 1) / det, -S(0, 1) / det, -S(1, 0) / det, S(0, 0) / det;
  log_det = dmath::dlog(det);
  return true;
}

/// ln N(v; 0, S) from S^-1 and ln|S|.
template <class T>
T log_gauss2(const Vec2<T>& v, const Mat2<T>& S_inv, T log_det) {
  const T q = v(0) * (S_inv(0, 0) * v(0) + S_inv(0, 1) * v(1)) +
              v(1) * (S_inv(1, 0) * v(0) + S_inv(1, 1) * v(1));
  // dlog(2 pi) rather than dmath::kLnTwoPi: in double it is 1 ulp below
  // the correctly rounded constant, and switching moves the double PHD,
  // CPHD and CBMeMBer goldens (left for a deliberate golden change).
  return -dmath::dlog(T(2) * dmath::kPi<T>) - T(0.5) * log_det - T(0.5) * q;
}

/// Mahalanobis distance d^2 = v^T S^-1 v.
template <class T>
T mahalanobis2(const Vec2<T>& v, const Mat2<T>& S_inv) {
  return v(0) * (S_inv(0, 0) * v(0) + S_inv(0, 1) * v(1)) +
         v(1) * (S_inv(1, 0) * v(0) + S_inv(1, 1) * v(1));
}

}  // namespace mptrack::rfs
