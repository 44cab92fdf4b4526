// IGGM amplitude model (seed 001 Sec. III-IV): likelihoods of a detected
// amplitude a above the threshold d, marginalised over an inverse-gamma
// power belief (model/inverse_gamma.h).
//
// Units: amplitudes are the normalised envelope of measurement.h
// (m = |z| / sqrt(N0), so the noise power is 1). A target's IG belief is on
// its total mean power varsigma = 1 + SNR; a clutter source's IG belief is
// on the Weibull scale sigma0 of g(a) = 2b/sigma0 a^(2b-1) exp(-a^(2b)/sigma0)
// (b = 1 is Rayleigh, where sigma0 is the clutter power). All likelihoods are
// densities in the amplitude a, so target and clutter terms of one
// measurement are comparable; everything is returned as a natural log
// (float overflows past e^88, and amplitude ratios of e^100 are normal at
// 20 dB SNR).
#pragma once

#include "mptrack/math/detmath.h"
#include "mptrack/model/inverse_gamma.h"

namespace mptrack::model {

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
/// (docs/algorithms, IGGM filters).
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

/// ln K_RL (seed 001 eqs. (60)-(61)): the IG marginal of the truncated
/// RL^tau(a; varsigma, n), n in {1, 2}:
///   (2a)^(2n-1) Gamma(a+n)/Gamma(a) beta^alpha / (beta + n e)^(alpha+n).
template <class T>
T log_target_amplitude(const InverseGamma<T>& p, const AmplitudeTerms<T>& m, int n) {
  const T tn = T(n);
  const T log_gamma_ratio =
      n == 1 ? dmath::dlog(p.a) : dmath::dlog(p.a) + dmath::dlog(p.a + T(1));
  return (T(2) * tn - T(1)) * m.log_2a + log_gamma_ratio + p.a * dmath::dlog(p.b) -
         (p.a + tn) * dmath::dlog(p.b + tn * m.target_excess);
}

/// Detection probability of a target component with power belief p,
/// threshold d. n = 1: E_IG[exp(-d^2/varsigma)] = (beta/(beta+d^2))^alpha,
/// exact. n = 2: the exact chi-square-4 tail
/// (1 + x) e^-x, x = 2 d^2 / varsigma, at the mean varsigma (plug-in).
template <class T>
T target_detection_probability(const InverseGamma<T>& p, T d, int n) {
  const T d2 = d * d;
  if (n == 1) return dmath::dexp(p.a * (dmath::dlog(p.b) - dmath::dlog(p.b + d2)));
  const T x = T(2) * d2 / p.mean();
  return (T(1) + x) * dmath::dexp(-x);
}

/// Conjugate update of a target power with one detection (seed 001 eq. (60)): alpha += n,
/// beta += n (a^2 - d^2).
template <class T>
void ig_update_target(InverseGamma<T>& p, const AmplitudeTerms<T>& m, int n) {
  p.a += T(n);
  p.b += T(n) * m.target_excess;
}

/// ln K_WB (seed 001 eqs. (62)-(63)): the IG marginal of the truncated Weibull,
///   2b a^(2b-1) alpha beta^alpha / (beta + a^(2b) - d^(2b))^(alpha+1).
template <class T>
T log_clutter_amplitude(const InverseGamma<T>& p, const AmplitudeTerms<T>& m) {
  return m.clutter_log_jac + dmath::dlog(p.a) + p.a * dmath::dlog(p.b) -
         (p.a + T(1)) * dmath::dlog(p.b + m.clutter_excess);
}

/// ln of the truncated Weibull for a known scale sigma0 (fixed-clutter mode).
template <class T>
T log_clutter_amplitude_known(T sigma0, const AmplitudeTerms<T>& m) {
  return m.clutter_log_jac - dmath::dlog(sigma0) - m.clutter_excess / sigma0;
}

}  // namespace mptrack::model
