// Two-state visibility HMM per track (seed 000 eqs. (3), (64)-(68);
// docs/algorithms/mfbp.md §Target chain).
//
// Transition T_vis: P(1|1) = p_s, P(1|0) = p_b. Evidence per scan is the
// association message Xi_k(s) (docs/algorithms/mfbp.md §Target chain):
// Xi(1) = 1 - Pd + Pd Lambda, Xi(0) = 1 - eps + eps Lambda, Lambda = sum_j>=1 phi_ij
// (1 where the track did not take part in the association).
#pragma once

#include <cstddef>

namespace mptrack::mfbp {

/// P(s_k = 1) after one transition from P(s_k-1 = 1) = f1.
template <class T>
T visibility_predict(T f1, T p_s, T p_b) {
  return p_s * f1 + p_b * (T(1) - f1);
}

/// Forward-backward over n scans.
/// @param[in]  pred0_1  P(s = 1) predicted for the first scan (f_s at birth)
/// @param[in]  xi1, xi0 evidence Xi_k(1), Xi_k(0), k = 0..n-1
/// @param[out] filt1    forward (filtered) P(s_k = 1)
/// @param[out] smooth1  smoothed b_s(s_k = 1)
/// @param[out] extr1    extrinsic q_k(1) = pred_k(1) g_k(1), normalised
///                      (the message into p(a_i0|s) for the next BP pass)
template <class T>
void visibility_forward_backward(T pred0_1, const T* xi1, const T* xi0, std::size_t n, T p_s,
                                 T p_b, T* filt1, T* smooth1, T* extr1) {
  T pred1 = pred0_1;
  T preds[64];
  for (std::size_t k = 0; k < n; ++k) {
    preds[k < 64 ? k : 63] = pred1;
    const T u1 = xi1[k] * pred1;
    const T u0 = xi0[k] * (T(1) - pred1);
    const T z = u1 + u0;
    filt1[k] = z > T(0) ? u1 / z : pred1;
    pred1 = visibility_predict(filt1[k], p_s, p_b);
  }
  T g1 = T(1), g0 = T(1);  // backward message at k = n-1
  for (std::size_t kk = n; kk-- > 0;) {
    if (kk + 1 < n) {
      const std::size_t k1 = kk + 1;
      const T n1 = p_s * xi1[k1] * g1 + (T(1) - p_s) * xi0[k1] * g0;
      const T n0 = p_b * xi1[k1] * g1 + (T(1) - p_b) * xi0[k1] * g0;
      const T z = n1 + n0;
      g1 = z > T(0) ? n1 / z : T(0.5);
      g0 = z > T(0) ? n0 / z : T(0.5);
    }
    const T f1 = filt1[kk];
    const T s1 = f1 * g1;
    const T s0 = (T(1) - f1) * g0;
    smooth1[kk] = (s1 + s0) > T(0) ? s1 / (s1 + s0) : f1;
    const T p1 = preds[kk < 64 ? kk : 63];
    const T e1 = p1 * g1;
    const T e0 = (T(1) - p1) * g0;
    extr1[kk] = (e1 + e0) > T(0) ? e1 / (e1 + e0) : p1;
  }
}

}  // namespace mptrack::mfbp
