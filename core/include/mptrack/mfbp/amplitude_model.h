// Amplitude model of seed 000: detection probability from the threshold
// (docs/algorithms/models.md §Detection probability) and the truncated
// generalised-Rayleigh amplitude likelihood in the conjugate parameterisation
// varsigma = 1 + SNR (docs/algorithms/models.md §Amplitude likelihoods).
//
// Terms common to every source of one measurement (ln 2 + (2n-1) ln m and
// the Nakagami constant) are dropped: they cancel in the BP messages.
#pragma once

#include "mptrack/math/detmath.h"
#include "mptrack/mfbp/mfbp_params.h"

namespace mptrack::mfbp {

/// P_D for total mean power varsigma = 1 + snr (linear), threshold d.
/// kExact: P(u > d^2) for u ~ Gamma(n, varsigma/n) = e^-x sum_{l<n} x^l/l!,
/// x = n d^2 / varsigma (docs/algorithms/models.md §Detection probability).
/// kPaper: (seed 000 eq. (9)) e^-x.
template <class T>
T detection_probability(T varsigma, T d, int n, PdModel model) {
  const T x = T(n) * d * d / varsigma;
  const T e = dmath::dexp(-x);
  if (model == PdModel::kPaper || n == 1) return e;
  return e * (T(1) + x);  // n == 2
}

/// E_IG(a,b)[ln R^d(m; varsigma, n)] up to the per-measurement constant.
/// kExact (docs/algorithms/models.md §Amplitude likelihoods):
/// -n (ln b - psi(a)) - n (m^2 - d^2) a / b.
/// kPaper (seed 000 eqs. (80), (86), (109)): (2n-1) ln m - n m^2 a/b + n / (2 (a-2)), a > 2.
/// One (a, b) against many amplitudes m: the term without m (a logarithm
/// and a digamma) is computed at the first call only, by the same
/// operations as every call before; no call, no cost.
template <class T>
class ExpectedAmplitudeLoglik {
 public:
  ExpectedAmplitudeLoglik(T d, T a, T b, int n, AmpLoglik model)
      : d_(d), a_(a), b_(b), tn_(T(n)), paper_(model == AmpLoglik::kPaper) {}

  T operator()(T m) {
    if (!have_m_free_) {
      m_free_ = paper_ ? paper_a_term() : dmath::dlog(b_) - dmath::ddigamma(a_);  // kExact: E[ln varsigma]
      have_m_free_ = true;
    }
    if (paper_) return (T(2) * tn_ - T(1)) * dmath::dlog(m) - tn_ * m * m * a_ / b_ + m_free_;
    return -tn_ * m_free_ - tn_ * (m * m - d_ * d_) * a_ / b_;
  }

 private:
  T paper_a_term() const {
    const T a_safe = a_ > T(2.001) ? a_ : T(2.001);  // the printed form diverges at a = 2
    return tn_ / (T(2) * (a_safe - T(2)));
  }

  T d_, a_, b_, tn_;
  bool paper_;
  bool have_m_free_ = false;
  T m_free_ = T(0);  ///< kExact: E[ln varsigma]; kPaper: n / (2 (a - 2))
};

template <class T>
T expected_amplitude_loglik(T m, T d, T a, T b, int n, AmpLoglik model) {
  return ExpectedAmplitudeLoglik<T>(d, a, b, n, model)(m);
}

/// ln R^d(m; varsigma, n) for a known varsigma (known-clutter ablation),
/// same dropped constant as expected_amplitude_loglik.
template <class T>
T amplitude_loglik(T m, T d, T varsigma, int n) {
  const T tn = T(n);
  return -tn * dmath::dlog(varsigma) - tn * (m * m - d * d) / varsigma;
}

}  // namespace mptrack::mfbp
