// Deterministic error function and its complement: derf, derfc.
//
// Same bits on every target (see detmath.h for the rules and the accuracy
// table). The split follows fdlibm s_erf.c, with polynomials instead of its
// rational functions (one division fewer) and our own minimax coefficients:
//
// - |x| < 0.75: erf x = x + x Y(x^2) (Y degree 10 double / 5 float);
//   erfc x = 1 - (x + x Y) for x < 1/4, else 0.5 - ((x - 0.5) + x Y), where
//   x - 0.5 is exact (fdlibm's trick against cancellation).
// - |x| >= 0.75: erfc a = e^(-a^2) G(a) with the scaled complement
//   G = erfcx, which is smooth and free of underflow. G is a polynomial in
//   a - c on [0.75, 1.5), [1.5, 2.5) (and [2.5, 4) for double), and beyond
//   G(a) = K(1/a^2) / a (K degree 14 double / 7 float, fitted only up to the
//   underflow point of erfc, so no asymptotic series is needed). The leading
//   coefficient of each piece is a hi + lo pair, so it adds no rounding.
//   e^(-a^2) is evaluated from a^2 as an exact sum p + e (Dekker product), so
//   the large argument costs no accuracy, and the scaling by 2^k comes after
//   the product with G: the result underflows gracefully with one rounding.
//   erf a = 1 - erfc a, erfc(-a) = 2 - erfc a.
#pragma once

#include "mptrack/math/constants.h"
#include "mptrack/math/exp_log.h"

