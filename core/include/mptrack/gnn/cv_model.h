// Constant-velocity motion model with white-acceleration process noise,
// state [px, vx, py, vy] (track_report.h order), seed 004 spec 2.5:
//   F_axis = [[1, dt], [0, 1]],
//   Q_axis = sigma_a^2 [[dt^4/4, dt^3/2], [dt^3/2, dt^2]]   (per axis, no cross terms).
// The prediction is written out per entry over the 2x2 axis blocks: F is
// block diagonal, so this is F P F^T + Q with a fixed operation order and
// no multiplications by the zeros of F.
#pragma once

#include <Eigen/Core>

namespace mptrack {

template <class T>
using CvState = Eigen::Matrix<T, 4, 1>;  ///< [px m, vx m/s, py m, vy m/s]
template <class T>
using CvCovariance = Eigen::Matrix<T, 4, 4>;

/// Kalman prediction over dt [s] with white-acceleration std accel_std [m/s^2].
template <class T>
void cv_predict(CvState<T>& x, CvCovariance<T>& P, T dt, T accel_std) {
  x(0) += dt * x(1);
  x(2) += dt * x(3);
  // F P: row k of each position block gains dt * the velocity row.
  for (int c = 0; c < 4; ++c) {
    P(0, c) += dt * P(1, c);
    P(2, c) += dt * P(3, c);
  }
  // (F P) F^T: the same on the columns.
  for (int r = 0; r < 4; ++r) {
    P(r, 0) += dt * P(r, 1);
    P(r, 2) += dt * P(r, 3);
  }
  const T q = accel_std * accel_std;
  const T dt2 = dt * dt;
  const T q_pp = q * dt2 * dt2 / T(4);
  const T q_pv = q * dt2 * dt / T(2);
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

}  // namespace mptrack
