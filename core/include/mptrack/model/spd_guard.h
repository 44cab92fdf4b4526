// The one SPD guard of every tracker: keeps a covariance symmetric positive
// definite, and well conditioned enough for float, after each update.
//
// Kalman, cubature and RTS updates keep P symmetric PSD in exact
// arithmetic; in float they can lose definiteness (a track updated many
// times by a precise sensor), or leave a pivot so small that the next
// rounding makes P indefinite. The policy:
//  1. symmetrise: P <- (P + P^T) / 2;
//  2. test (is_well_conditioned_spd): the Cholesky factorisation succeeds
//     with every pivot positive and finite, AND every squared pivot is at
//     least kMinPivotRatio = 1e-4 of its diagonal entry. A smaller pivot
//     means a multiple correlation above 0.99995: such a float matrix
//     passes a plain Cholesky but not Eigen's LLT after the next rounding
//     (fuzz finding F14, docs/reliability.md). Real track covariances stay
//     far from it;
//  3. repair by escalating diagonal loading: up to 8 times, add
//     1e-6 * 10^k * max diag(P) to the diagonal (non-positive diagonal
//     entries first set to 0), stopping at the first load that passes the
//     test. Loading adds uncertainty, it never removes it;
//  4. if P still fails (NaN or inf entries, or an indefiniteness larger than
//     10 x its largest variance), replace P by its diagonal floored at
//     min_variance: SPD by construction, and conservative (it forgets the
//     correlations, it never invents information).
// The caller counts a repair (return value true) in
// TrackerCounters::numerical_repairs. Units: those of P; min_variance in
// the units of P's diagonal. Fixed operation order: same bits on every target.
#pragma once

#include <Eigen/Core>

#include "mptrack/model/cholesky.h"

namespace mptrack::model {

/// Smallest accepted ratio pivot^2 / diagonal (F14, see the file comment).
template <class T>
inline constexpr T kMinPivotRatio = T(1e-4);

/// Diagonal floor of the last-resort repair for callers without their own
/// (MF-BP) [units of P's diagonal].
template <class T>
inline constexpr T kDefaultMinVariance = T(1e-6);

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

/// Step 2 of the policy: Cholesky succeeds, every pivot finite and
/// pivot^2 >= kMinPivotRatio * diagonal.
template <class T, int N>
bool is_well_conditioned_spd(const Eigen::Matrix<T, N, N>& P) {
  Eigen::Matrix<T, N, N> L;
  if (!cholesky<T, N>(P, L)) return false;
  for (int j = 0; j < N; ++j) {
    const T pivot2 = L(j, j) * L(j, j);
    if (!(pivot2 - pivot2 == T(0)) || !(pivot2 >= kMinPivotRatio<T> * P(j, j))) return false;
  }
  return true;
}

/// Symmetrises P and, if it then fails the test, repairs it (steps 3, 4).
/// Returns true when a repair beyond symmetrisation was needed.
template <class T, int N>
bool keep_spd(Eigen::Matrix<T, N, N>& P, T min_variance) {
  symmetrize(P);
  for (int attempt = 0; attempt < 8; ++attempt) {
    if (is_well_conditioned_spd(P)) return attempt > 0;
    T scale = T(0);
    for (int r = 0; r < N; ++r) scale = P(r, r) > scale ? P(r, r) : scale;
    T load = scale * T(1e-6);
    for (int k = 0; k < attempt; ++k) load *= T(10);
    if (!(load > T(0))) load = T(1e-6);
    for (int r = 0; r < N; ++r) {
      if (!(P(r, r) > T(0))) P(r, r) = T(0);
      P(r, r) += load;
    }
  }
  if (is_well_conditioned_spd(P)) return true;
  for (int r = 0; r < N; ++r) {
    for (int c = 0; c < N; ++c) {
      if (r != c) P(r, c) = T(0);
    }
    const T d = P(r, r);
    P(r, r) = (d > min_variance && d - d == T(0)) ? d : min_variance;
  }
  return true;
}

}  // namespace mptrack::model