namespace mptrack::dmath {
namespace detail {

template <class T>
struct ErfCoeffs;

template <>
struct ErfCoeffs<float> {
  // erf(x)/x - 1 in z = x^2 <= 0.5625; relative error of erf < 2^-29.2.
  static constexpr float kY[] = {0x1.06eba8p-3f,  -0x1.81273ap-2f, 0x1.ce2acep-4f,
                                 -0x1.b7a75cp-6f, 0x1.4f188ap-8f,  -0x1.613e5p-11f};
  // erfcx(a) on [0.75, 1.5) in a - 1.125: kA0Hi + kA0Lo + u kA(u); rel. error < 2^-29.3.
  static constexpr float kA0Hi = 0x1.9531ep-2f;
  static constexpr float kA0Lo = 0x1.35ab1p-27f;
  static constexpr float kA[] = {-0x1.e78b34p-3f, 0x1.05e724p-3f,  -0x1.0134e8p-4f, 0x1.d4eba4p-6f,
                                 -0x1.90a12p-7f,  0x1.431d52p-8f,  -0x1.06508ap-9f, 0x1.a5f9eep-11f};
  // erfcx(a) on [1.5, 2.5) in a - 2; relative error < 2^-30.
  static constexpr float kB0Hi = 0x1.058672p-2f;
  static constexpr float kB0Lo = -0x1.2be82ap-28f;
  static constexpr float kB[] = {-0x1.b57034p-4f, 0x1.5672bap-5f,  -0x1.fa9e8ap-7f, 0x1.649032p-8f,
                                 -0x1.dfa21ap-10f, 0x1.36a82ep-11f, -0x1.98497p-13f, 0x1.dcc732p-15f};
  static constexpr float kTailStart = 2.5f;
  // a erfcx(a) in s = 1/a^2 for a in [2.5, 10.1]; relative error < 2^-29.4.
  static constexpr float kK0Hi = 0x1.20dd74p-1f;
  static constexpr float kK0Lo = 0x1.079dfap-28f;
  static constexpr float kK[] = {-0x1.20dbfcp-2f, 0x1.b0d68ep-2f,  -0x1.0a25b8p+0f, 0x1.a2b9d6p+1f,
                                 -0x1.44cf0ep+3f, 0x1.726018p+4f,  -0x1.a08c04p+4f};
  static constexpr float kErfOne = 4.0f;      ///< erf x rounds to +-1 beyond (erfc 4 < 2^-25)
  static constexpr float kErfcZero = 10.1f;   ///< erfc x underflows to 0 beyond
};

template <>
struct ErfCoeffs<double> {
  // relative error of erf < 2^-56.3
  static constexpr double kY[] = {0x1.06eba8214db69p-3,  -0x1.812746b037a33p-2, 0x1.ce2f21a046eadp-4,
                                  -0x1.b82ce313f3216p-6, 0x1.565bcd4c79647p-8,  -0x1.c02dc010b9d67p-11,
                                  0x1.f9a48c1f2db0ap-14, -0x1.f4eab043bbfe3p-17, 0x1.bac7856859b45p-20,
                                  -0x1.61bb6292d85f5p-23, 0x1.caa9b38f7b2b9p-27};
  // [0.75, 1.5) in a - 1.125; relative error < 2^-55.9
  static constexpr double kA0Hi = 0x1.9531e09b149b5p-2;
  static constexpr double kA0Lo = -0x1.c2aab57b65e4ep-58;
  static constexpr double kA[] = {
      -0x1.e78b356770fbdp-3, 0x1.05e72521ca1c3p-3,   -0x1.01343a2c91e19p-4, 0x1.d4e711a2dc681p-6,
      -0x1.910a5d7caf2cdp-7, 0x1.446c5169a3ce2p-8,   -0x1.f38c6c5776ea7p-10, 0x1.6fd9a2ff871f3p-11,
      -0x1.041e679645eaap-12, 0x1.6275690be042ap-14, -0x1.d2983df733792p-16, 0x1.2948fe87989b6p-17,
      -0x1.74320d4f85ee2p-19, 0x1.d0d1721df9b06p-21, -0x1.a11be2d1d9588p-23};
  // [1.5, 2.5) in a - 2; relative error < 2^-54.9
  static constexpr double kB0Hi = 0x1.058671b52c776p-2;
  static constexpr double kB0Lo = -0x1.6f6d6f9af1e95p-58;
  static constexpr double kB[] = {
      -0x1.b57034efd3f79p-4, 0x1.5672b9ea13e1ap-5,   -0x1.fa9d3ac953c44p-7, 0x1.649072159b34ep-8,
      -0x1.e028e8a83b1f9p-10, 0x1.369ffa1062961p-11, -0x1.83821fbf18767p-13, 0x1.d37b9ce155684p-15,
      -0x1.115d7e712da25p-16, 0x1.3699b0cfaac3bp-18, -0x1.574eb45c6d075p-20, 0x1.71a021dd6d723p-22,
      -0x1.8c59f8db8e6e2p-24, 0x1.aab3bd961b4a5p-26, -0x1.30772fbee1581p-28};
  // [2.5, 4) in a - 3.25; relative error < 2^-56.2
  static constexpr double kC0Hi = 0x1.54a7a08d4bb45p-3;
  static constexpr double kC0Lo = -0x1.7765837d7eb35p-61;
  static constexpr double kC[] = {
      -0x1.82a8522b868a0p-5,  0x1.a7eddc9ee6428p-7,  -0x1.c24b49c47a8a9p-9,  0x1.d085857a17cdep-11,
      -0x1.d25ebba131b2fp-13, 0x1.c882f0237127cp-15, -0x1.b45d02c62eeefp-17, 0x1.97dd78fc54095p-19,
      -0x1.753c856cfd217p-21, 0x1.4ec07e890c6dfp-23, -0x1.26942c2b96679p-25, 0x1.fd026f7a4b433p-28,
      -0x1.ae40db64209a9p-30, 0x1.6786c1a6960dfp-32, -0x1.469c41702b6b3p-34, 0x1.0633a382f53b7p-36};
  static constexpr double kTailStart = 4.0;
  // a erfcx(a) in s = 1/a^2 for a in [4, 27.3]; relative error < 2^-59.6
  static constexpr double kK0Hi = 0x1.20dd750429b6dp-1;
  static constexpr double kK0Lo = -0x1.8f5e0c6a402d1p-56;
  static constexpr double kK[] = {
      -0x1.20dd7504297fap-2, 0x1.b14c2f85b3277p-2, -0x1.0ecf9d85c8283p+0, 0x1.d9eb41a2371ebp+1,
      -0x1.0a932e610f802p+4, 0x1.6e70bbc0ee703p+6, -0x1.28f21634c6505p+9, 0x1.11eecdc10e562p+12,
      -0x1.10ba47f72ffd1p+15, 0x1.0d05ad428f46fp+18, -0x1.d6242f5c23a29p+20, 0x1.40340227f99aep+23,
      -0x1.20f9624fda7f2p+25, 0x1.f86090e296e2cp+25};
  static constexpr double kErfOne = 6.0;     ///< erfc 6 < 2^-54
  static constexpr double kErfcZero = 27.3;  ///< erfc 27.3 < 2^-1075
};

/// erfc a for 0.75 <= a < kErfcZero: e^(-a^2) G(a), both factors as
/// unevaluated pairs and their leading product exact (Dekker), so that the
/// result is rounded about once (then scaled by 2^k, exactly unless subnormal).
template <class T>
inline T erfc_kernel(T a) {
  using C = ErfCoeffs<T>;
  T sq;
  T sq_err;
  two_prod(a, a, &sq, &sq_err);  // a^2 = sq + sq_err exactly
  int k = 0;
  T et;
  const T eh = exp_parts_pair(-sq, -sq_err, &k, &et);
  // G = gh + gl: the leading coefficient pair plus u P(u) (or K for the tail).
  T gh = T(0);
  T gl = T(0);
  bool tail = false;
  if (a < T(1.5)) {
    const T u = a - T(1.125);
    gh = C::kA0Hi;
    gl = C::kA0Lo + u * horner(C::kA, u);
  } else if (a < T(2.5)) {
    const T u = a - T(2);
    gh = C::kB0Hi;
    gl = C::kB0Lo + u * horner(C::kB, u);
  } else if (a < C::kTailStart) {  // [2.5, 4): double only (float starts the tail at 2.5)
    if constexpr (std::is_same_v<T, double>) {
      const T u = a - T(3.25);
      gh = C::kC0Hi;
      gl = C::kC0Lo + u * horner(C::kC, u);
    }
  } else {
    // G = K(1/a^2) / a; the division by a comes last, on the pair.
    const T w = T(1) / a;
    const T s = w * w;
    gh = C::kK0Hi;
    gl = C::kK0Lo + s * horner(C::kK, s);
    tail = true;
  }
  T p;
  T pe;
  two_prod(eh, gh, &p, &pe);
  const T rest = pe + (eh * gl + et * (gh + gl));
  T v;
  if (!tail) {
    v = p + rest;
  } else {
    // (p + rest) / a with one rounding: q = p / a, then the exact residual
    // p - q a (Dekker) plus rest, divided by a, corrects q.
    const T q = p / a;
    T qa;
    T qae;
    two_prod(q, a, &qa, &qae);
    v = q + (((p - qa) - qae) + rest) / a;
  }
  return scale(v, k);
}

}  // namespace detail

/// Error function, 2/sqrt(pi) times the integral of e^(-t^2) from 0 to x.
/// Special values: NaN -> NaN, +-inf -> +-1, +-0 -> +-0.
template <class T>
inline T derf(T x) {
  static_assert(detail::kIsSupported<T>, "mptrack::dmath supports float and double only");
  using C = detail::ErfCoeffs<T>;
  if (detail::is_nan(x)) {
    return detail::quiet_nan<T>();
  }
  const T a = detail::abs_value(x);
  if (a < T(0.75)) {
    return x + x * detail::horner(C::kY, x * x);
  }
  const T r = a < C::kErfOne ? T(1) - detail::erfc_kernel(a) : T(1);
  return detail::copy_sign(r, x);
}

/// Complementary error function 1 - erf x, accurate also where erf x ~ 1.
/// Special values: NaN -> NaN, +inf -> +0, -inf -> 2, +-0 -> 1; underflows
/// to +0 for x >= kErfcZero (27.3 double, 10.1 float).
template <class T>
inline T derfc(T x) {
  static_assert(detail::kIsSupported<T>, "mptrack::dmath supports float and double only");
  using C = detail::ErfCoeffs<T>;
  if (detail::is_nan(x)) {
    return detail::quiet_nan<T>();
  }
  const T a = detail::abs_value(x);
  if (a < T(0.75)) {
    const T xy = x * detail::horner(C::kY, x * x);
    if (x < T(0.25)) {
      return T(1) - (x + xy);
    }
    return T(0.5) - ((x - T(0.5)) + xy);
  }
  if (x > T(0)) {
    return x < C::kErfcZero ? detail::erfc_kernel(x) : T(0);
  }
  return a < C::kErfOne ? T(2) - detail::erfc_kernel(a) : T(2);
}

}  // namespace mptrack::dmath
