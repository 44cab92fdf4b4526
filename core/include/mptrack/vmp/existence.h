// Existence of one potential object in log-odds (seed 004 eqs. (15)-(17);
// docs/algorithms/vmp.md §Amplitudes and existence).
//
// With alpha integrated out, q(xi_k) maximises over x = xi_k in [0, 1]
//   F(x) = b^H Lambda^-1 b - ln|Lambda| + H_b(x) + x g_k,
//   Lambda = M (.) Gamma + lambda_p I,  b = diag(xi) c,
// the others' xi held fixed. Partitioning index k off (Schur complement) gives
// the scalar closed form
//   F(x) = const + x^2 A / den(x) - ln den(x) + H_b(x) + x g,
//   den(x) = x B + lambda_p - x^2 D,
//   A = |c_k - v^H mu_r|^2,  B = Gamma_kk,  D = v^H Lambda_r^-1 v,  v_j = xi_j Gamma_jk,
// where Lambda_r, mu_r are the amplitude precision and mean of the other objects.
// F is in general bimodal (one mode near x = 0, one near 1), so the maximiser is
// global: a grid uniform in logit x over [-40, 40], then golden-section
// refinement around the best grid point. Everything is in log-odds because a
// float cannot hold 1 - 1e-8 (seed 004's birth threshold).
#pragma once

#include <cstddef>

#include "mptrack/math/detmath.h"

namespace mptrack::vmp {

/// ln(1 + e^t) without overflow.
template <class T>
T softplus(T t) {
  return t > T(0) ? t + dmath::dlog1p(dmath::dexp(-t)) : dmath::dlog1p(dmath::dexp(t));
}

/// 1 / (1 + e^-l).
template <class T>
T sigmoid(T l) {
  if (l >= T(0)) return T(1) / (T(1) + dmath::dexp(-l));
  const T e = dmath::dexp(l);
  return e / (T(1) + e);
}

/// ln(p / (1 - p)), p in (0, 1).
template <class T>
T logit(T p) {
  return dmath::dlog(p) - dmath::dlog1p(-p);
}

/// The scalars of the closed form for one object (see the file comment).
template <class T>
struct ExistenceTerms {
  T a = T(0);         ///< A_k = |c_k - v^H mu_r|^2
  T b = T(0);         ///< B_k = Gamma_kk (with the delta-method trace)
  T d = T(0);         ///< D_k = v^H Lambda_r^-1 v >= 0
  T lambda_p = T(1);  ///< amplitude prior precision
  T g = T(0);         ///< prior log-odds (seed 004 eq. (17))
};

/// F at x = sigmoid(l), up to the constant (b_r^H Lambda_r^-1 b_r - ln|Lambda_r|).
/// H_b(x) = x softplus(-l) + (1 - x) softplus(l).
template <class T>
T existence_objective(const ExistenceTerms<T>& t, T l) {
  const T x = sigmoid(l);
  const T y = sigmoid(-l);
  T den = x * t.b + t.lambda_p - x * x * t.d;
  const T floor = T(1e-6) * t.lambda_p;
  if (!(den > floor)) den = floor;  // Lambda is PD: only rounding reaches here
  const T hb = x * softplus(-l) + y * softplus(l);
  return x * x * t.a / den - dmath::dlog(den) + hb + x * t.g;
}

/// dF/dx without the entropy term: at a stationary point logit x equals it
/// (dH_b/dx = -logit x). With den' = B - 2 x D:
///   phi(x) = (2 x A den - x^2 A den') / den^2 - den' / den + g.
template <class T>
T existence_slope(const ExistenceTerms<T>& t, T x) {
  T den = x * t.b + t.lambda_p - x * x * t.d;
  const T floor = T(1e-6) * t.lambda_p;
  if (!(den > floor)) den = floor;
  const T dden = t.b - T(2) * x * t.d;
  return (T(2) * x * t.a * den - x * x * t.a * dden) / (den * den) - dden / den + t.g;
}

/// Global maximiser of F in logit x: kGrid uniform points over [-40, 40] pick
/// the mode, kGolden golden-section steps refine it. In a saturated mode
/// (|logit| > 12: x (1 - x) < 1e-5) F is flat to working precision (in float
/// it cannot tell logit 16 from 40), so there the stationarity condition
/// logit x = phi(x) is iterated instead; it contracts by phi'(x) x (1 - x) per
/// step and returns log-odds beyond +-40 when the evidence says so.
template <class T>
T maximise_existence(const ExistenceTerms<T>& t) {
  constexpr int kGrid = 64;
  constexpr int kGolden = 24;
  const T span = T(40);
  const T step = T(2) * span / static_cast<T>(kGrid - 1);
  int best = 0;
  T best_f = existence_objective(t, -span);
  for (int i = 1; i < kGrid; ++i) {
    const T f = existence_objective(t, -span + step * static_cast<T>(i));
    if (f > best_f) {
      best_f = f;
      best = i;
    }
  }
  T lo = -span + step * static_cast<T>(best > 0 ? best - 1 : 0);
  T hi = -span + step * static_cast<T>(best < kGrid - 1 ? best + 1 : kGrid - 1);
  const T r = T(0.6180339887498949);
  T x1 = hi - r * (hi - lo);
  T x2 = lo + r * (hi - lo);
  T f1 = existence_objective(t, x1);
  T f2 = existence_objective(t, x2);
  for (int i = 0; i < kGolden; ++i) {
    if (f1 < f2) {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + r * (hi - lo);
      f2 = existence_objective(t, x2);
    } else {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - r * (hi - lo);
      f1 = existence_objective(t, x1);
    }
  }
  T l = T(0.5) * (lo + hi);
  // The bracket ends can beat the interior point at the span limits.
  if (!(existence_objective(t, l) >= best_f)) l = -span + step * static_cast<T>(best);
  const T saturated = T(12);
  if (l > saturated || l < -saturated) {
    for (int i = 0; i < 8; ++i) {
      const T next = existence_slope(t, sigmoid(l));
      // Stay in the mode the grid chose (the slope's sign cannot flip there).
      if ((l > T(0)) != (next > T(0))) break;
      l = next;
    }
  }
  return l;
}

}  // namespace mptrack::vmp
