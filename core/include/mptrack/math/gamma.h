// Deterministic log-gamma and digamma for x > 0: dlgamma, ddigamma.
//
// Same bits on every target (see detmath.h for the rules and the accuracy
// table). Our own construction, in the spirit of fdlibm e_lgamma_r.c and
// Cody-Strecok-Thacher (1973), with minimax polynomials only:
//
// dlgamma:
// - [0.5, 2.5): 1/Gamma(x) - 1 = (x-1)(x-2) R(x - 1.5). 1/Gamma is entire,
//   so R converges fast (degree 18 double / 10 float on a width-2 interval),
//   and the factors (x-1)(x-2), exact for these x, put both zeros of lgamma
//   into the formula: lgamma x = -ln(1 + g) is relatively accurate right up to
//   x = 1 and x = 2 (dlog1p).
// - (0, 0.5): lgamma x = lgamma (1+x) - ln x, with g at 1+x = x (x-1) R(x-0.5)
//   evaluated from x itself (no rounded 1 + x).
// - [2.5, 8): recurrence down to y = x - n in [1.5, 2.5):
//   lgamma x = lgamma y + ln(y (y+1) ... (x-1)); the factors are exact.
// - [8, inf): Stirling series with Bernoulli terms,
//   (x - 1/2)(ln x - 1) + ln(2 pi)/2 - 1/2 + sum B2k / (2k (2k-1) x^(2k-1)),
//   9 terms double / 3 float, with ln x as a double-word and the leading
//   product exact (Dekker), so the result rounds about once.
// ddigamma:
// - [1, 2): psi x = (x - x0) P1(x - 1.5), x0 = 1.4616... the positive root,
//   subtracted as a hi + lo pair: relative accuracy through the zero.
// - [2, 3): psi x = P2(x - 2.5).
// - [3, inf): psi x = ln x - 1/(2x) - z T(z), z = 1/x^2, T the minimax fit of
//   the asymptotic (Bernoulli) series on [0, 1/9]; ln x as a double-word.
// - (0, 1): psi x = psi(1 + x) - 1/x, psi(1+x) from P1 evaluated from x
//   itself, 1/x as a double-word (Dekker) so the cancellation near x = 1
//   costs little.
#pragma once

#include "mptrack/math/constants.h"
#include "mptrack/math/exp_log.h"

