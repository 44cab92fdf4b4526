// Per-path linearisation and the state update of the multipath tracker
// (seed 002 eqs. (28)-(32); docs/algorithms/multipath.md §State update).
//
// Per (track, path) the VB association gives weights E[a^{i,j,tau}]; they
// collapse into one synthetic measurement per path (seed 002 eqs. (29)-(31)):
//   y_bar = sum_j E[a] y_j / w,   R_bar = R / w,   w = sum_j E[a]
// (no update when w is 0). The paths cannot be merged into one measurement
// (each has its own h^tau), so the update uses all of them at once: a
// stacked measurement [y_bar_1; ...; y_bar_NP] with block-diagonal R_bar,
// linearised at the current VB iterate x_lin (iterated EKF). With one
// linearisation point the stacked update equals the sequential per-path
// Kalman updates done here, and in information form it is
//   P^-1 = P_prior^-1 + sum_tau H_tau^T R_bar_tau^-1 H_tau,
// the path fusion of seed 002 eq. (32) without counting the prior once per
// path (docs/algorithms/multipath.md §Departures from the paper).
#pragma once

#include <cstddef>

#include <Eigen/Core>

#include "mptrack/model/cholesky.h"
#include "mptrack/model/othr_measurement.h"
#include "mptrack/multipath/path_track.h"

namespace mptrack::multipath {

/// h^tau, H^tau and the innovation covariance of one (track, path) at the
/// current iterate; the mean-field trace penalty tr(R^-1 H P H^T) of
/// seed 002 eq. (43).
template <class T>
struct PathLinearization {
  model::OthrMeas<T> h = model::OthrMeas<T>::Zero();
  model::OthrJacobian<T> H = model::OthrJacobian<T>::Zero();
  Mat3<T> L = Mat3<T>::Identity();  ///< Cholesky factor of S = H P H^T + R
  T trace_penalty = T(0);
  bool valid = false;  ///< S factorised
};

/// Linearises path `path` of the state (x, P) with diagonal noise r_var.
template <class T>
PathLinearization<T> linearize_path(const model::OthrState<T>& x, const Mat4<T>& P,
                                    const model::OthrPath<T>& path, T baseline_km,
                                    const model::OthrMeas<T>& r_var) {
  PathLinearization<T> lin;
  model::othr_linearize(x, path, baseline_km, lin.h, lin.H);
  const Eigen::Matrix<T, 3, 4> HP = lin.H * P;
  Mat3<T> S = HP * lin.H.transpose();
  lin.trace_penalty = T(0);
  for (int r = 0; r < 3; ++r) {
    lin.trace_penalty += S(r, r) / r_var(r);
    S(r, r) += r_var(r);
  }
  lin.valid = model::cholesky<T, 3>(S, lin.L);
  return lin;
}

/// Squared Mahalanobis distance of residual v under S = L L^T.
template <class T>
T mahalanobis2(const PathLinearization<T>& lin, const model::OthrMeas<T>& v) {
  return model::cholesky_whiten<T, 3>(lin.L, v).squaredNorm();
}

/// One path's term of the stacked update: synthetic measurement y_bar with
/// weight w (R_bar = R / w), linearised at x_lin; updates (x, P) in place
/// (Joseph form). use_rate false: the range-rate residual is 0 (a scan
/// without Doppler). Returns false (and leaves x, P) if S is not SPD.
template <class T>
bool path_update(model::OthrState<T>& x, Mat4<T>& P, const model::OthrState<T>& x_lin,
                 const model::OthrPath<T>& path, T baseline_km, const model::OthrMeas<T>& y_bar,
                 T w, const model::OthrMeas<T>& r_var, bool use_rate) {
  model::OthrMeas<T> h;
  model::OthrJacobian<T> H;
  model::othr_linearize(x_lin, path, baseline_km, h, H);
  model::OthrMeas<T> r_bar;
  for (int r = 0; r < 3; ++r) r_bar(r) = r_var(r) / w;
  const Eigen::Matrix<T, 3, 4> HP = H * P;
  Mat3<T> S = HP * H.transpose();
  for (int r = 0; r < 3; ++r) S(r, r) += r_bar(r);
  Mat3<T> L;
  if (!model::cholesky<T, 3>(S, L)) return false;
  // Residual of the model linearised at x_lin, evaluated at the current x.
  model::OthrMeas<T> v = y_bar - h - H * (x - x_lin);
  if (!use_rate) v(1) = T(0);
  const Eigen::Matrix<T, 4, 3> K = model::cholesky_solve<T, 3, 4>(L, HP).transpose();
  x += K * v;
  const Mat4<T> A = Mat4<T>::Identity() - K * H;
  Mat4<T> Pn = A * P * A.transpose();
  for (int r = 0; r < 3; ++r) Pn += r_bar(r) * K.col(r) * K.col(r).transpose();
  P = Pn;
  return true;
}

}  // namespace mptrack::multipath
