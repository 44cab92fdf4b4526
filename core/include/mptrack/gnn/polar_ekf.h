// Polar (range, azimuth) measurements of a Cartesian CV state: EKF pieces.
//
// Choice (seed 004 Sec. V-A leaves it open): an EKF update rather than a
// converted-measurement KF. Range and azimuth noises are independent in
// the sensor's own coordinates, so R = diag(sigma_r^2, sigma_az^2) is exact;
// a converted measurement would need a range-dependent, correlated
// Cartesian R (and a debiasing term at large cross-range error). The EKF
// linearises h at the predicted state, where the error is far smaller.
//
//   h(x), H: model/polar_measurement.h (range, azimuth rows)
//   S = H P H^T + R,  K = P H^T S^-1,
//   Joseph form: P <- (I - K H) P (I - K H)^T + K R K^T
//     (Bar-Shalom, Li, Kirubarajan 2001, eq. 5.2.3-18; stays PSD under
//      rounding, unlike P - K S K^T).
// Azimuth innovations are wrapped to [-pi, pi]. Only dmath is used for the
// transcendental functions (README.md §Conventions a firmware engineer can rely on).
#pragma once

#include <cmath>

#include <Eigen/Core>

#include "mptrack/math/constants.h"
#include "mptrack/math/detmath.h"
#include "mptrack/model/cv_motion.h"
#include "mptrack/model/mahalanobis.h"
#include "mptrack/model/polar_measurement.h"

