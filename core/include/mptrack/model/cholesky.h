// Fixed-size Cholesky factorisation A = L L^T, whitening L^-1 b and solve
// A^-1 B (N <= 4), written out as plain loops: Eigen's LLT::solve with a
// matrix right-hand side goes through its blocked triangular solver, which
// references the heap (malloc/free for its workspace) and fails the core nm
// check. Fixed evaluation order, so the bits are the same on every target
// (docs/architecture.md). Units: those of A (L has their square roots).
#pragma once

#include <cmath>

#include <Eigen/Core>

namespace mptrack::model {

/// A = L L^T for symmetric A (lower triangle read). False if a pivot is
/// <= 0 or NaN (A not positive definite); L is then unspecified.
template <class T, int N>
bool cholesky(const Eigen::Matrix<T, N, N>& A, Eigen::Matrix<T, N, N>& L) {
  L.setZero();
  for (int j = 0; j < N; ++j) {
    T d = A(j, j);
    for (int k = 0; k < j; ++k) d -= L(j, k) * L(j, k);
    if (!(d > T(0))) return false;  // also rejects NaN
    const T ljj = std::sqrt(d);
    L(j, j) = ljj;
    for (int i = j + 1; i < N; ++i) {
      T s = A(i, j);
      for (int k = 0; k < j; ++k) s -= L(i, k) * L(j, k);
      L(i, j) = s / ljj;
    }
  }
  return true;
}

/// True if the Cholesky factorisation of symmetric P succeeds with every
/// pivot > 0 and finite (NaN and inf fail).
template <class T, int N>
bool is_spd(const Eigen::Matrix<T, N, N>& P) {
  Eigen::Matrix<T, N, N> L;
  if (!cholesky<T, N>(P, L)) return false;
  for (int j = 0; j < N; ++j) {
    if (!(L(j, j) - L(j, j) == T(0))) return false;
  }
  return true;
}

/// Forward substitution L^-1 b (whitens b when L L^T is its covariance).
template <class T, int N>
Eigen::Matrix<T, N, 1> cholesky_whiten(const Eigen::Matrix<T, N, N>& L, const Eigen::Matrix<T, N, 1>& b) {
  Eigen::Matrix<T, N, 1> y;
  for (int i = 0; i < N; ++i) {
    T s = b(i);
    for (int k = 0; k < i; ++k) s -= L(i, k) * y(k);
    y(i) = s / L(i, i);
  }
  return y;
}

/// X = A^-1 B given the Cholesky factor L of A (forward then back substitution).
template <class T, int N, int M>
Eigen::Matrix<T, N, M> cholesky_solve(const Eigen::Matrix<T, N, N>& L, const Eigen::Matrix<T, N, M>& B) {
  Eigen::Matrix<T, N, M> X;
  for (int c = 0; c < M; ++c) {
    Eigen::Matrix<T, N, 1> y;
    for (int i = 0; i < N; ++i) {
      T s = B(i, c);
      for (int k = 0; k < i; ++k) s -= L(i, k) * y(k);
      y(i) = s / L(i, i);
    }
    for (int i = N - 1; i >= 0; --i) {
      T s = y(i);
      for (int k = i + 1; k < N; ++k) s -= L(k, i) * X(k, c);
      X(i, c) = s / L(i, i);
    }
  }
  return X;
}

}  // namespace mptrack::model
