// Joint update of the amplitudes q(alpha_n) and existences q(xi_n) of one frame
// (seed 004 eqs. (12)-(16), App. A; docs/algorithms/vmp.md §Amplitudes and existence).
//
// Inputs per object k < n: the Gram matrix Gamma (Gamma_kj = s_k^H s_j, diagonal
// with the delta-method trace ||s_k||^2 + tr(P_k Re{J_k^H J_k}), seed 004 eq. (34)),
// the matched-filter outputs c_k = s_k^H z and the prior log-odds g_k (eq. (17)).
//   q(alpha) = CN(mu, C):  Lambda = M (.) Gamma + lambda_p I,  mu = Lambda^-1 diag(xi) c,
//   C = Lambda^-1,  M_kj = xi_k xi_j (k != j), M_kk = xi_k.
// Existence: coordinate sweeps of the global maximiser of existence.h until the
// log-odds move by less than a tolerance (or a sweep cap), then mu and C once.
#pragma once

#include <array>
#include <cstddef>

#include "mptrack/vmp/existence.h"
#include "mptrack/vmp/hermitian.h"

namespace mptrack::vmp {

template <class T, std::size_t K>
class AmplitudeExistence {
 public:
  /// Sizes the problem to n objects (n <= K) with prior precision lambda_p.
  void reset(std::size_t n, T lambda_p) {
    n_ = n;
    lambda_p_ = lambda_p;
  }
  std::size_t size() const { return n_; }

  Cx<T>& gamma(std::size_t k, std::size_t j) { return gamma_[k * K + j]; }
  const Cx<T>& gamma(std::size_t k, std::size_t j) const { return gamma_[k * K + j]; }
  Cx<T>& c(std::size_t k) { return c_[k]; }
  T& g(std::size_t k) { return g_[k]; }
  /// Log-odds of xi_k (start value in, result out).
  T& logit_xi(std::size_t k) { return logit_[k]; }
  T xi(std::size_t k) const { return sigmoid(logit_[k]); }
  const Cx<T>& mu(std::size_t k) const { return mu_[k]; }
  const Cx<T>& cov(std::size_t k, std::size_t j) const { return cov_[k * K + j]; }

  /// The closed-form scalars of object k with the others' xi fixed.
  /// False if the others' precision is not positive definite (rounding).
  bool terms(std::size_t k, ExistenceTerms<T>& t) {
    std::size_t m = 0;
    for (std::size_t j = 0; j < n_; ++j) {
      if (j == k) continue;
      idx_[m++] = j;
    }
    for (std::size_t p = 0; p < m; ++p) {
      const std::size_t j = idx_[p];
      const T xj = xi(j);
      for (std::size_t q = 0; q <= p; ++q) {
        const std::size_t i = idx_[q];
        const T w = (i == j) ? xj : xj * xi(i);
        work_[p * K + q] = model::cx_scale(gamma_[j * K + i], w);
        if (i == j) work_[p * K + q].re += lambda_p_;
      }
      b_[p] = model::cx_scale(c_[j], xj);
      v_[p] = model::cx_scale(gamma_[j * K + k], xj);  // v_j = xi_j Gamma_jk
    }
    t.b = gamma_[k * K + k].re;
    t.lambda_p = lambda_p_;
    t.g = g_[k];
    if (m == 0) {
      t.a = model::cx_norm2(c_[k]);
      t.d = T(0);
      return true;
    }
    if (!herm_cholesky<T, K>(work_, m, chol_)) return false;
    herm_solve<T, K>(chol_, m, b_.data(), x_.data());  // mu_r
    Cx<T> vmu{};
    for (std::size_t p = 0; p < m; ++p) vmu = model::cx_add(vmu, model::cx_cmul(v_[p], x_[p]));
    t.a = model::cx_norm2(model::cx_sub(c_[k], vmu));
    herm_solve<T, K>(chol_, m, v_.data(), x_.data());  // Lambda_r^-1 v
    T d = T(0);
    for (std::size_t p = 0; p < m; ++p) d += model::cx_cmul(v_[p], x_[p]).re;
    t.d = d > T(0) ? d : T(0);
    return true;
  }

