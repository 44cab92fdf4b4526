// Deterministic circular functions: dsin, dcos, dsincos, datan, datan2.
//
// Same bits on every target (see detmath.h for the rules and the accuracy
// table). Algorithms:
//
// - Argument reduction x = n pi/2 + r, |r| <= pi/4 (+ rounding slack):
//   * double: fdlibm's "medium" __ieee754_rem_pio2: pi/2 in three 33-bit
//     pieces plus tails, so n * piece is exact for n < 2^20; a second and
//     third Cody-Waite step run only when the first one cancels, which makes
//     r good to ~150 bits, enough for every double in the domain. r is kept
//     as a double-double (r, r_tail).
//   * float: Cody-Waite with pi/2 in three 8-bit pieces (n * piece exact for
//     n < 2^16) and a 24-bit tail. Where that would lose relative accuracy
//     (|r| < n 2^-19, i.e. x close to a multiple of pi/2) an exact integer
//     reduction runs instead: x and n * (pi/2 rounded to 2^-94) are formed in
//     128-bit fixed point with 32x32->64-bit products, so the result is
//     correct to ~2^-79 absolute. Pure integer and float operations.
//   The domain is |x| <= kTrigMaxArg<T> (~1.6e6 double, ~1.0e5 float); beyond
//   it (and for +-inf) the result is NaN: such an angle has lost all meaning
//   (the float ulp at 1e5 is 0.008 rad) and a silent value would hide the bug.
// - Kernels on |r| <= 0.79: fdlibm __kernel_sin / __kernel_cos, including
//   the correction for r_tail, with our minimax coefficients
//   (sin r = r + r^3 S(r^2), cos r = 1 - r^2/2 + r^4 C(r^2); degree 5 in r^2
//   for double, 2 for float).
// - atan2: the argument ratio a = min(|x|,|y|) / max(|x|,|y|) in [0, 1] is
//   reduced as in fdlibm's s_atan.c to t in [-0.19, 0.44] around 0, 1/2 or 1
//   with one division (t = (2a-1)/(2+a) is computed as (2 num - den) /
//   (2 den + num), never from a rounded a); atan t = t + t^3 A(t^2) (degree
//   10 double / 4 float). The quadrant offset (0, pi/2, pi) and the interval
//   base (0, atan 1/2, pi/4) are combined in float-float and added to the
//   polynomial in one final rounding.
#pragma once

#include <cstdint>

#include "mptrack/math/constants.h"

