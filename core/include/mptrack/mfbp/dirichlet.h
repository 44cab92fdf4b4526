// Dirichlet belief on the clutter mixing weights (docs/algorithms/mfbp.md
// §Clutter chain).
#pragma once

#include <cstddef>

#include "mptrack/math/detmath.h"

namespace mptrack::mfbp {

/// Prediction (seed 000 eq. (70)): alpha_k|k-1 = kappa M_k-1 alpha / sum(alpha): keeps
/// the mean weights, total pseudo-count kappa times the last clutter count.
/// M_prev is floored at 1 so an empty scan does not collapse the belief.
template <class T>
void dirichlet_predict(const T* alpha_in, T* alpha_out, std::size_t n, T kappa, T m_prev) {
  T total = T(0);
  for (std::size_t t = 0; t < n; ++t) total += alpha_in[t];
  const T m = m_prev > T(1) ? m_prev : T(1);
  const T scale = total > T(0) ? kappa * m / total : T(0);
  for (std::size_t t = 0; t < n; ++t) {
    const T a = alpha_in[t] * scale;
    alpha_out[t] = a > T(1e-3) ? a : T(1e-3);  // psi() needs alpha > 0
  }
}

/// E[ln pi_t] = psi(alpha_t) - psi(sum alpha) (seed 000 eq. (91), corrected:
/// docs/algorithms/mfbp.md §Departures from the paper).
template <class T>
void dirichlet_expected_log(const T* alpha, T* e_log, std::size_t n) {
  T total = T(0);
  for (std::size_t t = 0; t < n; ++t) total += alpha[t];
  const T psi_total = dmath::ddigamma(total);
  for (std::size_t t = 0; t < n; ++t) e_log[t] = dmath::ddigamma(alpha[t]) - psi_total;
}

}  // namespace mptrack::mfbp