  /// Coordinate sweeps of the existence maximisation; returns the number of
  /// objects whose terms needed a repair (counted by the caller).
  std::size_t sweep(std::size_t max_sweeps, T tol) {
    std::size_t repairs = 0;
    for (std::size_t s = 0; s < max_sweeps; ++s) {
      T change = T(0);
      for (std::size_t k = 0; k < n_; ++k) {
        ExistenceTerms<T> t;
        if (!terms(k, t)) {
          ++repairs;
          continue;
        }
        const T l = maximise_existence(t);
        const T dl = l > logit_[k] ? l - logit_[k] : logit_[k] - l;
        if (dl > change) change = dl;
        logit_[k] = l;
      }
      if (change < tol) break;
    }
    return repairs;
  }

  /// mu, C at the current xi. False (mu = 0, C = I / lambda_p) if Lambda is
  /// not positive definite, which a PSD Gamma excludes up to rounding.
  bool solve_amplitudes() {
    for (std::size_t k = 0; k < n_; ++k) {
      const T xk = xi(k);
      for (std::size_t j = 0; j <= k; ++j) {
        const T w = (j == k) ? xk : xk * xi(j);
        work_[k * K + j] = model::cx_scale(gamma_[k * K + j], w);
        if (j == k) work_[k * K + j].re += lambda_p_;
      }
      b_[k] = model::cx_scale(c_[k], xk);
    }
    if (!herm_cholesky<T, K>(work_, n_, chol_)) {
      for (std::size_t k = 0; k < n_; ++k) {
        mu_[k] = Cx<T>{};
        for (std::size_t j = 0; j < n_; ++j) cov_[k * K + j] = Cx<T>{k == j ? T(1) / lambda_p_ : T(0), T(0)};
      }
      return false;
    }
    herm_solve<T, K>(chol_, n_, b_.data(), mu_.data());
    herm_inverse<T, K>(chol_, n_, cov_);
    return true;
  }

 private:
  std::size_t n_ = 0;
  T lambda_p_ = T(1);
  HermMatrix<T, K> gamma_{};
  HermMatrix<T, K> work_{};
  HermMatrix<T, K> chol_{};
  HermMatrix<T, K> cov_{};
  std::array<Cx<T>, K> c_{}, mu_{}, b_{}, v_{}, x_{};
  std::array<T, K> g_{}, logit_{};
  std::array<std::size_t, K> idx_{};
};

/// The stationarity condition of F in x = xi_k (seed 004 eq. (16)): at a
/// stationary point logit xi_k equals
///   2 Re{c_k^* mu_k} - Gamma_kk (|mu_k|^2 + C_kk) - 2 sum_{j != k} xi_j Re{Gamma_kj (mu_k^* mu_j + C_jk)} + g_k,
/// with mu, C evaluated at the current xi (the usual VMP Bernoulli log-odds).
template <class T, std::size_t K>
T stationarity_logit(const AmplitudeExistence<T, K>& q, std::size_t k, Cx<T> c_k, T g_k) {
  const Cx<T>& mk = q.mu(k);
  T s = T(2) * model::cx_cmul(c_k, mk).re - q.gamma(k, k).re * (model::cx_norm2(mk) + q.cov(k, k).re);
  for (std::size_t j = 0; j < q.size(); ++j) {
    if (j == k) continue;
    const Cx<T> m = model::cx_add(model::cx_cmul(mk, q.mu(j)), q.cov(j, k));
    s -= T(2) * q.xi(j) * model::cx_mul(q.gamma(k, j), m).re;
  }
  return s + g_k;
}

}  // namespace mptrack::vmp
