// Inverse-Gamma power belief and amplitude likelihoods of the IGGM filters
// (seed 001 spec sections 1.3, 3, 4, 5.5).
//
// Units: amplitudes are the normalised envelope of measurement.h
// (m = |z| / sqrt(N0), so the noise power is 1). A target's IG belief is on
// its total mean power varsigma = 1 + SNR (seed 000 spec 2.5 [fix]); a
// clutter source's IG belief is on the Weibull scale sigma0 of
// g(a) = 2b/sigma0 a^(2b-1) exp(-a^(2b)/sigma0) (seed 001 spec 3.4; b = 1 is
// Rayleigh, where sigma0 is the clutter power). All likelihoods are densities
// in the amplitude a, so target and clutter terms of one measurement are
// comparable; everything is returned as a natural log (float overflows past
// e^88, and amplitude ratios of e^100 are normal at 20 dB SNR).
#pragma once

#include <cmath>
#include <cstddef>

#include "mptrack/math/detmath.h"

namespace mptrack::phd {

/// IG(alpha, beta) belief on a power [-] (normalised units); mean beta/(alpha-1).
template <class T>
struct IgPower {
  T alpha = T(3);  ///< shape [-]
  T beta = T(2);   ///< scale [-]

  /// Mean beta/(alpha-1), alpha guarded at > 1.
  T mean() const { return beta / ((alpha > T(1.001) ? alpha : T(1.001)) - T(1)); }
};

/// Forgetting-factor prediction (seed 001 spec 1.3, P50-P52): beta/v and
/// (alpha + v - 1)/v keep the mean and widen the belief; memory v/(v-1)
/// scans. alpha is clamped at min_alpha (spec 1.3 [impl], finite variance).
template <class T>
void ig_forget(IgPower<T>& p, T v, T min_alpha) {
  p.alpha = (p.alpha + v - T(1)) / v;
  p.beta = p.beta / v;
  if (p.alpha < min_alpha) {
    // Keep the mean while raising the shape.
    const T mean = p.beta / (p.alpha - T(1) > T(1e-3) ? p.alpha - T(1) : T(1e-3));
    p.alpha = min_alpha;
    p.beta = mean * (min_alpha - T(1));
  }
}

/// Per-measurement amplitude quantities, computed once per scan.
template <class T>
struct AmplitudeTerms {
  T log_2a = T(0);            ///< ln(2 a)
  T target_excess = T(0);     ///< a^2 - d^2 (>= 0)
  T clutter_excess = T(0);    ///< a^(2b) - d^(2b) (>= 0)
  T clutter_log_jac = T(0);   ///< ln(2b) + (2b-1) ln a
};

/// x^p for x > 0 through dexp/dlog (no libm pow).
template <class T>
T dpow_pos(T x, T p) {
  return dmath::dexp(p * dmath::dlog(x));
}

/// Fills the terms for amplitude a, threshold d, Weibull shape b. The
/// excesses are clamped at 0: interpolated peaks can sit just below d
/// (seed 001 spec 9, item 9).
template <class T>
AmplitudeTerms<T> amplitude_terms(T a, T d, T b) {
  AmplitudeTerms<T> t;
  const T log_a = dmath::dlog(a);
  t.log_2a = dmath::dlog(T(2)) + log_a;
  const T e = a * a - d * d;
  t.target_excess = e > T(0) ? e : T(0);
  const T ce = dmath::dexp(T(2) * b * log_a) - dpow_pos(d, T(2) * b);
  t.clutter_excess = ce > T(0) ? ce : T(0);
  t.clutter_log_jac = dmath::dlog(T(2) * b) + (T(2) * b - T(1)) * log_a;
  return t;
}

/// ln K_RL (seed 001 spec 4, P60-P61): the IG marginal of the truncated
/// RL^tau(a; varsigma, n), n in {1, 2}:
///   (2a)^(2n-1) Gamma(a+n)/Gamma(a) beta^alpha / (beta + n e)^(alpha+n).
template <class T>
T log_target_amplitude(const IgPower<T>& p, const AmplitudeTerms<T>& m, int n) {
  const T tn = T(n);
  const T log_gamma_ratio =
      n == 1 ? dmath::dlog(p.alpha) : dmath::dlog(p.alpha) + dmath::dlog(p.alpha + T(1));
  return (T(2) * tn - T(1)) * m.log_2a + log_gamma_ratio + p.alpha * dmath::dlog(p.beta) -
         (p.alpha + tn) * dmath::dlog(p.beta + tn * m.target_excess);
}

/// Detection probability of a target component with power belief p,
/// threshold d. n = 1: E_IG[exp(-d^2/varsigma)] = (beta/(beta+d^2))^alpha,
/// exact (spec 4 [supplement]). n = 2: the exact chi-square-4 tail
/// (1 + x) e^-x, x = 2 d^2 / varsigma, at the mean varsigma (plug-in, P72).
template <class T>
T target_detection_probability(const IgPower<T>& p, T d, int n) {
  const T d2 = d * d;
  if (n == 1) return dmath::dexp(p.alpha * (dmath::dlog(p.beta) - dmath::dlog(p.beta + d2)));
  const T x = T(2) * d2 / p.mean();
  return (T(1) + x) * dmath::dexp(-x);
}

/// Conjugate update of a target power with one detection (P60): alpha += n,
/// beta += n (a^2 - d^2).
template <class T>
void ig_update_target(IgPower<T>& p, const AmplitudeTerms<T>& m, int n) {
  p.alpha += T(n);
  p.beta += T(n) * m.target_excess;
}

/// ln K_WB (P62-P63): the IG marginal of the truncated Weibull,
///   2b a^(2b-1) alpha beta^alpha / (beta + a^(2b) - d^(2b))^(alpha+1).
template <class T>
T log_clutter_amplitude(const IgPower<T>& p, const AmplitudeTerms<T>& m) {
  return m.clutter_log_jac + dmath::dlog(p.alpha) + p.alpha * dmath::dlog(p.beta) -
         (p.alpha + T(1)) * dmath::dlog(p.beta + m.clutter_excess);
}

/// ln of the truncated Weibull for a known scale sigma0 (fixed-clutter mode).
template <class T>
T log_clutter_amplitude_known(T sigma0, const AmplitudeTerms<T>& m) {
  return m.clutter_log_jac - dmath::dlog(sigma0) - m.clutter_excess / sigma0;
}

/// Trigamma psi'(x), x > 0: recurrence to x >= 6, then the asymptotic series
/// 1/x + 1/(2x^2) + 1/(6x^3) - 1/(30x^5) + 1/(42x^7) - 1/(30x^9)
/// (Abramowitz-Stegun 6.4.12). Rel. error < 1e-9 in double; only needed
/// for the Newton step of the IG merge.
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

/// Symmetric KL divergence of two IG beliefs (seed 001 spec 5.5, P80).
template <class T>
T ig_symmetric_kl(const IgPower<T>& p, const IgPower<T>& q) {
  return (p.alpha - q.alpha) * (dmath::ddigamma(p.alpha) - dmath::ddigamma(q.alpha) +
                                dmath::dlog(q.beta) - dmath::dlog(p.beta)) +
         (p.beta - q.beta) * (q.alpha / q.beta - p.alpha / p.beta);
}

/// Accumulates the sufficient statistics of the KL-projection merge of
/// weighted IG beliefs (P83-P85): sum w, sum w alpha/beta, sum w (psi(alpha) - ln beta).
template <class T>
struct IgMergeAccumulator {
  T w = T(0);
  T w_rho = T(0);
  T w_elog = T(0);
  T w_alpha = T(0);

