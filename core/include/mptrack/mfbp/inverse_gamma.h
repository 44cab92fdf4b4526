// Inverse-Gamma belief IG(varsigma; a, b) on the total mean power
// varsigma = 1 + SNR (spec 2.2, 2.5 [fix], 3.8.1).
//
// Density b^a/Gamma(a) varsigma^(-a-1) exp(-b/varsigma). The amplitude
// likelihood is exactly conjugate: a += n w, b += n sum w_j (m_j^2 - d^2).
#pragma once

#include "mptrack/math/detmath.h"

namespace mptrack::mfbp {

template <class T>
struct InverseGamma {
  T a = T(3);  ///< shape [-]
  T b = T(2);  ///< scale [-] (same units as varsigma)

  /// Keeps a >= 1 + 1e-6 (spec 3.13) so b/(a-1) exists; b stays positive.
  static constexpr T kMinShape = T(1) + T(1e-3);

  /// Forgetting-factor "transition" (spec 2.2): pseudo-count (a-1) and b
  /// scaled by 1/u; the mean b/(a-1) is kept, the variance grows.
  InverseGamma predicted(T u) const {
    InverseGamma out;
    out.a = (a + u - T(1)) / u;
    out.b = b / u;
    return out;
  }

  /// Conjugate update with weighted statistics (spec 3.8, 3.9):
  /// count = n sum w_j, power = n sum w_j (m_j^2 - d^2).
  void update(T count, T power) {
    a += count;
    b += power;
  }

  /// E[varsigma] = b/(a-1), with the shape guard.
  T mean() const { return b / ((a > kMinShape ? a : kMinShape) - T(1)); }
  /// E[1/varsigma] = a/b (exact).
  T mean_inverse() const { return a / b; }
  /// E[ln varsigma] = ln b - psi(a) (exact).
  T mean_log() const { return dmath::dlog(b) - dmath::ddigamma(a); }
  /// Reported linear SNR: E[varsigma] - 1, clamped at 0.
  T snr() const {
    const T s = mean() - T(1);
    return s > T(0) ? s : T(0);
  }
};

/// Weighted amplitude statistics of one scan for one source (spec 3.8.1):
/// w = sum a_j, s = sum a_j (m_j^2 - d^2). The IG update uses n w and n s.
template <class T>
struct AmplitudeStats {
  T w = T(0);
  T s = T(0);
};

}  // namespace mptrack::mfbp
