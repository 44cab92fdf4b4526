// Keeping a 4x4 state covariance symmetric positive definite in float.
//
// The Joseph-form update keeps P symmetric PSD in exact arithmetic; in float
// it can still lose definiteness when a track is updated many times with a
// precise sensor. After every update the tracker symmetrises P and tries a
// Cholesky factorisation (plain loops, fixed order); if a pivot is not
// positive, P is replaced by its diagonal floored at min_variance, which
// is SPD by construction, and the repair is counted
// (TrackerCounters::numerical_repairs). Dropping the correlations is
// conservative (it forgets information, it never invents it).
#pragma once

#include <cmath>

#include <Eigen/Core>

namespace mptrack {

/// P <- (P + P^T) / 2.
template <class T, int N>
void symmetrize(Eigen::Matrix<T, N, N>& P) {
  for (int r = 0; r < N; ++r) {
    for (int c = r + 1; c < N; ++c) {
      const T m = (P(r, c) + P(c, r)) / T(2);
      P(r, c) = m;
      P(c, r) = m;
    }
  }
}

/// True if the Cholesky factorisation of symmetric P succeeds with every
/// pivot > 0 and finite (NaN fails too).
template <class T, int N>
bool is_spd(const Eigen::Matrix<T, N, N>& P) {
  Eigen::Matrix<T, N, N> L = Eigen::Matrix<T, N, N>::Zero();
  for (int j = 0; j < N; ++j) {
    T d = P(j, j);
    for (int k = 0; k < j; ++k) d -= L(j, k) * L(j, k);
    if (!(d > T(0)) || !(d - d == T(0))) return false;
    const T l_jj = std::sqrt(d);
    L(j, j) = l_jj;
    for (int i = j + 1; i < N; ++i) {
      T s = P(i, j);
      for (int k = 0; k < j; ++k) s -= L(i, k) * L(j, k);
      L(i, j) = s / l_jj;
    }
  }
  return true;
}

/// Symmetrises P; if it is then not SPD, replaces it with its floored
/// diagonal. Returns true when that repair was needed.
template <class T, int N>
bool keep_spd(Eigen::Matrix<T, N, N>& P, T min_variance) {
  symmetrize(P);
  if (is_spd(P)) return false;
  for (int r = 0; r < N; ++r) {
    for (int c = 0; c < N; ++c) {
      if (r != c) P(r, c) = T(0);
    }
    const T d = P(r, r);
    P(r, r) = (d > min_variance && d - d == T(0)) ? d : min_variance;
  }
  return true;
}

}  // namespace mptrack
