// Divergence and merging of inverse-gamma beliefs (model/inverse_gamma.h),
// used by Gaussian-mixture reduction of the IGGM filters (seed 001 eq. (80):
// symmetric KL divergence, used by the bi-threshold merge of eq. (81);
// eqs. (83)-(85): KL projection of a weighted IG mixture onto one IG).
// Units: the power s of the beliefs [-].
#pragma once

#include <cmath>

#include "mptrack/math/detmath.h"
#include "mptrack/model/inverse_gamma.h"

namespace mptrack::model {

/// Trigamma psi'(x), x > 0: recurrence to x >= 6, then the asymptotic series
/// 1/x + 1/(2x^2) + 1/(6x^3) - 1/(30x^5) + 1/(42x^7) - 1/(30x^9)
/// (Abramowitz-Stegun 6.4.12). Rel. error < 1e-9 in double; only needed
/// for the Newton step of the merge.
template <class T>
T trigamma(T x) {
  T acc = T(0);
  while (x < T(6)) {
    acc += T(1) / (x * x);
    x += T(1);
  }
  const T r = T(1) / x;
  const T r2 = r * r;
  const T series =
      r + r2 / T(2) +
      r * r2 * (T(1) / T(6) - r2 * (T(1) / T(30) - r2 * (T(1) / T(42) - r2 / T(30))));
  return acc + series;
}

/// Symmetric KL divergence KL(p||q) + KL(q||p) of two IG beliefs.
template <class T>
T ig_symmetric_kl(const InverseGamma<T>& p, const InverseGamma<T>& q) {
  return (p.a - q.a) * (dmath::ddigamma(p.a) - dmath::ddigamma(q.a) + dmath::dlog(q.b) -
                        dmath::dlog(p.b)) +
         (p.b - q.b) * (q.a / q.b - p.a / p.b);
}

/// Sufficient statistics of the KL projection of weighted IG beliefs:
/// sum w, sum w a/b (E[1/s]), sum w (psi(a) - ln b) (E[ln 1/s]), sum w a.
template <class T>
struct IgMergeAccumulator {
  T w = T(0);
  T w_rho = T(0);
  T w_elog = T(0);
  T w_alpha = T(0);

  void add(T weight, const InverseGamma<T>& p) {
    w += weight;
    w_rho += weight * p.a / p.b;
    w_elog += weight * (dmath::ddigamma(p.a) - dmath::dlog(p.b));
    w_alpha += weight * p.a;
  }

  /// The IG matching E[1/s] and E[ln 1/s] of the mixture: solve
  /// ln a - psi(a) = c by Newton from Minka's seed, then b = a / rho.
  /// Falls back to the weighted mean shape when c is not positive
  /// (identical inputs, rounding). Clamps a to [1.001, max_shape].
  InverseGamma<T> result(T max_shape) const {
    InverseGamma<T> out;
    const T rho = w_rho / w;
    const T c = dmath::dlog(rho) - w_elog / w;
    T alpha = w_alpha / w;
    if (c > T(1e-12)) {
      const T disc = (c - T(3)) * (c - T(3)) + T(24) * c;
      alpha = (T(3) - c + std::sqrt(disc)) / (T(12) * c);
      for (int it = 0; it < 5; ++it) {
        if (!(alpha < max_shape)) break;
        const T f = dmath::dlog(alpha) - dmath::ddigamma(alpha) - c;
        const T fp = T(1) / alpha - trigamma(alpha);
        const T next = alpha - f / fp;
        alpha = next > alpha / T(2) ? next : alpha / T(2);  // stay positive
      }
    }
    if (alpha > max_shape) alpha = max_shape;
    if (alpha < T(1.001)) alpha = T(1.001);
    out.a = alpha;
    out.b = alpha / rho;
    return out;
  }
};

}  // namespace mptrack::model
