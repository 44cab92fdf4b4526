// The SPD guard (spd_guard.h) for a covariance whose axes have very
// different units, such as the OTHR ground state [km, km/s, rad, rad/s]
// whose variances span 1e1 .. 1e-10: keep_spd's diagonal loading is a
// fraction of the LARGEST variance and would swamp the small ones. Here the
// guard runs on the correlation matrix C = D^-1 P D^-1, D = diag(sqrt(P_ii)),
// and P is rebuilt from the repaired C: the policy becomes scale-invariant.
#pragma once

#include <cmath>

#include <Eigen/Core>

#include "mptrack/model/spd_guard.h"

namespace mptrack::model {

/// keep_spd on the correlation matrix of P. Diagonal entries that are not
/// positive and finite are set to min_variance first (that alone counts as
/// a repair). Returns true when a repair beyond symmetrisation was needed.
template <class T, int N>
bool keep_spd_scaled(Eigen::Matrix<T, N, N>& P, T min_variance) {
  bool repaired = false;
  Eigen::Matrix<T, N, 1> d;
  for (int r = 0; r < N; ++r) {
    if (!(P(r, r) > T(0)) || !(P(r, r) - P(r, r) == T(0))) {
      P(r, r) = min_variance;
      repaired = true;
    }
    d(r) = std::sqrt(P(r, r));
  }
  Eigen::Matrix<T, N, N> C;
  for (int r = 0; r < N; ++r) {
    for (int c = 0; c < N; ++c) C(r, c) = P(r, c) / (d(r) * d(c));
  }
  repaired = keep_spd(C, T(1e-6)) || repaired;
  for (int r = 0; r < N; ++r) {
    for (int c = 0; c < N; ++c) P(r, c) = C(r, c) * (d(r) * d(c));
  }
  return repaired;
}

}  // namespace mptrack::model
