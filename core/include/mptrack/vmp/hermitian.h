// Small dense Hermitian positive-definite algebra for the joint amplitude
// posterior q(alpha) (seed 004 eqs. (12)-(14)): A = L L^H, solves, log-det and the
// inverse, for n <= K (run-time size, compile-time capacity; row-major with
// leading dimension K). Plain loops with a fixed order, so float and double give
// the same bits on every target; no heap.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include "mptrack/math/detmath.h"
#include "mptrack/model/complex_value.h"

namespace mptrack::vmp {

using model::Cx;

template <class T, std::size_t K>
using HermMatrix = std::array<Cx<T>, K * K>;

/// Lower Cholesky factor of the Hermitian A (lower triangle read). False if a
/// pivot is <= 0 or NaN.
template <class T, std::size_t K>
bool herm_cholesky(const HermMatrix<T, K>& a, std::size_t n, HermMatrix<T, K>& l) {
  for (std::size_t j = 0; j < n; ++j) {
    T d = a[j * K + j].re;
    for (std::size_t k = 0; k < j; ++k) d -= model::cx_norm2(l[j * K + k]);
    if (!(d > T(0))) return false;
    const T ljj = std::sqrt(d);
    l[j * K + j] = {ljj, T(0)};
    for (std::size_t i = j + 1; i < n; ++i) {
      Cx<T> s = a[i * K + j];
      for (std::size_t k = 0; k < j; ++k) s = model::cx_sub(s, model::cx_mul(l[i * K + k], model::cx_conj(l[j * K + k])));
      l[i * K + j] = model::cx_scale(s, T(1) / ljj);
    }
    for (std::size_t i = 0; i < j; ++i) l[i * K + j] = Cx<T>{};
  }
  return true;
}

/// x = A^-1 b from the factor L (forward, then back substitution).
template <class T, std::size_t K>
void herm_solve(const HermMatrix<T, K>& l, std::size_t n, const Cx<T>* b, Cx<T>* x) {
  std::array<Cx<T>, K> y{};
  for (std::size_t i = 0; i < n; ++i) {
    Cx<T> s = b[i];
    for (std::size_t k = 0; k < i; ++k) s = model::cx_sub(s, model::cx_mul(l[i * K + k], y[k]));
    y[i] = model::cx_scale(s, T(1) / l[i * K + i].re);
  }
  for (std::size_t ii = n; ii-- > 0;) {
    Cx<T> s = y[ii];
    for (std::size_t k = ii + 1; k < n; ++k) s = model::cx_sub(s, model::cx_cmul(l[k * K + ii], x[k]));
    x[ii] = model::cx_scale(s, T(1) / l[ii * K + ii].re);
  }
}

/// ln |A| = 2 sum ln L_ii.
template <class T, std::size_t K>
T herm_logdet(const HermMatrix<T, K>& l, std::size_t n) {
  T s = T(0);
  for (std::size_t i = 0; i < n; ++i) s += dmath::dlog(l[i * K + i].re);
  return T(2) * s;
}

/// A^-1 (full Hermitian matrix) from the factor L.
template <class T, std::size_t K>
void herm_inverse(const HermMatrix<T, K>& l, std::size_t n, HermMatrix<T, K>& inv) {
  std::array<Cx<T>, K> e{};
  std::array<Cx<T>, K> col{};
  for (std::size_t j = 0; j < n; ++j) {
    for (std::size_t i = 0; i < n; ++i) e[i] = Cx<T>{i == j ? T(1) : T(0), T(0)};
    herm_solve<T, K>(l, n, e.data(), col.data());
    for (std::size_t i = 0; i < n; ++i) inv[i * K + j] = col[i];
  }
  // Exact Hermitian symmetry (the two triangles come from different solves).
  for (std::size_t i = 0; i < n; ++i) {
    inv[i * K + i].im = T(0);
    for (std::size_t j = 0; j < i; ++j) inv[j * K + i] = model::cx_conj(inv[i * K + j]);
  }
}

}  // namespace mptrack::vmp
