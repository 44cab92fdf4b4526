// Joint Gaussian posterior of the complex amplitudes of K superimposed atoms
// (seed 004 eqs. (12)-(14); docs/algorithms/sbl.md §Joint amplitudes):
//   Lambda = Gram-like Hermitian precision (K x K, the caller fills it:
//            Gram + diag(prior precisions) for the SBL detector,
//            M (.) Gram + lambda_p I for the VMP tracker),
//   mu     = Lambda^-1 b,     C = Lambda^-1,    ln|Lambda|.
// Solved by a complex Cholesky factorisation Lambda = L L^H (L lower
// triangular with a real positive diagonal), written as plain loops on Cx
// (model/complex_value.h): fixed operation order, no heap, no libgcc complex
// helpers; K <= KMax at run time. Whitened units: Lambda dimensionless.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include "mptrack/math/detmath.h"
#include "mptrack/model/complex_value.h"
#include "mptrack/status.h"

namespace mptrack::model {

/// Lambda = L L^H for Hermitian Lambda (lower triangle read; row-major, stride
/// `ld`). False if a pivot is <= 0 or NaN (not positive definite).
template <class T>
bool complex_cholesky(const Cx<T>* a, std::size_t n, std::size_t ld, Cx<T>* l) {
  for (std::size_t j = 0; j < n; ++j) {
    T d = a[j * ld + j].re;
    for (std::size_t k = 0; k < j; ++k) d -= cx_norm2(l[j * ld + k]);
    if (!(d > T(0))) return false;  // also rejects NaN
    const T ljj = std::sqrt(d);
    const T inv = T(1) / ljj;
    l[j * ld + j] = Cx<T>{ljj, T(0)};
    for (std::size_t i = j + 1; i < n; ++i) {
      // L_ij = (A_ij - sum_k L_ik conj(L_jk)) / L_jj
      Cx<T> s = a[i * ld + j];
      for (std::size_t k = 0; k < j; ++k) s = cx_sub(s, cx_mul(l[i * ld + k], cx_conj(l[j * ld + k])));
      l[i * ld + j] = cx_scale(s, inv);
    }
    for (std::size_t i = 0; i < j; ++i) l[i * ld + j] = Cx<T>{};  // upper triangle zero
  }
  return true;
}

/// x = Lambda^-1 b from the factor L (forward L y = b, back L^H x = y).
template <class T>
void complex_cholesky_solve(const Cx<T>* l, std::size_t n, std::size_t ld, const Cx<T>* b, Cx<T>* x) {
  for (std::size_t i = 0; i < n; ++i) {
    Cx<T> s = b[i];
    for (std::size_t k = 0; k < i; ++k) s = cx_sub(s, cx_mul(l[i * ld + k], x[k]));
    x[i] = cx_scale(s, T(1) / l[i * ld + i].re);
  }
  for (std::size_t ii = n; ii-- > 0;) {
    Cx<T> s = x[ii];
    for (std::size_t k = ii + 1; k < n; ++k) s = cx_sub(s, cx_cmul(l[k * ld + ii], x[k]));
    x[ii] = cx_scale(s, T(1) / l[ii * ld + ii].re);
  }
}

/// The joint amplitude posterior of up to KMax atoms.
template <class T, std::size_t KMax>
class JointAmplitude {
 public:
  static constexpr std::size_t kMax = KMax;

  /// Sets the size (<= KMax) and zeroes Lambda. kCapacityExceeded if n > KMax.
  Status reset(std::size_t n) {
    if (n > KMax) return Status::kCapacityExceeded;
    n_ = n;
    for (std::size_t i = 0; i < KMax * KMax; ++i) lambda_[i] = Cx<T>{};
    return Status::kOk;
  }
  std::size_t size() const { return n_; }

  /// Lambda(i, j) for i >= j (the lower triangle is what solve() reads).
  Cx<T>& lambda(std::size_t i, std::size_t j) { return lambda_[i * KMax + j]; }
  Cx<T> lambda(std::size_t i, std::size_t j) const { return lambda_[i * KMax + j]; }

  /// Factorises Lambda, then mu = Lambda^-1 b, C = Lambda^-1 (full Hermitian)
  /// and ln|Lambda| = 2 sum ln L_jj. kNumericalError if Lambda is not positive
  /// definite (mu, C unspecified).
  Status solve(const Cx<T>* b) {
    if (!complex_cholesky(lambda_.data(), n_, KMax, l_.data())) return Status::kNumericalError;
    complex_cholesky_solve(l_.data(), n_, KMax, b, mu_.data());
    std::array<Cx<T>, KMax> e{};
    std::array<Cx<T>, KMax> col{};
    for (std::size_t j = 0; j < n_; ++j) {
      for (std::size_t i = 0; i < n_; ++i) e[i] = Cx<T>{i == j ? T(1) : T(0), T(0)};
      complex_cholesky_solve(l_.data(), n_, KMax, e.data(), col.data());
      for (std::size_t i = j; i < n_; ++i) cov_[i * KMax + j] = col[i];
    }
    // C is Hermitian: mirror the lower triangle, real diagonal (exactly).
    for (std::size_t i = 0; i < n_; ++i) {
      cov_[i * KMax + i].im = T(0);
      for (std::size_t j = i + 1; j < n_; ++j) cov_[i * KMax + j] = cx_conj(cov_[j * KMax + i]);
    }
    log_det_ = T(0);
    for (std::size_t j = 0; j < n_; ++j) log_det_ += T(2) * dmath::dlog(l_[j * KMax + j].re);
    return Status::kOk;
  }

  /// Posterior mean mu_i (after solve()).
  Cx<T> mu(std::size_t i) const { return mu_[i]; }
  /// Posterior covariance C(i, j) = [Lambda^-1]_ij (after solve()).
  Cx<T> cov(std::size_t i, std::size_t j) const { return cov_[i * KMax + j]; }
  /// ln|Lambda| (after solve()).
  T log_det() const { return log_det_; }
  /// The Cholesky factor L(i, j), i >= j (after solve()).
  Cx<T> factor(std::size_t i, std::size_t j) const { return l_[i * KMax + j]; }

 private:
  std::array<Cx<T>, KMax * KMax> lambda_{};
  std::array<Cx<T>, KMax * KMax> l_{};
  std::array<Cx<T>, KMax * KMax> cov_{};
  std::array<Cx<T>, KMax> mu_{};
  std::size_t n_ = 0;
  T log_det_ = T(0);
};

}  // namespace mptrack::model