namespace mptrack::gnn {

/// Everything gating and updating need from one track's prediction.
template <class T>
struct PolarPrediction {
  Eigen::Matrix<T, 2, 1> z_hat = Eigen::Matrix<T, 2, 1>::Zero();  ///< [range m, azimuth rad]
  Eigen::Matrix<T, 2, 4> H = Eigen::Matrix<T, 2, 4>::Zero();      ///< Jacobian of h at x
  Eigen::Matrix<T, 2, 2> S = Eigen::Matrix<T, 2, 2>::Zero();      ///< innovation covariance
  Eigen::Matrix<T, 2, 2> S_inv = Eigen::Matrix<T, 2, 2>::Zero();  ///< its inverse (closed form)
  bool valid = false;  ///< false: range ~ 0 or S not SPD, the track cannot be gated
};

/// Ranges below this cannot be linearised (H has a 1/r^2 term) [m].
template <class T>
constexpr T kMinLinearisationRange = T(1e-3);

/// Predicted measurement, Jacobian and innovation covariance of (x, P).
template <class T>
PolarPrediction<T> polar_predict(const model::CvState<T>& x, const model::CvCovariance<T>& P, T sigma_range_m,
                                 T sigma_azimuth_rad) {
  PolarPrediction<T> out;
  const T px = x(0);
  const T py = x(2);
  const T r2 = px * px + py * py;
  const T r = std::sqrt(r2);
  if (!(r > kMinLinearisationRange<T>)) return out;
  model::polar_linearize(x, r2, out.z_hat, out.H);
  const Eigen::Matrix<T, 4, 2> PHt = P * out.H.transpose();
  out.S = out.H * PHt;
  // Symmetrise before adding R so S is exactly symmetric.
  const T s01 = (out.S(0, 1) + out.S(1, 0)) / T(2);
  out.S(0, 1) = s01;
  out.S(1, 0) = s01;
  out.S(0, 0) += sigma_range_m * sigma_range_m;
  out.S(1, 1) += sigma_azimuth_rad * sigma_azimuth_rad;
  const model::Mahalanobis2<T> checked(out.S);  // det > 0 and finite, S00 > 0
  if (!checked.valid()) return out;
  const T det = checked.det();
  out.S_inv(0, 0) = out.S(1, 1) / det;
  out.S_inv(1, 1) = out.S(0, 0) / det;
  out.S_inv(0, 1) = -s01 / det;
  out.S_inv(1, 0) = -s01 / det;
  out.valid = true;
  return out;
}

/// z - h(x) with the azimuth difference wrapped to [-pi, pi]. Both
/// azimuths lie in [-pi, pi], so one correction of 2 pi is enough.
template <class T>
Eigen::Matrix<T, 2, 1> polar_innovation(T range_m, T azimuth_rad, const PolarPrediction<T>& pred) {
  Eigen::Matrix<T, 2, 1> nu;
  nu(0) = range_m - pred.z_hat(0);
  T da = azimuth_rad - pred.z_hat(1);
  if (da > dmath::kPi<T>) {
    da -= dmath::kTwoPi<T>;
  } else if (da < -dmath::kPi<T>) {
    da += dmath::kTwoPi<T>;
  }
  nu(1) = da;
  return nu;
}

/// Squared Mahalanobis distance nu^T S^-1 nu, written out (fixed order).
template <class T>
T mahalanobis2(const Eigen::Matrix<T, 2, 1>& nu, const PolarPrediction<T>& pred) {
  return pred.S_inv(0, 0) * nu(0) * nu(0) + T(2) * pred.S_inv(0, 1) * nu(0) * nu(1) +
         pred.S_inv(1, 1) * nu(1) * nu(1);
}

/// EKF update with the Joseph-form covariance (pred must be valid).
template <class T>
void polar_update(model::CvState<T>& x, model::CvCovariance<T>& P, const Eigen::Matrix<T, 2, 1>& nu,
                  const PolarPrediction<T>& pred, T sigma_range_m, T sigma_azimuth_rad) {
  const Eigen::Matrix<T, 4, 2> PHt = P * pred.H.transpose();
  const Eigen::Matrix<T, 4, 2> K = PHt * pred.S_inv;
  x += K * nu;
  const model::CvCovariance<T> A = model::CvCovariance<T>::Identity() - K * pred.H;
  Eigen::Matrix<T, 2, 2> R = Eigen::Matrix<T, 2, 2>::Zero();
  R(0, 0) = sigma_range_m * sigma_range_m;
  R(1, 1) = sigma_azimuth_rad * sigma_azimuth_rad;
  const model::CvCovariance<T> AP = A * P;
  const Eigen::Matrix<T, 4, 2> KR = K * R;
  P = AP * A.transpose() + KR * K.transpose();
}

/// Single-point initiation (docs/algorithms/gnn.md §Update): position from the measurement,
/// velocity 0. Position covariance J R J^T with J = d(x, y)/d(r, az) at
/// the measurement; velocity covariance init_velocity_std^2 I.
template <class T>
void polar_initiate(T range_m, T azimuth_rad, T sigma_range_m, T sigma_azimuth_rad,
                    T init_velocity_std_mps, model::CvState<T>& x, model::CvCovariance<T>& P) {
  T s;
  T c;
  dmath::dsincos(azimuth_rad, s, c);
  x = model::CvState<T>::Zero();
  x(0) = range_m * c;
  x(2) = range_m * s;
  const T var_r = sigma_range_m * sigma_range_m;
  // Cross-range std floored at 1e-3 x the range std: near r = 0 the polar
  // covariance is rank one (fuzz_params, docs/reliability.md F12), and the
  // floor keeps the position block's condition number <= 1e6, which float
  // factorises. GnnParams bounds the other side (region.range_max_m azimuth std <=
  // 1e3 sigma_r). The floor only binds below r = 1e-3 sigma_r / sigma_az
  // (2 cm with the defaults).
  const T r_floor = T(1e-3) * sigma_range_m / sigma_azimuth_rad;
  const T r_cov = range_m > r_floor ? range_m : r_floor;
  const T var_a = r_cov * r_cov * sigma_azimuth_rad * sigma_azimuth_rad;  // cross-range [m^2]
  P = model::CvCovariance<T>::Zero();
  P(0, 0) = c * c * var_r + s * s * var_a;
  P(2, 2) = s * s * var_r + c * c * var_a;
  const T cross = s * c * (var_r - var_a);
  P(0, 2) = cross;
  P(2, 0) = cross;
  const T var_v = init_velocity_std_mps * init_velocity_std_mps;
  P(1, 1) = var_v;
  P(3, 3) = var_v;
}

}  // namespace mptrack::gnn
