// Deterministic exponential and logarithm: dexp, dexpm1, dlog, dlog1p.
//
// Same bits on every target (see detmath.h for the rules and the accuracy
// table). Algorithms follow Sun's fdlibm, with our own minimax coefficients
// (Remez exchange in 50-digit arithmetic, coefficients rounded one at a time
// with the rest refitted), a shorter pure-float set for float:
//
// - exp:   Cody-Waite reduction x = k ln2 + r, |r| <= ln2/2, with ln2 split in
//          a short head (k * head exact) and a tail; e^r - 1 = r + r^2 Q(r)
//          (Q degree 9 double / 5 float); result scaled by 2^k on the bits.
// - expm1: the same reduction and polynomial, recombined as in fdlibm so no
//          cancellation occurs for small or moderate k.
// - log:   x = 2^k m, m in [sqrt2/2, sqrt2), f = m - 1, s = f / (2 + f);
//          ln(1+f) = f - f^2/2 + s (f^2/2 + R(s^2)) (fdlibm e_log.c), R of
//          degree 7 double / 3 float in s^2.
// - log1p: the same kernel on 1 + x, plus fdlibm's correction for the
//          rounding error of 1 + x.
#pragma once

#include "mptrack/math/constants.h"

namespace mptrack::dmath {
namespace detail {

template <class T>
struct ExpLogCoeffs;

template <>
struct ExpLogCoeffs<float> {
  // ln2 = kLn2Hi + kLn2Lo; kLn2Hi has 15 significant bits, so k * kLn2Hi is
  // exact for |k| < 2^9 (exp needs |k| <= 150, log |k| <= 152).
  static constexpr float kLn2Hi = 0x1.62e4p-1f;
  static constexpr float kLn2Lo = 0x1.7f7d1cp-20f;
  static constexpr float kInvLn2 = 0x1.715476p+0f;
  // (e^r - 1 - r) / r^2 on |r| <= 0.3466; relative error of e^r - 1 < 2^-28.1.
  static constexpr float kExpQ[] = {0x1.0p-1f,        0x1.55552cp-3f,  0x1.555502p-5f,
                                    0x1.1155a8p-7f,   0x1.6d2e4ap-10f, 0x1.3b88e6p-13f};
  // (2 atanh(s) / s - 2) / s^2 on s^2 <= 0.02944; relative error of ln(1+f) < 2^-30.2.
  static constexpr float kLogR[] = {0x1.55557ap-1f, 0x1.995ed4p-2f, 0x1.31e0dap-2f};
  static constexpr float kSqrt2 = 0x1.6a09e6p+0f;
  static constexpr float kExpOverflow = 89.0f;    ///< e^x = inf above (> ln FLT_MAX = 88.72)
  static constexpr float kExpUnderflow = -104.0f; ///< e^x = +0 below (< ln 2^-150 = -103.97)
  static constexpr float kExpm1Saturate = -18.0f; ///< e^x - 1 rounds to -1 below (e^-18 < 2^-25)
  static constexpr float kTiny = 0x1.0p-25f;      ///< below, e^x - 1 and ln(1+x) round to x
};

template <>
struct ExpLogCoeffs<double> {
  // kLn2Hi has 32 significant bits: k * kLn2Hi exact for |k| < 2^21.
  static constexpr double kLn2Hi = 0x1.62e42fee00000p-1;
  static constexpr double kLn2Lo = 0x1.a39ef35793c76p-33;
  static constexpr double kInvLn2 = 0x1.71547652b82fep+0;
  // relative error of e^r - 1 < 2^-55.2
  static constexpr double kExpQ[] = {
      0x1.0000000000000p-1,  0x1.555555555553ep-3,  0x1.5555555553b11p-5, 0x1.1111111118cf7p-7,
      0x1.6c16c179fd63bp-10, 0x1.a01a0171b6b8bp-13, 0x1.a019b3a1c7581p-16, 0x1.71de975f45657p-19,
      0x1.28976085f46bcp-22, 0x1.ae4924b5cec8dp-26};
  // relative error of ln(1+f) < 2^-59.5
  static constexpr double kLogR[] = {0x1.5555555555592p-1, 0x1.999999997ff06p-2, 0x1.24924941e30d8p-2,
                                     0x1.c71c521283b04p-3, 0x1.74663d5d8f953p-3, 0x1.39a1dbf4b1394p-3,
                                     0x1.2f04493a34995p-3};
  static constexpr double kSqrt2 = 0x1.6a09e667f3bcdp+0;
  static constexpr double kExpOverflow = 710.0;     ///< > ln DBL_MAX = 709.78
  static constexpr double kExpUnderflow = -746.0;   ///< < ln 2^-1075 = -745.13
  static constexpr double kExpm1Saturate = -40.0;   ///< e^-40 < 2^-54
  static constexpr double kTiny = 0x1.0p-54;
};

/// e^r - 1 for |r| <= ~0.35: r + r^2 Q(r). The leading r is added last, so the
/// relative error stays ~0.5 ulp also for tiny r.
template <class T>
inline T expm1_reduced(T r) {
  const T q = horner(ExpLogCoeffs<T>::kExpQ, r);
  return r + (r * r) * q;
}

/// a + e^r - 1 for |r| <= ~0.35 and an exactly representable a (1 for e^r,
/// 1 - 2^-k for expm1): a + r is formed exactly (TwoSum) and r^2 Q(r) plus a
/// small correction c (of the reduction) is added before the one rounding of
/// the result. This keeps e^r within ~0.55 ulp instead of ~1 ulp.
template <class T>
inline T add_expm1_reduced(T a, T r, T c) {
  const T r2q = (r * r) * horner(ExpLogCoeffs<T>::kExpQ, r);
  T head;
  T err;
  two_sum(a, r, &head, &err);
  return head + ((err + c) + r2q);
}

/// Cody-Waite reduction: hi + lo = k ln2 + r + c with |r| <= ~0.35, where
/// c is the rounding error of r (kept, since results near 2^k ln2 may be much
/// smaller than 2^k). Requires |hi| <= kExpOverflow and |lo| <= ~1e-3.
template <class T>
inline T exp_reduce(T hi, T lo, int* k, T* c) {
  using C = ExpLogCoeffs<T>;
  const int kk = round_to_int((hi + lo) * C::kInvLn2);
  const T kf = static_cast<T>(kk);
  const T r_hi = hi - kf * C::kLn2Hi;  // exact: k * kLn2Hi is exact and close to hi
  const T t = kf * C::kLn2Lo - lo;
  const T r = r_hi - t;
  *c = (r_hi - r) - t;
  *k = kk;
  return r;
}

/// e^(hi + lo) as p * 2^k (p in [0.7, 1.5]). Same preconditions as exp_reduce.
template <class T>
inline T exp_parts(T hi, T lo, int* k) {
  T c;
  const T r = exp_reduce(hi, lo, k, &c);
  // e^(r + c) = e^r (1 + c) = 1 + (e^r - 1) + c to within c^2 and c (e^r - 1).
  return add_expm1_reduced(T(1), r, c);
}

/// e^(hi + lo) as (head + *tail) * 2^k, unrounded, for callers that multiply
/// by a further factor before the one final rounding (derfc).
template <class T>
inline T exp_parts_pair(T hi, T lo, int* k, T* tail) {
  T c;
  const T r = exp_reduce(hi, lo, k, &c);
  const T r2q = (r * r) * horner(ExpLogCoeffs<T>::kExpQ, r);
  T head;
  T err;
  two_sum(T(1), r, &head, &err);
  *tail = (err + c) + r2q;
  return head;
}

/// Shared tail of the fdlibm logarithm: for f = m - 1 in [sqrt2/2-1, sqrt2-1]
/// writes hfsq = f^2/2 and sr = s (hfsq + R(s^2)), s = f / (2 + f), so that
/// ln(1+f) = f - (hfsq - sr). The one division is cheaper than the degree-20
/// polynomial that ln(1+f) would need on this interval.
template <class T>
inline void log_kernel(T f, T* hfsq, T* sr) {
  const T s = f / (T(2) + f);
  const T z = s * s;
  const T r = z * horner(ExpLogCoeffs<T>::kLogR, z);
  const T h = T(0.5) * f * f;
  *hfsq = h;
  *sr = s * (h + r);
}

/// x = 2^k (1 + f) with 1 + f in [sqrt2/2, sqrt2): returns f (exact), writes k.
/// x must be positive and finite.
template <class T>
inline T log_reduce(T x, int* k) {
  T m = split_exponent(x, k);
  if (m > ExpLogCoeffs<T>::kSqrt2) {
    m *= T(0.5);
    *k += 1;
  }
  return m - T(1);
}

/// ln x as an unevaluated sum hi + lo with |lo| <= ulp(hi) and an error of
/// about 2^-(p+4) relative (p = mantissa bits) for x >= 2. Used by dlgamma and
/// ddigamma, where ln x is multiplied by up to 1e6 or nearly cancelled.
/// x must be positive and finite.
template <class T>
inline void log_hi_lo(T x, T* hi, T* lo) {
  using C = ExpLogCoeffs<T>;
  int k = 0;
  const T f = log_reduce(x, &k);
  T hfsq;
  T sr;
  log_kernel(f, &hfsq, &sr);
  const T kf = static_cast<T>(k);
  T s;
  T e;
  two_sum(kf * C::kLn2Hi, f, &s, &e);  // k * kLn2Hi is exact
  const T tail = e + ((sr + kf * C::kLn2Lo) - hfsq);
  fast_two_sum(s, tail, hi, lo);
}

/// ln(1 + x) for x > -1 (finite, not tiny) as an unevaluated sum hi + lo,
/// the log1p counterpart of log_hi_lo (used by dlgamma near its zeros).
template <class T>
inline void log1p_hi_lo(T x, T* hi, T* lo) {
  using C = ExpLogCoeffs<T>;
  int k = 0;
  T f = x;
  T c = T(0);
  if (!(x > C::kSqrt2 * T(0.5) - T(1) && x < C::kSqrt2 - T(1))) {
    T u;
    T err;
    two_sum(T(1), x, &u, &err);
    f = log_reduce(u, &k);
    c = err / u;
  }
  T hfsq;
  T sr;
  log_kernel(f, &hfsq, &sr);
  const T kf = static_cast<T>(k);
  T s;
  T e;
  two_sum(kf * C::kLn2Hi, f, &s, &e);
  const T tail = e + (((sr - hfsq) + kf * C::kLn2Lo) + c);
  fast_two_sum(s, tail, hi, lo);
}

}  // namespace detail

/// e^x.
/// Special values: NaN -> NaN, +inf -> +inf, -inf -> +0, x > ln(max) -> +inf,
/// x < ln(min subnormal / 2) -> +0, dexp(+-0) = 1 exactly.
template <class T>
inline T dexp(T x) {
  static_assert(detail::kIsSupported<T>, "mptrack::dmath supports float and double only");
  using C = detail::ExpLogCoeffs<T>;
  if (detail::is_nan(x)) {
    return detail::quiet_nan<T>();
  }
  if (x > C::kExpOverflow) {
    return detail::infinity<T>();
  }
  if (x < C::kExpUnderflow) {
    return T(0);
  }
  int k = 0;
  const T p = detail::exp_parts(x, T(0), &k);
  return detail::scale(p, k);
}

/// e^x - 1, accurate also for small |x| where e^x - 1 would cancel.
/// Special values: NaN -> NaN, +inf -> +inf, -inf -> -1, +-0 -> +-0.
template <class T>
inline T dexpm1(T x) {
  static_assert(detail::kIsSupported<T>, "mptrack::dmath supports float and double only");
  using C = detail::ExpLogCoeffs<T>;
  using Tr = detail::FpTraits<T>;
  if (detail::is_nan(x)) {
    return detail::quiet_nan<T>();
  }
  if (x > C::kExpOverflow) {
    return detail::infinity<T>();
  }
  if (x < C::kExpm1Saturate) {
    return T(-1);
  }
  const T ax = detail::abs_value(x);
  if (ax < C::kTiny) {
    return x;  // e^x - 1 = x (1 + x/2 + ...) rounds to x; keeps the sign of zero
  }
  if (ax <= T(0.5) * C::kLn2Hi) {
    return detail::expm1_reduced(x);
  }
  int k = 0;
  T c;
  const T r = detail::exp_reduce(x, T(0), &k, &c);
  if (k >= -Tr::kMantissaBits && k <= Tr::kMantissaBits) {
    // e^x - 1 = 2^k ((1 - 2^-k) + (e^r - 1)); 1 - 2^-k is exact for these k,
    // (1 - 2^-k) + r is formed exactly and the sum is rounded once before the
    // exact scaling. Without this the absolute error of e^r - 1 would be
    // magnified by 2^k relative to a result that can be as small as 0.29.
    const T a = T(1) - detail::pow2<T>(-k);
    return detail::scale(detail::add_expm1_reduced(a, r, c * (T(1) + r)), k);
  }
  // k > mantissa bits: the -1 is below half an ulp (or the result is inf);
  // k < -mantissa bits: 2^k (1 + e) is below half an ulp of -1.
  return detail::scale(detail::add_expm1_reduced(T(1), r, c), k) - T(1);
}

/// Natural logarithm.
/// Special values: NaN -> NaN, x < 0 (also -inf) -> NaN, +-0 -> -inf,
/// +inf -> +inf, dlog(1) = +0 exactly. Subnormal x are handled.
template <class T>
inline T dlog(T x) {
  static_assert(detail::kIsSupported<T>, "mptrack::dmath supports float and double only");
  using C = detail::ExpLogCoeffs<T>;
  if (detail::is_nan(x)) {
    return detail::quiet_nan<T>();
  }
  if (detail::is_zero(x)) {
    return -detail::infinity<T>();
  }
  if (x < T(0)) {
    return detail::quiet_nan<T>();
  }
  if (detail::is_inf(x)) {
    return x;
  }
  int k = 0;
  const T f = detail::log_reduce(x, &k);
  T hfsq;
  T sr;
  detail::log_kernel(f, &hfsq, &sr);
  const T kf = static_cast<T>(k);
  // fdlibm's order: the exact head k ln2_hi is added last, f next to last.
  return kf * C::kLn2Hi - ((hfsq - (sr + kf * C::kLn2Lo)) - f);
}

/// ln(1 + x), accurate also for small |x| where 1 + x would round.
/// Special values: NaN -> NaN, x < -1 -> NaN, x = -1 -> -inf, +inf -> +inf,
/// +-0 -> +-0.
template <class T>
inline T dlog1p(T x) {
  static_assert(detail::kIsSupported<T>, "mptrack::dmath supports float and double only");
  using C = detail::ExpLogCoeffs<T>;
  if (detail::is_nan(x)) {
    return detail::quiet_nan<T>();
  }
  if (x < T(-1)) {
    return detail::quiet_nan<T>();
  }
  if (!(x > T(-1))) {
    return -detail::infinity<T>();
  }
  if (detail::is_inf(x)) {
    return x;
  }
  if (detail::abs_value(x) < C::kTiny) {
    return x;  // ln(1+x) = x (1 - x/2 + ...) rounds to x; keeps the sign of zero
  }
  int k = 0;
  T f;
  T c = T(0);
  if (x > C::kSqrt2 * T(0.5) - T(1) && x < C::kSqrt2 - T(1)) {
    f = x;  // 1 + x already in [sqrt2/2, sqrt2): no reduction, f exact
  } else {
    // u = 1 + x rounded, err = (1 + x) - u exactly (TwoSum; fdlibm's shortcut
    // 1 - (u - x) is inexact for x in (0.41, 0.5) and cost two ulps there).
    // ln(1 + x) = ln u + ln(1 + err/u) = ln u + err/u to within 2^-2p.
    T u;
    T err;
    detail::two_sum(T(1), x, &u, &err);
    f = detail::log_reduce(u, &k);
    c = err / u;
  }
  T hfsq;
  T sr;
  detail::log_kernel(f, &hfsq, &sr);
  const T kf = static_cast<T>(k);
  return kf * C::kLn2Hi - ((hfsq - (sr + (kf * C::kLn2Lo + c))) - f);
}

}  // namespace mptrack::dmath