  void add(T weight, const IgPower<T>& p) {
    w += weight;
    w_rho += weight * p.alpha / p.beta;
    w_elog += weight * (dmath::ddigamma(p.alpha) - dmath::dlog(p.beta));
    w_alpha += weight * p.alpha;
  }

  /// The IG matching E[1/s] and E[ln 1/s] of the mixture: solve
  /// ln alpha - psi(alpha) = c by Newton from Minka's seed (spec 5.5 [impl]),
  /// then beta = alpha / rho. Falls back to the weighted mean shape when c
  /// is not positive (identical inputs, rounding). Clamps alpha to [1.001, max_alpha].
  IgPower<T> result(T max_alpha) const {
    IgPower<T> out;
    const T rho = w_rho / w;
    const T c = dmath::dlog(rho) - w_elog / w;
    T alpha = w_alpha / w;
    if (c > T(1e-12)) {
      const T disc = (c - T(3)) * (c - T(3)) + T(24) * c;
      alpha = (T(3) - c + std::sqrt(disc)) / (T(12) * c);
      for (int it = 0; it < 5; ++it) {
        if (!(alpha < max_alpha)) break;
        const T f = dmath::dlog(alpha) - dmath::ddigamma(alpha) - c;
        const T fp = T(1) / alpha - trigamma(alpha);
        const T next = alpha - f / fp;
        alpha = next > alpha / T(2) ? next : alpha / T(2);  // stay positive
      }
    }
    if (alpha > max_alpha) alpha = max_alpha;
    if (alpha < T(1.001)) alpha = T(1.001);
    out.alpha = alpha;
    out.beta = alpha / rho;
    return out;
  }
};

}  // namespace mptrack::phd
