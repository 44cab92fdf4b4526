// Probabilistic data association (PDA) for one slant path track
// (docs/algorithms/mptf.md §Path trackers; Bar-Shalom's PDA filter, which
// the paper's MPTF runs per path, seed 002 Sec. IV). The gated detections
// j = 1..n with innovations v_j and d_j^2 = v_j^T S^-1 v_j get
//   e_j  = p_d N(v_j; 0, S) / lambda,  b = 1 - p_d p_g,
//   beta_j = e_j / (b + sum e),        beta_0 = b / (b + sum e),
// and the update
//   s += K v,  v = sum beta_j v_j,  K = P H^T S^-1,
//   P  = P - (1 - beta_0) K H P + K (sum beta_j v_j v_j^T - v v^T) K^T,
// with H = [I_3 0] (the measurement is a selection of the slant state).
#pragma once

#include <cstddef>

#include <Eigen/Core>

#include "mptrack/math/constants.h"
#include "mptrack/math/detmath.h"
#include "mptrack/model/cholesky.h"
#include "mptrack/model/othr_measurement.h"
#include "mptrack/mptf/slant_track.h"

namespace mptrack::mptf {

/// The innovation covariance S = H P H^T + R of a track, factored.
template <class T>
struct SlantGate {
  Mat3<T> L = Mat3<T>::Identity();  ///< Cholesky factor of S
  T ln_norm = T(0);                 ///< ln of N(0; 0, S): -(3/2) ln 2 pi - (1/2) ln det S
};

/// S of track t with measurement variances r_var [km^2, (km/s)^2, rad^2].
/// False if S is not positive definite.
template <class T>
bool slant_gate(const SlantTrack<T>& t, const model::OthrMeas<T>& r_var, SlantGate<T>& g) {
  Mat3<T> S = t.P.template topLeftCorner<3, 3>();
  for (int r = 0; r < 3; ++r) S(r, r) += r_var(r);
  if (!model::cholesky<T, 3>(S, g.L)) return false;
  g.ln_norm = -T(1.5) * dmath::kLnTwoPi<T>;
  for (int r = 0; r < 3; ++r) g.ln_norm -= dmath::dlog(g.L(r, r));
  return true;
}

/// d^2 = v^T S^-1 v.
template <class T>
T gate_distance2(const SlantGate<T>& g, const model::OthrMeas<T>& v) {
  return model::cholesky_whiten<T, 3>(g.L, v).squaredNorm();
}

/// The PDA update of t from its n gated innovations v[k] with distances
/// d2[k]; ln_pd_lambda = ln(p_d / lambda), miss = 1 - p_d p_g. Returns the
/// index k of the largest beta (or -1 when n is 0: then t is unchanged).
template <class T>
int pda_update(SlantTrack<T>& t, const SlantGate<T>& g, const model::OthrMeas<T>* v, const T* d2, std::size_t n,
               T ln_pd_lambda, T miss, T* beta_scratch) {
  if (n == 0) return -1;
  T ln_max = dmath::dlog(miss);
  for (std::size_t k = 0; k < n; ++k) {
    beta_scratch[k] = ln_pd_lambda + g.ln_norm - T(0.5) * d2[k];
    if (beta_scratch[k] > ln_max) ln_max = beta_scratch[k];
  }
  T sum = miss * dmath::dexp(-ln_max);
  for (std::size_t k = 0; k < n; ++k) {
    beta_scratch[k] = dmath::dexp(beta_scratch[k] - ln_max);
    sum += beta_scratch[k];
  }
  int best = 0;
  model::OthrMeas<T> vbar = model::OthrMeas<T>::Zero();
  Mat3<T> spread = Mat3<T>::Zero();
  for (std::size_t k = 0; k < n; ++k) {
    beta_scratch[k] /= sum;
    if (beta_scratch[k] > beta_scratch[best]) best = static_cast<int>(k);
    vbar += beta_scratch[k] * v[k];
    spread += beta_scratch[k] * (v[k] * v[k].transpose());
  }
  const T beta0 = miss * dmath::dexp(-ln_max) / sum;
  spread -= vbar * vbar.transpose();
  // K^T = S^-1 H P (3x4), K = P H^T S^-1.
  const Eigen::Matrix<T, 3, 4> HP = t.P.template topRows<3>();
  const Eigen::Matrix<T, 3, 4> KT = model::cholesky_solve<T, 3, 4>(g.L, HP);
  const Eigen::Matrix<T, 4, 3> K = KT.transpose();
  t.s += K * vbar;
  const Eigen::Matrix<T, 4, 3> KSp = K * spread;
  Mat4<T> P = t.P - (T(1) - beta0) * (K * HP) + KSp * KT;
  t.P = T(0.5) * (P + P.transpose());
  return best;
}

}  // namespace mptrack::mptf
