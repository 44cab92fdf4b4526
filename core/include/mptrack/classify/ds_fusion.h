// Dempster-Shafer fusion of the tracker's and the classifier's belief that a
// detection is target-originated (seed 003 section III-E, eqs. (24)-(25);
// docs/algorithms/nemp.md §Fusion).
//
// Frame {clutter, target}. Polarity: both inputs are P(target-originated):
// the tracker's p_FG = 1 - P(a_0j = 1) (a_0j = 1 means clutter, so the
// paper's m_1 as printed is reversed) and the classifier's w.
// Both BBAs are Bayesian, so Dempster's rule (24) is the normalised product
// and the pignistic transform (25) is the identity. With the optional
// reliability discount alpha < 1 the classifier's BBA puts 1 - alpha on the
// whole frame, and BetP(target) = m(target) + m(frame) / 2.
// w = 0.5 is the neutral element: p_FG is returned bit for bit.
#pragma once

#include "mptrack/math/detmath.h"

namespace mptrack::classify {

/// Dempster's rule for two Bayesian BBAs (eq. (24)): m(target). Under total
/// conflict (p_fg and w at opposite certainties) the rule is undefined and
/// the tracker's belief is kept.
template <class T>
T ds_normalized_product(T p_fg, T w) {
  if (w == T(0.5)) return p_fg;  // neutral: exactly m_1
  const T a = p_fg * w;
  const T b = (T(1) - p_fg) * (T(1) - w);
  const T z = a + b;
  return z > T(0) ? a / z : p_fg;
}

/// Dempster's rule with the classifier discounted by reliability alpha in
/// [0, 1] (mass 1 - alpha on the frame), then the pignistic transform
/// (eq. (25)): BetP(target). alpha = 1 is ds_normalized_product; alpha = 0
/// ignores the classifier.
template <class T>
T ds_discounted_betp(T p_fg, T w, T alpha) {
  if (w == T(0.5) || !(alpha > T(0))) return p_fg;
  if (!(alpha < T(1))) return ds_normalized_product(p_fg, w);
  const T m1h = p_fg, m1c = T(1) - p_fg;
  const T m2h = alpha * w, m2c = alpha * (T(1) - w), m2o = T(1) - alpha;
  const T mh = m1h * m2h + m1h * m2o;  // m_1 has no mass on the frame
  const T mc = m1c * m2c + m1c * m2o;
  const T z = mh + mc;  // = 1 - K
  return z > T(0) ? mh / z : p_fg;
}

/// The classifier's output under a training set with target fraction pi,
/// mapped to balanced classes: odds(w) / odds(pi) (the network's likelihood
/// ratio; docs/algorithms/nemp.md §Fusion). pi = 0.5 returns w exactly.
template <class T>
T correct_training_prior(T w, T pi) {
  if (pi == T(0.5)) return w;
  const T a = w * (T(1) - pi);
  const T b = (T(1) - w) * pi;
  const T z = a + b;
  return z > T(0) ? a / z : w;
}

/// Probabilities are clamped to [kProbFloor, 1 - kProbFloor] before odds
/// are taken, so a certain belief cannot produce an infinite message.
template <class T>
inline constexpr T kProbFloor = T(1e-6);

template <class T>
T clamp_probability(T p) {
  const T lo = kProbFloor<T>, hi = T(1) - kProbFloor<T>;
  return p < lo ? lo : (p > hi ? hi : p);
}

/// The classifier's probability with its log-odds scaled by gain (a
/// temperature 1/gain; docs/algorithms/nemp.md §Fusion, "Gain"):
/// sigmoid(gain ln odds(w)). gain = 1 and w = 0.5 return w exactly.
template <class T>
T scale_log_odds(T w, T gain) {
  if (gain == T(1) || w == T(0.5)) return w;
  const T c = clamp_probability(w);
  const T z = gain * (dmath::dlog(c) - dmath::dlog1p(-c));
  return T(1) / (T(1) + dmath::dexp(-z));
}

/// ln of the factor on a detection's clutter weight that turns the
/// extrinsic tracker belief p_fg into the fused belief betp: ln odds(p_fg)
/// - ln odds(betp) (target odds). 0 exactly when betp == p_fg.
template <class T>
T clutter_log_factor(T p_fg, T betp) {
  if (betp == p_fg) return T(0);
  const T p = clamp_probability(p_fg), b = clamp_probability(betp);
  return (dmath::dlog(p) - dmath::dlog1p(-p)) - (dmath::dlog(b) - dmath::dlog1p(-b));
}

}  // namespace mptrack::classify