namespace mptrack::dmath {

/// Largest |x| accepted by dsin, dcos and dsincos; NaN beyond (see file comment).
template <class T>
inline constexpr T kTrigMaxArg = detail::pick<T>(0x1.921fb6p+16f, 0x1.921fb54442d18p+20);

namespace detail {

template <class T>
struct TrigCoeffs;

template <>
struct TrigCoeffs<float> {
  // pi/2 = kPio2[0] + kPio2[1] + kPio2[2] + kPio2Tail; the pieces have 8
  // significant bits each, so n * piece is exact for n < 2^16.
  static constexpr float kPio2[] = {0x1.92p+0f, 0x1.fap-12f, 0x1.54p-20f};
  static constexpr float kPio2Tail = 0x1.10b462p-30f;
  static constexpr float kTwoOverPi = 0x1.45f306p-1f;
  // pi/2 * 2^94 rounded, as three 32-bit limbs (most significant first).
  static constexpr std::uint32_t kPio2Fixed[] = {0x6487ed51u, 0x10b4611au, 0x62633146u};
  static constexpr int kPio2FixedShift = 94;
  // (sin r - r) / r^3 and (cos r - 1 + r^2/2) / r^4 as polynomials in z = r^2,
  // z <= 0.6241 (|r| <= 0.79); relative errors < 2^-27.8 and < 2^-32.8.
  static constexpr float kSin[] = {-0x1.555544p-3f, 0x1.1106c6p-7f, -0x1.991c28p-13f};
  static constexpr float kCos[] = {0x1.55554ap-5f, -0x1.6c0c1ep-10f, 0x1.99e336p-16f};
  static constexpr float kTiny = 0x1.0p-12f;  ///< below, sin x rounds to x and cos x to 1
  // (atan t - t) / t^3 in z = t^2 <= 0.1914; relative error of atan < 2^-29.5.
  static constexpr float kAtan[] = {-0x1.555542p-2f, 0x1.998df8p-3f, -0x1.236f16p-3f, 0x1.add6b2p-4f,
                                    -0x1.dd3c62p-5f};
  static constexpr float kAtanHalfHi = 0x1.dac670p-2f;  ///< atan(1/2) = hi + lo
  static constexpr float kAtanHalfLo = 0x1.586ed4p-28f;
  static constexpr float kPio4Hi = 0x1.921fb6p-1f;  ///< pi/4 = hi + lo
  static constexpr float kPio4Lo = -0x1.777a5cp-26f;
  static constexpr float kPio2Hi = 0x1.921fb6p+0f;  ///< pi/2 = hi + lo
  static constexpr float kPio2Lo = -0x1.777a5cp-25f;
  static constexpr float kPiHi = 0x1.921fb6p+1f;  ///< pi = hi + lo
  static constexpr float kPiLo = -0x1.777a5cp-24f;
};

template <>
struct TrigCoeffs<double> {
  // fdlibm e_rem_pio2.c: pio2_1 (33 bits), pio2_1t = pi/2 - pio2_1, ...
  static constexpr double kPio2_1 = 0x1.921fb54400000p+0;
  static constexpr double kPio2_1t = 0x1.0b4611a626331p-34;
  static constexpr double kPio2_2 = 0x1.0b4611a600000p-34;
  static constexpr double kPio2_2t = 0x1.3198a2e037073p-69;
  static constexpr double kPio2_3 = 0x1.3198a2e000000p-69;
  static constexpr double kPio2_3t = 0x1.b839a252049c1p-104;
  static constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;
  // |r| <= 0.79; relative errors < 2^-57.7 (sin) and < 2^-63.8 (cos).
  static constexpr double kSin[] = {-0x1.5555555555547p-3, 0x1.111111110f595p-7, -0x1.a01a019bb4447p-13,
                                    0x1.71de3526325f2p-19, -0x1.ae5e25f41d393p-26, 0x1.5d803e089ce0bp-33};
  static constexpr double kCos[] = {0x1.555555555554ap-5,  -0x1.6c16c16c14df7p-10, 0x1.a01a019c5abd0p-16,
                                    -0x1.27e4f7cbcc1edp-22, 0x1.1ee9c216e1f54p-29,  -0x1.8f9924f9cfb56p-37};
  static constexpr double kTiny = 0x1.0p-27;
  // relative error of atan < 2^-57.7
  static constexpr double kAtan[] = {-0x1.555555555550bp-2, 0x1.999999998e7e9p-3, -0x1.2492491ff35dep-3,
                                     0x1.c71c6fdb2646fp-4,  -0x1.745cdba584f84p-4, 0x1.3b0f206a60ab9p-4,
                                     -0x1.10d60201c0fb7p-4, 0x1.ddddb21295c2ep-5,  -0x1.97a091aaaa4d0p-5,
                                     0x1.2b17bf35079b3p-5,  -0x1.0a7eba04cae38p-6};
  static constexpr double kAtanHalfHi = 0x1.dac670561bb4fp-2;
  static constexpr double kAtanHalfLo = 0x1.a2b7f222f65e2p-56;
  static constexpr double kPio4Hi = 0x1.921fb54442d18p-1;
  static constexpr double kPio4Lo = 0x1.1a62633145c07p-55;
  static constexpr double kPio2Hi = 0x1.921fb54442d18p+0;
  static constexpr double kPio2Lo = 0x1.1a62633145c07p-54;
  static constexpr double kPiHi = 0x1.921fb54442d18p+1;
  static constexpr double kPiLo = 0x1.1a62633145c07p-53;
};

/// Biased exponent field of a double (for fdlibm's cancellation test).
inline int exponent_field(double x) {
  return static_cast<int>((to_bits(x) >> 52) & 0x7ffu);
}

/// x = n pi/2 + (*y0 + *y1) for pi/4 < |x| <= kTrigMaxArg<double>; returns n.
/// fdlibm e_rem_pio2.c, medium case, unchanged in structure.
inline int rem_pio2(double x, double* y0, double* y1) {
  using C = TrigCoeffs<double>;
  const double t = abs_value(x);
  const int n = static_cast<int>(t * C::kTwoOverPi + 0.5);
  const double fn = static_cast<double>(n);
  double r = t - fn * C::kPio2_1;  // exact: n < 2^20, kPio2_1 has 33 bits
  double w = fn * C::kPio2_1t;     // first round good to 85 bits
  const int j = exponent_field(t);
  double y = r - w;
  if (j - exponent_field(y) > 16) {
    // Cancellation of more than 16 bits: second round, good to 118 bits.
    double u = r;
    w = fn * C::kPio2_2;
    r = u - w;
    w = fn * C::kPio2_2t - ((u - r) - w);
    y = r - w;
    if (j - exponent_field(y) > 49) {
      // Third round, 151 bits: covers every double in the domain.
      u = r;
      w = fn * C::kPio2_3;
      r = u - w;
      w = fn * C::kPio2_3t - ((u - r) - w);
      y = r - w;
    }
  }
  const double tail = (r - y) - w;
  if (sign_bit(x)) {
    *y0 = -y;
    *y1 = -tail;
    return -n;
  }
  *y0 = y;
  *y1 = tail;
  return n;
}

/// Number of leading zero bits of a nonzero 64-bit value (portable).
inline int count_leading_zeros(std::uint64_t v) {
  int n = 0;
  for (int step = 32; step > 0; step >>= 1) {
    if ((v >> (64 - step)) == 0) {
      v <<= step;
      n += step;
    }
  }
  return n;
}

/// |x| - n pi/2 exactly in 128-bit fixed point (unit 2^-94), for
/// 0.5 <= |x| < 2^17 and 0 <= n < 2^16; result rounded to hi + lo floats.
inline void rem_pio2_exact(float ax, int n, float* y0, float* y1) {
  using C = TrigCoeffs<float>;
  const std::uint32_t u = to_bits(ax);
  const std::uint64_t mant = static_cast<std::uint64_t>((u & 0x007fffffu) | 0x00800000u);
  const int e = static_cast<int>(u >> 23) - 150;  // ax = mant * 2^e, e in [-24, -7]
  // X = mant * 2^(e + 94) lies entirely in the high 64-bit word.
  const std::uint64_t x_hi = mant << (e + C::kPio2FixedShift - 64);
  const std::uint64_t x_lo = 0;
  // N = n * P with P = (P2 P1 P0) 32-bit limbs.
  const std::uint64_t nn = static_cast<std::uint64_t>(n);
  const std::uint64_t a0 = nn * C::kPio2Fixed[2];
  const std::uint64_t a1 = nn * C::kPio2Fixed[1];
  const std::uint64_t a2 = nn * C::kPio2Fixed[0];
  const std::uint64_t n_lo = a0 + (a1 << 32);
  const std::uint64_t n_hi = a2 + (a1 >> 32) + (n_lo < a0 ? 1u : 0u);
  // D = X - N, as sign and magnitude.
  const bool negative = x_hi < n_hi || (x_hi == n_hi && x_lo < n_lo);
  std::uint64_t d_hi;
  std::uint64_t d_lo;
  if (negative) {
    d_lo = n_lo - x_lo;
    d_hi = n_hi - x_hi - (n_lo < x_lo ? 1u : 0u);
  } else {
    d_lo = x_lo - n_lo;
    d_hi = x_hi - n_hi - (x_lo < n_lo ? 1u : 0u);
  }
  // Top 63 significant bits into `top` (63, not 64, so that the rounded float
  // value converts back to an integer without overflow), value = top * 2^exp2.
  std::uint64_t top;
  int exp2;
  if (d_hi != 0) {
    const int s = count_leading_zeros(d_hi);
    top = s == 0 ? d_hi : (d_hi << s) | (d_lo >> (64 - s));
    exp2 = 64 - s - C::kPio2FixedShift;
  } else if (d_lo != 0) {
    const int s = count_leading_zeros(d_lo);
    top = d_lo << s;
    exp2 = -s - C::kPio2FixedShift;
  } else {
    *y0 = 0.0f;
    *y1 = 0.0f;
    return;
  }
  top >>= 1;
  exp2 += 1;
  const float head = static_cast<float>(top);  // correctly rounded conversion
  const std::uint64_t head_int = static_cast<std::uint64_t>(head);
  const std::int64_t rest = static_cast<std::int64_t>(top - head_int);  // |rest| < 2^39
  float hi = scale(head, exp2);
  float lo = scale(static_cast<float>(rest), exp2);
  if (negative) {
    hi = -hi;
    lo = -lo;
  }
  *y0 = hi;
  *y1 = lo;
}

/// x = n pi/2 + (*y0 + *y1) for pi/4 < |x| <= kTrigMaxArg<float>; returns n.
inline int rem_pio2(float x, float* y0, float* y1) {
  using C = TrigCoeffs<float>;
  const float t = abs_value(x);
  const int n = static_cast<int>(t * C::kTwoOverPi + 0.5f);
  const float fn = static_cast<float>(n);
  // Each product has at most 8 + 16 bits and is exact, and so are the first
  // two differences (Sterbenz, then a result on the 2^-24 grid); the third
  // difference can round, so its error e is kept (TwoSum).
  const float r2 = (t - fn * C::kPio2[0]) - fn * C::kPio2[1];
  float r;
  float e;
  two_sum(r2, -(fn * C::kPio2[2]), &r, &e);
  const float w = fn * C::kPio2Tail;
  float y = r - w;
  float tail = ((r - y) - w) + e;
  // The tail product errs by up to n 2^-47; below n 2^-19 that is more than
  // 2^-28 relative to y, so recompute exactly (rare: x near a multiple of pi/2).
  if (abs_value(y) * 0x1.0p19f < fn) {
    rem_pio2_exact(t, n, &y, &tail);
  }
  if (sign_bit(x)) {
    *y0 = -y;
    *y1 = -tail;
    return -n;
  }
  *y0 = y;
  *y1 = tail;
  return n;
}

/// sin (x + y) for |x| <= 0.79, |y| <= ulp(x) (fdlibm __kernel_sin).
template <class T>
inline T sin_kernel(T x, T y) {
  const T* c = TrigCoeffs<T>::kSin;
  constexpr std::size_t kN = sizeof(TrigCoeffs<T>::kSin) / sizeof(T);
  const T z = x * x;
  const T v = z * x;
  // r = S2 + z S3 + ... (Horner from the top; c[0] = S1 is applied below)
  T r = c[kN - 1];
  for (std::size_t i = kN - 1; i > 1; --i) {
    r = r * z + c[i - 1];
  }
  // x + v (S1 + z r) + y cos x, with the tail folded in as in fdlibm
  return x - ((z * (T(0.5) * y - v * r) - y) - v * c[0]);
}

/// cos (x + y) for |x| <= 0.79, |y| <= ulp(x) (fdlibm __kernel_cos): the
/// 1 - x^2/2 part is split so that its rounding error is recovered.
template <class T>
inline T cos_kernel(T x, T y) {
  const T z = x * x;
  const T r = z * horner(TrigCoeffs<T>::kCos, z);
  const T hz = T(0.5) * z;
  const T w = T(1) - hz;
  return w + (((T(1) - w) - hz) + (z * r - x * y));
}

/// Reduction shared by dsin, dcos and dsincos. Returns false (NaN result)
/// outside the domain; otherwise the quadrant n and r = y0 + y1.
template <class T>
inline bool trig_reduce(T x, int* n, T* y0, T* y1) {
  const T ax = abs_value(x);
  if (!(ax <= kTrigMaxArg<T>)) {  // also NaN and +-inf
    return false;
  }
  if (ax <= kQuarterPi<T>) {
    *n = 0;
    *y0 = x;
    *y1 = T(0);
    return true;
  }
  *n = rem_pio2(x, y0, y1);
  return true;
}

/// atan2 for non-NaN y, x (see file comment).
template <class T>
inline T atan2_kernel(T y, T x) {
  using C = TrigCoeffs<T>;
  using Tr = FpTraits<T>;
  T ax = abs_value(x);
  T ay = abs_value(y);
  const bool swap = abs_bits(ay) > abs_bits(ax);
  T num = swap ? ax : ay;
  T den = swap ? ay : ax;
  T base_hi = T(0);
  T base_lo = T(0);
  T p = T(0);
  if (is_inf(num)) {  // both infinite: the ratio is 1
    base_hi = C::kPio4Hi;
    base_lo = C::kPio4Lo;
  } else if (!is_zero(den)) {  // (both zero leaves theta0 = 0)
    if (den > pow2<T>(Tr::kMaxExponent - 2)) {
      num *= T(0.25);  // keep 2 den + num finite; exact unless num is tiny,
      den *= T(0.25);  // and then the ratio is below the result's precision
    }
    T t;
    if (num < T(0.4375) * den) {
      t = num / den;
    } else if (num < T(0.6875) * den) {
      t = (T(2) * num - den) / (T(2) * den + num);  // (2a - 1) / (2 + a)
      base_hi = C::kAtanHalfHi;
      base_lo = C::kAtanHalfLo;
    } else {
      t = (num - den) / (num + den);  // (a - 1) / (a + 1)
      base_hi = C::kPio4Hi;
      base_lo = C::kPio4Lo;
    }
    const T z = t * t;
    p = t + t * (z * horner(C::kAtan, z));
  }
  // theta = off + s (base + p): off = 0, pi/2 or pi, s = +-1 by quadrant.
  T off_hi = T(0);
  T off_lo = T(0);
  bool minus = false;
  if (sign_bit(x)) {
    off_hi = swap ? C::kPio2Hi : C::kPiHi;
    off_lo = swap ? C::kPio2Lo : C::kPiLo;
    minus = !swap;
  } else if (swap) {
    off_hi = C::kPio2Hi;
    off_lo = C::kPio2Lo;
    minus = true;
  }
  if (minus) {
    base_hi = -base_hi;
    base_lo = -base_lo;
    p = -p;
  }
  T k_hi;
  T k_err;
  two_sum(off_hi, base_hi, &k_hi, &k_err);
  const T theta = k_hi + (((k_err + off_lo) + base_lo) + p);
  return sign_bit(y) ? -theta : theta;
}

}  // namespace detail

/// sin x, x in radians.
/// Special values: NaN, +-inf and |x| > kTrigMaxArg<T> -> NaN; +-0 -> +-0.
template <class T>
inline T dsin(T x) {
  static_assert(detail::kIsSupported<T>, "mptrack::dmath supports float and double only");
  if (detail::abs_value(x) < detail::TrigCoeffs<T>::kTiny) {
    return x;  // sin x = x (1 - x^2/6) rounds to x; keeps the sign of zero
  }
  int n = 0;
  T y0;
  T y1;
  if (!detail::trig_reduce(x, &n, &y0, &y1)) {
    return detail::quiet_nan<T>();
  }
  switch (n & 3) {
    case 0: return detail::sin_kernel(y0, y1);
    case 1: return detail::cos_kernel(y0, y1);
    case 2: return -detail::sin_kernel(y0, y1);
    default: return -detail::cos_kernel(y0, y1);
  }
}

/// cos x, x in radians.
/// Special values: NaN, +-inf and |x| > kTrigMaxArg<T> -> NaN; dcos(+-0) = 1.
template <class T>
inline T dcos(T x) {
  static_assert(detail::kIsSupported<T>, "mptrack::dmath supports float and double only");
  if (detail::abs_value(x) < detail::TrigCoeffs<T>::kTiny) {
    return T(1);
  }
  int n = 0;
  T y0;
  T y1;
  if (!detail::trig_reduce(x, &n, &y0, &y1)) {
    return detail::quiet_nan<T>();
  }
  switch (n & 3) {
    case 0: return detail::cos_kernel(y0, y1);
    case 1: return -detail::sin_kernel(y0, y1);
    case 2: return -detail::cos_kernel(y0, y1);
    default: return detail::sin_kernel(y0, y1);
  }
}

/// sin x and cos x with one argument reduction; bit-identical to dsin(x) and
/// dcos(x). Special values as for dsin / dcos (both NaN outside the domain).
template <class T>
inline void dsincos(T x, T& s, T& c) {
  static_assert(detail::kIsSupported<T>, "mptrack::dmath supports float and double only");
  if (detail::abs_value(x) < detail::TrigCoeffs<T>::kTiny) {
    s = x;
    c = T(1);
    return;
  }
  int n = 0;
  T y0;
  T y1;
  if (!detail::trig_reduce(x, &n, &y0, &y1)) {
    s = detail::quiet_nan<T>();
    c = s;
    return;
  }
  const T sk = detail::sin_kernel(y0, y1);
  const T ck = detail::cos_kernel(y0, y1);
  switch (n & 3) {
    case 0: s = sk; c = ck; break;
    case 1: s = ck; c = -sk; break;
    case 2: s = -sk; c = -ck; break;
    default: s = -ck; c = sk; break;
  }
}

/// Angle of the point (x, y) in (-pi, pi], radians.
/// Special values (C99 Annex F): NaN in either -> NaN; datan2(+-0, +0) = +-0;
/// datan2(+-0, -0) = +-pi; datan2(+-0, x<0) = +-pi; datan2(y>0, +-0) = pi/2;
/// datan2(+-y, -inf) = +-pi and datan2(+-y, +inf) = +-0 for finite y;
/// datan2(+-inf, x finite) = +-pi/2; datan2(+-inf, -inf) = +-3pi/4;
/// datan2(+-inf, +inf) = +-pi/4.
template <class T>
inline T datan2(T y, T x) {
  static_assert(detail::kIsSupported<T>, "mptrack::dmath supports float and double only");
  if (detail::is_nan(x) || detail::is_nan(y)) {
    return detail::quiet_nan<T>();
  }
  return detail::atan2_kernel(y, x);
}

/// Arc tangent, result in [-pi/2, pi/2] radians; bit-identical to
/// datan2(x, 1). Special values: NaN -> NaN, +-inf -> +-pi/2, +-0 -> +-0.
template <class T>
inline T datan(T x) {
  static_assert(detail::kIsSupported<T>, "mptrack::dmath supports float and double only");
  if (detail::is_nan(x)) {
    return detail::quiet_nan<T>();
  }
  return detail::atan2_kernel(x, T(1));
}

}  // namespace mptrack::dmath
