// Inverse-gamma belief IG(s; a, b) on a mean power s [-] (normalised units,
// noise power 1): a target's total mean power s = 1 + SNR (MF-BP, GM-PHD,
// GM-CPHD, CBMeMBer) or a clutter source's Weibull scale sigma0 (IGGM
// clutter estimator). Density b^a / Gamma(a) s^(-a-1) exp(-b / s).
// Moments: E[s] = b / (a - 1) (a > 1), E[1/s] = a / b, E[ln s] = ln b - psi(a).
//
// Forgetting between scans (seed 000 Sec. II, target SNR transition;
// seed 001 eqs. (50)-(52)): a <- (a + u - 1) / u, b <- b / u with u > 1 keeps the mean
// b / (a - 1) and widens the belief (memory u / (u - 1) scans). Two rules:
//  - predicted(u): the paper's transition as written (MF-BP);
//  - forget_clamped(ig, u, min_shape): the same, then a raised to min_shape
//    with the mean kept, so the variance stays finite (a > 2) under a long
//    run of misses (the IGGM filters). The clamp changes the bits whenever
//    it binds, so the rules stay two named functions.
// Conjugate update with amplitude evidence: a += count, b += power (see
// model/amplitude_iggm.h for the IGGM statistics).
#pragma once

#include "mptrack/math/detmath.h"

namespace mptrack::model {

template <class T>
struct InverseGamma {
  T a = T(3);  ///< shape [-]
  T b = T(2);  ///< scale [-] (same units as the power s)

  /// Shape floor of mean(), so b / (a - 1) exists.
  static constexpr T kMinShape = T(1) + T(1e-3);

  /// Forgetting-factor transition (file comment): mean kept, variance grows.
  InverseGamma predicted(T u) const {
    InverseGamma out;
    out.a = (a + u - T(1)) / u;
    out.b = b / u;
    return out;
  }

  /// Conjugate update: a += count, b += power.
  void update(T count, T power) {
    a += count;
    b += power;
  }

  /// E[s] = b / (a - 1), with the shape floor kMinShape.
  T mean() const { return b / ((a > kMinShape ? a : kMinShape) - T(1)); }
  /// E[1/s] = a / b (exact).
  T mean_inverse() const { return a / b; }
  /// E[ln s] = ln b - psi(a) (exact).
  T mean_log() const { return dmath::dlog(b) - dmath::ddigamma(a); }
  /// Reported linear SNR of a target power: E[s] - 1, clamped at 0.
  T snr() const {
    const T s = mean() - T(1);
    return s > T(0) ? s : T(0);
  }
};

/// IG with mean `mean` [-] and shape `shape` (> 1): b = mean (shape - 1).
template <class T>
InverseGamma<T> inverse_gamma_with_mean(T mean, T shape) {
  InverseGamma<T> out;
  out.a = shape;
  out.b = mean * (shape - T(1));
  return out;
}

/// Forgetting with the shape clamp of the IGGM filters (file comment):
/// predicted(u), then, if a < min_shape, a = min_shape with the mean kept
/// (the mean's shape guard here is a - 1 >= 1e-3).
template <class T>
void forget_clamped(InverseGamma<T>& ig, T u, T min_shape) {
  ig.a = (ig.a + u - T(1)) / u;
  ig.b = ig.b / u;
  if (ig.a < min_shape) {
    const T mean = ig.b / (ig.a - T(1) > T(1e-3) ? ig.a - T(1) : T(1e-3));
    ig.a = min_shape;
    ig.b = mean * (min_shape - T(1));
  }
}

}  // namespace mptrack::model
