// Nearly-constant-velocity motion with continuous white-noise acceleration
// given as a power spectral density per axis (seed 002 Sec. IV: q = 1e-8 in
// ground range and in bearing). State [p0, v0, p1, v1], per axis
//   F_axis = [[1, T], [0, 1]],   Q_axis = q_axis [[T^3/3, T^2/2], [T^2/2, T]].
// The axes may have different units and PSDs (ground range km and bearing
// rad in the OTHR model); model/cv_motion.h is the discrete white-
// acceleration variant with one variance for both Cartesian axes.
#pragma once

#include <Eigen/Core>

namespace mptrack::model {

/// x <- F x, P <- F P F^T + Q over dt [s] with PSDs q0 (axis 0) and q1
/// (axis 1) [unit^2/s^3], written as matrix products (fixed order).
template <class T>
void cwna_predict(Eigen::Matrix<T, 4, 1>& x, Eigen::Matrix<T, 4, 4>& P, T dt_s, T q0, T q1) {
  Eigen::Matrix<T, 4, 4> F = Eigen::Matrix<T, 4, 4>::Identity();
  F(0, 1) = dt_s;
  F(2, 3) = dt_s;
  const T t3 = dt_s * dt_s * dt_s / T(3);
  const T t2 = dt_s * dt_s / T(2);
  Eigen::Matrix<T, 4, 4> Q = Eigen::Matrix<T, 4, 4>::Zero();
  Q(0, 0) = q0 * t3;
  Q(0, 1) = q0 * t2;
  Q(1, 0) = q0 * t2;
  Q(1, 1) = q0 * dt_s;
  Q(2, 2) = q1 * t3;
  Q(2, 3) = q1 * t2;
  Q(3, 2) = q1 * t2;
  Q(3, 3) = q1 * dt_s;
  const Eigen::Matrix<T, 4, 1> xp = F * x;
  x = xp;
  const Eigen::Matrix<T, 4, 4> FP = F * P;
  P = FP * F.transpose() + Q;
}

}  // namespace mptrack::model