namespace mptrack::dmath {
namespace detail {

template <class T>
struct GammaCoeffs;

template <>
struct GammaCoeffs<float> {
  // (1/Gamma(u + 1.5) - 1) / ((u + 0.5)(u - 0.5)), |u| <= 1: kR0Hi + kR0Lo + u kR(u);
  // relative error < 2^-30.3.
  static constexpr float kR0Hi = -0x1.06eba8p-1f;
  static constexpr float kR0Lo = -0x1.0694c8p-28f;
  static constexpr float kR[] = {0x1.514d3ep-3f,  0x1.ae7f92p-5f,   -0x1.54ea8p-5f, 0x1.9f4b52p-8f,
                                 0x1.1adf3ap-9f,  -0x1.2187ap-10f,  0x1.3781bap-13f, 0x1.b85e7cp-16f,
                                 -0x1.c863dep-17f, 0x1.ef5208p-20f};
  // Stirling: B2k / (2k (2k-1)), k = 1..3.
  static constexpr float kStirling[] = {0x1.555556p-4f, -0x1.6c16c2p-9f, 0x1.a01a02p-11f};
  static constexpr float kHalfLn2PiMinusHalf = 0x1.acfe3ap-2f;  ///< ln(2 pi)/2 - 1/2
  static constexpr float kHuge = 0x1.0p+26f;  ///< above, lgamma = (x - 1/2)(ln x - 1)
  // digamma: positive root x0 = kX0Hi + kX0Lo, and x0 - 1.
  static constexpr float kX0Hi = 0x1.762d86p+0f;
  static constexpr float kX0Lo = 0x1.ab5f2p-27f;
  static constexpr float kX0m1Hi = 0x1.d8b618p-2f;
  static constexpr float kX0m1Lo = 0x1.ab5f2p-27f;
  // psi(u + 1.5) / (u + 1.5 - x0), |u| <= 0.5.
  // relative error < 2^-26.8
  static constexpr float kP10Hi = 0x1.e6f0ccp-1f;
  static constexpr float kP10Lo = -0x1.3310dap-27f;
  static constexpr float kP1[] = {-0x1.b1cb66p-2f, 0x1.eca1ap-3f,   -0x1.2fee1cp-3f, 0x1.8507cep-4f,
                                  -0x1.fb5f9p-5f,  0x1.4f749p-5f,   -0x1.ba486p-6f,  0x1.0fba96p-6f,
                                  -0x1.7268c8p-7f, 0x1.838b56p-7f,  -0x1.ef5a3p-8f};
  // psi(u + 2.5), |u| <= 0.5; relative error < 2^-28.3.
  static constexpr float kP20Hi = 0x1.680426p-1f;
  static constexpr float kP20Lo = -0x1.56bd4cp-27f;
  static constexpr float kP2[] = {0x1.f62056p-2f,  -0x1.e3bee4p-4f, 0x1.31b78ep-5f, -0x1.ac69d8p-7f,
                                  0x1.3ae80ep-8f,  -0x1.de16fcp-10f, 0x1.99c9a2p-11f, -0x1.3d113p-12f};
  // (ln x - 1/(2x) - psi x) x^2 in z = 1/x^2 <= 1/9; relative error of psi < 2^-37.
  static constexpr float kT[] = {0x1.555554p-4f, -0x1.110c4cp-7f, 0x1.0296c4p-8f, -0x1.eb969p-9f,
                                 0x1.d7734cp-9f};
  static constexpr float kEulerGamma = 0x1.2788d0p-1f;
  static constexpr float kPsiTiny = 0x1.0p-26f;  ///< below, psi x = -1/x - gamma
};

template <>
struct GammaCoeffs<double> {
  // relative error < 2^-56.4
  static constexpr double kR0Hi = -0x1.06eba8214db69p-1;
  static constexpr double kR0Lo = 0x1.c939e76173165p-55;
  static constexpr double kR[] = {
      0x1.514d3d90584b4p-3, 0x1.ae7f941ca4862p-5, -0x1.54ea68a3b3e86p-5, 0x1.9f4a6bce375a7p-8,
      0x1.1ad8e56fa22e7p-9, -0x1.2179817aba9f3p-10, 0x1.383d43a2beb09p-13, 0x1.b256fe40ed013p-16,
      -0x1.d1c7122f8e3cdp-17, 0x1.1e66f3cbd791fp-19, 0x1.0b26140a64751p-24, -0x1.7fd0552b6791bp-24,
      0x1.24b51e0e39d94p-26, -0x1.f5e058203a06fp-31, -0x1.2ac40769e5472p-32, 0x1.48d9f19dc9028p-34,
      -0x1.f644a97305d6bp-38, -0x1.d747cd440a185p-43};
  // Stirling: B2k / (2k (2k-1)), k = 1..9.
  static constexpr double kStirling[] = {0x1.5555555555555p-4,  -0x1.6c16c16c16c17p-9, 0x1.a01a01a01a01ap-11,
                                         -0x1.3813813813814p-11, 0x1.b951e2b18ff23p-11, -0x1.f6ab0d9993c7dp-10,
                                         0x1.a41a41a41a41ap-8,   -0x1.e4286cb0f5398p-6, 0x1.6fe96381e0680p-3};
  static constexpr double kHalfLn2PiMinusHalf = 0x1.acfe390c97d69p-2;
  static constexpr double kHuge = 0x1.0p+60;
  static constexpr double kX0Hi = 0x1.762d86356be3fp+0;
  static constexpr double kX0Lo = 0x1.b86a722197829p-54;
  static constexpr double kX0m1Hi = 0x1.d8b618d5af8fep-2;
  static constexpr double kX0m1Lo = -0x1.1e563779a1f5bp-56;
  // relative error < 2^-55.9
  static constexpr double kP10Hi = 0x1.e6f0cbb873616p-1;
  static constexpr double kP10Lo = 0x1.8d09cb0c60a16p-55;
  static constexpr double kP1[] = {
      -0x1.b1cb63005ee98p-2, 0x1.eca189b8e6f76p-3, -0x1.2feeeb98a78d3p-3, 0x1.8512e590384cbp-4,
      -0x1.fb44202a24efap-5, 0x1.4de9aa17d3748p-5, -0x1.b9f8b11b65478p-6, 0x1.256471621a57bp-6,
      -0x1.8635640e40047p-7, 0x1.03c0b0f9b200bp-7, -0x1.5a06a32d4cad3p-8, 0x1.cd1f77c31f09dp-9,
      -0x1.336dea2a40bd2p-9, 0x1.99dcf15e8fdcfp-10, -0x1.0fb1c6b0b386ap-10, 0x1.69e80b2d93f3dp-11,
      -0x1.fda4e96e0ed8ep-12, 0x1.55b64b1636b20p-12, -0x1.2f5de2d4c25fcp-13, 0x1.874c7de13d56cp-14,
      -0x1.75fdecb6815bep-13, 0x1.fc3e976111f00p-14};
  // relative error < 2^-54.9
  static constexpr double kP20Hi = 0x1.680425af12b5ep-1;
  static constexpr double kP20Lo = -0x1.8ac37d75f8ebep-58;
  static constexpr double kP2[] = {
      0x1.f62057f7296cbp-2,  -0x1.e3bef327df0bcp-4, 0x1.31b4c4359d6f1p-5,  -0x1.ac61ab99a9e82p-7,
      0x1.3bf9d581e4dcfp-8,  -0x1.dfdf12a9f9391p-10, 0x1.72e0077a2b690p-11, -0x1.21de1cb7d9e72p-12,
      0x1.c87333dc9a360p-14, -0x1.6925925983599p-15, 0x1.1eaa94568f0a6p-16, -0x1.c88eaa49ef6f4p-18,
      0x1.6d2dd6faa0775p-19, -0x1.1da1838b38616p-20, 0x1.b002ab8bc2ab3p-22, -0x1.bc4ecf0842989p-23,
      0x1.be335415ce408p-24};
  // relative error of psi < 2^-65
  static constexpr double kT[] = {
      0x1.555555555554ap-4,  -0x1.1111111100394p-7, 0x1.041040df8ffd8p-8, -0x1.1110fc7ec3de9p-8,
      0x1.f0751134afd89p-8,  -0x1.592e9241f5b91p-6, 0x1.512ebe73a1554p-4, -0x1.a648e2361b13fp-2,
      0x1.2a4ec52db2614p+1,  -0x1.9949b401ccbb7p+3, 0x1.da9f4e58e16c5p+5, -0x1.9a02cb4af58d4p+7,
      0x1.c588f53faa9b1p+8,  -0x1.d9b7412e5a03fp+8};
  static constexpr double kEulerGamma = 0x1.2788cfc6fb619p-1;
  static constexpr double kPsiTiny = 0x1.0p-54;
};

/// g = 1/Gamma(x) - 1 for x in [0.5, 2.5] as an unevaluated sum *gh + *gl,
/// from the factors xm1 = x - 1 (exact) and x - 2 = xm2 + xm2e (exact pair)
/// and u = x - 1.5, supplied by the caller so that they can be formed without
/// a rounded x. The factor product and the leading coefficient are kept exact
/// (Dekker), so g is good to a fraction of an ulp.
template <class T>
inline void recip_gamma_m1(T xm1, T xm2, T xm2e, T u, T* gh, T* gl) {
  using C = GammaCoeffs<T>;
  T r;
  T re;
  fast_two_sum(C::kR0Hi, C::kR0Lo + u * horner(C::kR, u), &r, &re);
  T m;
  T me;
  two_prod(xm1, xm2, &m, &me);
  me += xm1 * xm2e;
  T g;
  T ge;
  two_prod(m, r, &g, &ge);
  fast_two_sum(g, ge + (m * re + me * r), gh, gl);
}

/// lgamma x = -ln(1/Gamma x) = -ln(1 + gh + gl) for x in [0.5, 2.5], see
/// recip_gamma_m1 for the arguments; ln(1 + gh + gl) = ln(1 + gh) + gl / (1 + gh).
template <class T>
inline T lgamma_0_2(T xm1, T xm2, T xm2e, T u) {
  T gh;
  T gl;
  recip_gamma_m1(xm1, xm2, xm2e, u, &gh, &gl);
  T lh;
  T ll;
  log1p_hi_lo(gh, &lh, &ll);
  // 0 - lh, not -lh: dlgamma(1) and dlgamma(2) must be +0, not -0.
  return (T(0) - lh) - (ll + gl / (T(1) + gh));
}

/// lgamma x for x in [0.5, 2.5): x - 1 and x - 1.5 are exact there, x - 2
/// only from x >= 1, so it is formed as an exact pair.
template <class T>
inline T lgamma_half_to_2_5(T x) {
  T xm2;
  T xm2e;
  two_sum(x, T(-2), &xm2, &xm2e);
  return lgamma_0_2(x - T(1), xm2, xm2e, x - T(1.5));
}

/// a (ch + cl) with the product a ch exact: returns the rounded sum.
template <class T>
inline T mul_pair(T a, T ae, T ch, T cl) {
  T p;
  T pe;
  two_prod(a, ch, &p, &pe);
  return p + (pe + (a * cl + ae * (ch + cl)));
}

/// psi(1 + t) for t in [0, 1], with t exact (so psi(1 + t) for t < 1 needs no
/// rounded 1 + t): (t - (x0 - 1)) P1(t - 0.5), the difference and the leading
/// coefficient as exact pairs so that the root costs no accuracy.
template <class T>
inline T digamma_1_2(T t) {
  using C = GammaCoeffs<T>;
  const T u = t - T(0.5);
  T d;
  T de;
  two_sum(t, -C::kX0m1Hi, &d, &de);
  return mul_pair(d, de - C::kX0m1Lo, C::kP10Hi, C::kP10Lo + u * horner(C::kP1, u));
}

}  // namespace detail

/// Natural logarithm of the gamma function, for x > 0.
/// Special values: NaN -> NaN, x < 0 (outside the domain, also -inf) -> NaN,
/// +-0 -> +inf, +inf -> +inf; dlgamma(1) = dlgamma(2) = +0 exactly.
template <class T>
inline T dlgamma(T x) {
  static_assert(detail::kIsSupported<T>, "mptrack::dmath supports float and double only");
  using C = detail::GammaCoeffs<T>;
  if (detail::is_nan(x) || x < T(0)) {
    return detail::quiet_nan<T>();
  }
  if (detail::is_zero(x) || detail::is_inf(x)) {
    return detail::infinity<T>();
  }
  T hi;
  T lo;
  if (x < T(0.5)) {
    // lgamma x = lgamma (1 + x) - ln x, with g at 1 + x from x itself: the
    // factors are x (exact) and x - 1 (an exact pair), and ln x a double-word.
    T xm1;
    T xm1e;
    detail::two_sum(x, T(-1), &xm1, &xm1e);
    detail::log_hi_lo(x, &hi, &lo);
    return -hi + (detail::lgamma_0_2(x, xm1, xm1e, x - T(0.5)) - lo);
  }
  if (x < T(2.5)) {
    return detail::lgamma_half_to_2_5(x);
  }
  if (x < T(8)) {
    // lgamma x = lgamma y + ln(y (y+1) ... (x-1)), y = x - n in [1.5, 2.5).
    T y = x;
    T prod = T(1);
    while (y >= T(2.5)) {
      y -= T(1);  // exact for these x
      prod *= y;
    }
    detail::log_hi_lo(prod, &hi, &lo);
    return hi + (lo + detail::lgamma_half_to_2_5(y));
  }
  detail::log_hi_lo(x, &hi, &lo);
  const T t = x - T(0.5);
  if (x > C::kHuge) {
    return t * (hi - T(1));  // the series and the log tail are below an ulp
  }
  // t (ln x - 1): hi - 1 is exact (hi >= 2); the product is formed exactly.
  T p;
  T pe;
  detail::two_prod(t, hi - T(1), &p, &pe);
  const T w = T(1) / x;
  const T series = w * detail::horner(C::kStirling, w * w);
  return p + (((pe + t * lo) + series) + C::kHalfLn2PiMinusHalf);
}

/// Digamma (psi) function, the derivative of lgamma, for x > 0.
/// Special values: NaN -> NaN, x < 0 (outside the domain, also -inf) -> NaN,
/// +-0 -> -inf (the limit from the right), +inf -> +inf.
template <class T>
inline T ddigamma(T x) {
  static_assert(detail::kIsSupported<T>, "mptrack::dmath supports float and double only");
  using C = detail::GammaCoeffs<T>;
  if (detail::is_nan(x) || x < T(0)) {
    return detail::quiet_nan<T>();
  }
  if (detail::is_zero(x)) {
    return -detail::infinity<T>();
  }
  if (detail::is_inf(x)) {
    return x;
  }
  if (x >= T(3)) {
    T hi;
    T lo;
    detail::log_hi_lo(x, &hi, &lo);
    const T w = T(1) / x;
    const T z = w * w;
    return hi + (lo - (T(0.5) * w + z * detail::horner(C::kT, z)));
  }
  if (x >= T(2)) {
    const T u = x - T(2.5);
    return C::kP20Hi + (C::kP20Lo + u * detail::horner(C::kP2, u));
  }
  if (x >= T(1)) {
    return detail::digamma_1_2(x - T(1));
  }
  if (x < C::kPsiTiny) {
    return -(T(1) / x) - C::kEulerGamma;  // psi x = -1/x - gamma + O(x)
  }
  // psi x = psi(1 + x) - 1/x with 1/x = q + qe as a double-word.
  const T q = T(1) / x;
  T p;
  T pe;
  detail::two_prod(q, x, &p, &pe);
  const T qe = ((T(1) - p) - pe) * q;  // (1 - q x) / x
  return (detail::digamma_1_2(x) - qe) - q;
}

}  // namespace mptrack::dmath
