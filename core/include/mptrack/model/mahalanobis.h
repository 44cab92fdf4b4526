// Checked squared Mahalanobis distances: the 2-D measurement space
// (range, azimuth) used by every tracker's gates and likelihoods, and the
// N-D (4-D state) form through the Cholesky factor.
//
// d^2 = e^T C^-1 e for a 2x2 covariance C, through the adjugate:
//   d^2 = (C11 e0^2 - 2 C01 e0 e1 + C00 e1^2) / det C,   det C = C00 C11 - C01 C10.
// C must be symmetric positive definite; the check is det C > 0 and
// finite (with C00 > 0 this is Sylvester's criterion for 2x2). A caller
// that skips the check divides by a non-positive determinant and gets a
// negative or infinite distance that passes every "d^2 < gate" test, so
// the only way to get a distance here is through the check.
// Fixed operation order: same bits on every target (docs/architecture.md).
#pragma once

#include <Eigen/Core>

#include "mptrack/model/cholesky.h"

namespace mptrack::model {

/// det C of a 2x2 matrix, in the order every caller uses.
template <class T>
T det2(const Eigen::Matrix<T, 2, 2>& C) {
  return C(0, 0) * C(1, 1) - C(0, 1) * C(1, 0);
}

/// One 2x2 covariance, checked once, measured against many residuals.
template <class T>
class Mahalanobis2 {
 public:
  explicit Mahalanobis2(const Eigen::Matrix<T, 2, 2>& C) : C_(C), det_(det2(C)) {}

  /// True if C is usable: det C > 0 and finite, C00 > 0.
  bool valid() const { return det_ > T(0) && det_ - det_ == T(0) && C_(0, 0) > T(0); }
  /// det C (meaningful when valid()).
  T det() const { return det_; }

  /// d^2 for residual (e0, e1); only call when valid().
  T distance2(T e0, T e1) const {
    return (C_(1, 1) * e0 * e0 - T(2) * C_(0, 1) * e0 * e1 + C_(0, 0) * e1 * e1) / det_;
  }
  T distance2(const Eigen::Matrix<T, 2, 1>& e) const { return distance2(e(0), e(1)); }

 private:
  Eigen::Matrix<T, 2, 2> C_;
  T det_;
};

/// d^2 = e^T C^-1 e into d2; false (d2 untouched) if C is not usable.
template <class T>
bool mahalanobis2(const Eigen::Matrix<T, 2, 1>& e, const Eigen::Matrix<T, 2, 2>& C, T& d2) {
  const Mahalanobis2<T> m(C);
  if (!m.valid()) return false;
  d2 = m.distance2(e);
  return true;
}

/// N x N (e.g. 4x4 state space) d^2 = e^T C^-1 e through the Cholesky
/// factor: d^2 = e . (L L^T)^-1 e (forward and back substitution, fixed
/// order). False (d2 untouched) if C is not positive definite.
template <class T, int N>
bool mahalanobis_n(const Eigen::Matrix<T, N, 1>& e, const Eigen::Matrix<T, N, N>& C, T& d2) {
  Eigen::Matrix<T, N, N> L;
  if (!cholesky<T, N>(C, L)) return false;
  d2 = e.dot(cholesky_solve<T, N, 1>(L, e));
  return true;
}

}  // namespace mptrack::model
