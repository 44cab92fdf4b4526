// Constant-velocity (CV) motion model with white-acceleration process noise,
// the one kinematic model of every tracker. State [px m, vx m/s, py m, vy m/s]
// (track_report.h order); per axis (seed 000 eq. (1), seed 004 Sec. II):
//   F_axis = [[1, dt], [0, 1]],
//   Q_axis = q [[dt^4/4, dt^3/2], [dt^3/2, dt^2]],   no cross-axis terms.
// Unit convention: q is the per-axis white-acceleration VARIANCE [m^2/s^4]
// (sigma_a^2), the accel_var_m2ps4 field of every tracker's Params
// (tracker_params.h).
#pragma once

#include <Eigen/Core>

namespace mptrack::model {

template <class T>
using CvState = Eigen::Matrix<T, 4, 1>;  ///< [px m, vx m/s, py m, vy m/s]
template <class T>
using CvCovariance = Eigen::Matrix<T, 4, 4>;

/// F and Q of the CV model over dt [s] with acceleration variance q [m^2/s^4].
template <class T>
void cv_transition(T dt_s, T q, CvCovariance<T>& F, CvCovariance<T>& Q) {
  F.setIdentity();
  F(0, 1) = dt_s;
  F(2, 3) = dt_s;
  const T dt2 = dt_s * dt_s;
  const T q11 = q * dt2 * dt2 * T(0.25);
  const T q12 = q * dt2 * dt_s * T(0.5);
  const T q22 = q * dt2;
  Q.setZero();
  Q(0, 0) = q11;
  Q(0, 1) = q12;
  Q(1, 0) = q12;
  Q(1, 1) = q22;
  Q(2, 2) = q11;
  Q(2, 3) = q12;
  Q(3, 2) = q12;
  Q(3, 3) = q22;
}

/// Kalman prediction x <- F x, P <- F P F^T + Q over dt [s] with
/// acceleration variance q [m^2/s^4], written out per entry: F is block
/// diagonal, so this skips the multiplications by its zeros and fixes the
/// operation order (not the same bits as F * P * F^T through Eigen).
template <class T>
void cv_predict(CvState<T>& x, CvCovariance<T>& P, T dt_s, T q) {
  x(0) += dt_s * x(1);
  x(2) += dt_s * x(3);
  // F P: row k of each position block gains dt * the velocity row.
  for (int c = 0; c < 4; ++c) {
    P(0, c) += dt_s * P(1, c);
    P(2, c) += dt_s * P(3, c);
  }
  // (F P) F^T: the same on the columns.
  for (int r = 0; r < 4; ++r) {
    P(r, 0) += dt_s * P(r, 1);
    P(r, 2) += dt_s * P(r, 3);
  }
  const T dt2 = dt_s * dt_s;
  const T q_pp = q * dt2 * dt2 / T(4);
  const T q_pv = q * dt2 * dt_s / T(2);
  const T q_vv = q * dt2;
  P(0, 0) += q_pp;
  P(0, 1) += q_pv;
  P(1, 0) += q_pv;
  P(1, 1) += q_vv;
  P(2, 2) += q_pp;
  P(2, 3) += q_pv;
  P(3, 2) += q_pv;
  P(3, 3) += q_vv;
}

}  // namespace mptrack::model
