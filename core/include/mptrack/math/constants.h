// Mathematical constants for float and double, and the IEEE-754 building
// blocks (bit access, exact power-of-two scaling, error-free transformations)
// that the deterministic elementary functions in this directory share.
//
// Every constant is written as a hexadecimal literal, rounded to nearest from
// a 100-digit value (mpmath), so the bits are fixed by the source text and not
// by a compiler's decimal conversion or a platform's <cmath> macros. Constants
// with a _hi/_lo split live next to the kernel that needs them.
//
// The helpers in `detail` use only integer operations, + - * and comparisons.
// Under -ffp-contract=off (mptrack::deterministic) each of them gives the same
// bits on x86-64 SSE2, aarch64, armhf VFPv4 and Cortex-M7.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace mptrack::dmath {

namespace detail {

/// True for the two supported types. Every public function asserts it, so
/// dexp<long double> fails at compile time with a readable message.
template <class T>
inline constexpr bool kIsSupported = std::is_same_v<T, float> || std::is_same_v<T, double>;

/// Chooses the float or the double spelling of a constant. Rejects any other T
/// (long double is banned in core: its format differs between targets).
template <class T>
constexpr T pick(float f, double d) {
  static_assert(kIsSupported<T>, "mptrack::dmath supports float and double only");
  if constexpr (std::is_same_v<T, float>) {
    return f;
  } else {
    return d;
  }
}

}  // namespace detail

/// pi [rad]
template <class T>
inline constexpr T kPi = detail::pick<T>(0x1.921fb6p+1f, 0x1.921fb54442d18p+1);
/// 2 pi [rad]
template <class T>
inline constexpr T kTwoPi = detail::pick<T>(0x1.921fb6p+2f, 0x1.921fb54442d18p+2);
/// pi / 2 [rad]
template <class T>
inline constexpr T kHalfPi = detail::pick<T>(0x1.921fb6p+0f, 0x1.921fb54442d18p+0);
/// pi / 4 [rad]
template <class T>
inline constexpr T kQuarterPi = detail::pick<T>(0x1.921fb6p-1f, 0x1.921fb54442d18p-1);
/// 1 / pi [1/rad]
template <class T>
inline constexpr T kInvPi = detail::pick<T>(0x1.45f306p-2f, 0x1.45f306dc9c883p-2);
/// 2 / pi [1/rad]
template <class T>
inline constexpr T kTwoOverPi = detail::pick<T>(0x1.45f306p-1f, 0x1.45f306dc9c883p-1);
/// pi / 180: multiply degrees by this to get radians.
template <class T>
inline constexpr T kDegToRad = detail::pick<T>(0x1.1df46ap-6f, 0x1.1df46a2529d39p-6);
/// 180 / pi: multiply radians by this to get degrees.
template <class T>
inline constexpr T kRadToDeg = detail::pick<T>(0x1.ca5dc2p+5f, 0x1.ca5dc1a63c1f8p+5);
/// e, Euler's number
template <class T>
inline constexpr T kE = detail::pick<T>(0x1.5bf0a8p+1f, 0x1.5bf0a8b145769p+1);
/// natural logarithm of 2
template <class T>
inline constexpr T kLn2 = detail::pick<T>(0x1.62e430p-1f, 0x1.62e42fefa39efp-1);
/// natural logarithm of 10
template <class T>
inline constexpr T kLn10 = detail::pick<T>(0x1.26bb1cp+1f, 0x1.26bb1bbb55516p+1);
/// 1 / ln 2 (base-2 logarithm of e)
template <class T>
inline constexpr T kLog2E = detail::pick<T>(0x1.715476p+0f, 0x1.71547652b82fep+0);
/// square root of 2
template <class T>
inline constexpr T kSqrt2 = detail::pick<T>(0x1.6a09e6p+0f, 0x1.6a09e667f3bcdp+0);
/// 1 / sqrt 2
template <class T>
inline constexpr T kInvSqrt2 = detail::pick<T>(0x1.6a09e6p-1f, 0x1.6a09e667f3bcdp-1);
/// square root of pi
template <class T>
inline constexpr T kSqrtPi = detail::pick<T>(0x1.c5bf8ap+0f, 0x1.c5bf891b4ef6bp+0);
/// 2 / sqrt pi (derivative of erf at 0)
template <class T>
inline constexpr T kTwoOverSqrtPi = detail::pick<T>(0x1.20dd76p+0f, 0x1.20dd750429b6dp+0);
/// Euler-Mascheroni constant gamma = -digamma at 1
template <class T>
inline constexpr T kEulerGamma = detail::pick<T>(0x1.2788d0p-1f, 0x1.2788cfc6fb619p-1);
/// 0.5 ln(2 pi), the constant of Stirling's formula
template <class T>
inline constexpr T kHalfLnTwoPi = detail::pick<T>(0x1.d67f1cp-1f, 0x1.d67f1c864beb5p-1);
/// ln(2 pi), the normalising constant of a bivariate Gaussian density
template <class T>
inline constexpr T kLnTwoPi = detail::pick<T>(0x1.d67f1cp+0f, 0x1.d67f1c864beb5p+0);

namespace detail {

/// Layout of the IEEE-754 binary32/binary64 formats.
template <class T>
struct FpTraits;

template <>
struct FpTraits<float> {
  using Bits = std::uint32_t;
  static constexpr int kMantissaBits = 23;  ///< stored fraction bits
  static constexpr int kExponentBias = 127;
  static constexpr int kMaxExponent = 127;   ///< of the largest finite value
  static constexpr int kMinExponent = -126;  ///< of the smallest normal value
  static constexpr Bits kSignMask = 0x80000000u;
  static constexpr Bits kExponentMask = 0x7f800000u;
  static constexpr Bits kMantissaMask = 0x007fffffu;
  /// 2^12 + 1: Veltkamp split constant, cuts a float into two 12-bit halves.
  static constexpr float kSplitter = 4097.0f;
};

template <>
struct FpTraits<double> {
  using Bits = std::uint64_t;
  static constexpr int kMantissaBits = 52;
  static constexpr int kExponentBias = 1023;
  static constexpr int kMaxExponent = 1023;
  static constexpr int kMinExponent = -1022;
  static constexpr Bits kSignMask = 0x8000000000000000u;
  static constexpr Bits kExponentMask = 0x7ff0000000000000u;
  static constexpr Bits kMantissaMask = 0x000fffffffffffffu;
  /// 2^27 + 1: Veltkamp split constant, cuts a double into two 26-bit halves.
  static constexpr double kSplitter = 134217729.0;
};

/// Raw bit pattern of x (memcpy is the defined way to type-pun in C++17).
template <class T>
inline typename FpTraits<T>::Bits to_bits(T x) {
  typename FpTraits<T>::Bits u;
  std::memcpy(&u, &x, sizeof u);
  return u;
}

/// Value with bit pattern u.
template <class T>
inline T from_bits(typename FpTraits<T>::Bits u) {
  T x;
  std::memcpy(&x, &u, sizeof x);
  return x;
}

/// Magnitude bits: the pattern with the sign cleared. For finite and infinite
/// values these compare as unsigned integers in the same order as |x|.
template <class T>
inline typename FpTraits<T>::Bits abs_bits(T x) {
  return to_bits(x) & ~FpTraits<T>::kSignMask;
}

template <class T>
inline bool is_nan(T x) {
  return abs_bits(x) > FpTraits<T>::kExponentMask;
}

template <class T>
inline bool is_inf(T x) {
  return abs_bits(x) == FpTraits<T>::kExponentMask;
}

/// True for +0 and -0.
template <class T>
inline bool is_zero(T x) {
  return abs_bits(x) == 0;
}

/// True when the sign bit is set (also for -0 and negative NaNs).
template <class T>
inline bool sign_bit(T x) {
  return (to_bits(x) & FpTraits<T>::kSignMask) != 0;
}

/// |x| by clearing the sign bit (no libm, no rounding).
template <class T>
inline T abs_value(T x) {
  return from_bits<T>(abs_bits(x));
}

/// x with the sign bit of s.
template <class T>
inline T copy_sign(T x, T s) {
  return from_bits<T>(abs_bits(x) | (to_bits(s) & FpTraits<T>::kSignMask));
}

/// Quiet NaN with a fixed payload, so NaN results have the same bits everywhere.
template <class T>
inline T quiet_nan() {
  using Tr = FpTraits<T>;
  return from_bits<T>(Tr::kExponentMask | (typename Tr::Bits{1} << (Tr::kMantissaBits - 1)));
}

template <class T>
inline T infinity() {
  return from_bits<T>(FpTraits<T>::kExponentMask);
}

/// 2^k for k in [kMinExponent, kMaxExponent], built from its exponent field.
template <class T>
inline T pow2(int k) {
  using Tr = FpTraits<T>;
  using Bits = typename Tr::Bits;
  return from_bits<T>(static_cast<Bits>(k + Tr::kExponentBias) << Tr::kMantissaBits);
}

/// x * 2^k for any int k, rounded once (musl scalbn). Overflows to +-inf and
/// underflows through the subnormals like a single multiplication would: the
/// extra factor 2^(mantissa bits + 1) keeps the last product the only inexact
/// one, so there is no double rounding below the normal range.
template <class T>
inline T scale(T x, int k) {
  using Tr = FpTraits<T>;
  constexpr int kMax = Tr::kMaxExponent;
  constexpr int kMin = Tr::kMinExponent;
  constexpr int kGuard = Tr::kMantissaBits + 1;
  if (k > kMax) {
    x *= pow2<T>(kMax);
    k -= kMax;
    if (k > kMax) {
      x *= pow2<T>(kMax);
      k -= kMax;
      if (k > kMax) {
        k = kMax;
      }
    }
  } else if (k < kMin) {
    x *= pow2<T>(kMin + kGuard);
    k -= kMin + kGuard;
    if (k < kMin) {
      x *= pow2<T>(kMin + kGuard);
      k -= kMin + kGuard;
      if (k < kMin) {
        k = kMin;
      }
    }
  }
  return x * pow2<T>(k);
}

/// Splits a positive finite x into m * 2^k with m in [1, 2). Subnormals are
/// normalised first. Returns m; k is written to *k.
template <class T>
inline T split_exponent(T x, int* k) {
  using Tr = FpTraits<T>;
  using Bits = typename Tr::Bits;
  int extra = 0;
  if (abs_bits(x) < (Bits{1} << Tr::kMantissaBits)) {  // subnormal
    x *= pow2<T>(Tr::kMantissaBits + 2);
    extra = Tr::kMantissaBits + 2;
  }
  const Bits u = to_bits(x);
  *k = static_cast<int>(u >> Tr::kMantissaBits) - Tr::kExponentBias - extra;
  return from_bits<T>((u & Tr::kMantissaMask) | (static_cast<Bits>(Tr::kExponentBias) << Tr::kMantissaBits));
}

/// Rounds x to the nearest integer, ties away from zero, for |x| < 2^30.
/// (Conversion to int truncates in C++, identically on every target.)
template <class T>
inline int round_to_int(T x) {
  return static_cast<int>(x < T(0) ? x - T(0.5) : x + T(0.5));
}

/// Error-free sum (Knuth TwoSum): s + e == a + b exactly, s = fl(a + b).
template <class T>
inline void two_sum(T a, T b, T* s, T* e) {
  const T sum = a + b;
  const T bv = sum - a;
  const T av = sum - bv;
  *s = sum;
  *e = (a - av) + (b - bv);
}

/// Error-free sum for |a| >= |b| (Dekker FastTwoSum).
template <class T>
inline void fast_two_sum(T a, T b, T* s, T* e) {
  const T sum = a + b;
  *s = sum;
  *e = b - (sum - a);
}

/// Veltkamp split: a == hi + lo with each half holding at most half of the
/// significand bits, so products of halves are exact.
template <class T>
inline void split(T a, T* hi, T* lo) {
  const T c = FpTraits<T>::kSplitter * a;
  const T h = c - (c - a);
  *hi = h;
  *lo = a - h;
}

/// Error-free product without FMA (Dekker TwoProduct): p + e == a * b exactly,
/// p = fl(a * b), provided no overflow or underflow occurs.
template <class T>
inline void two_prod(T a, T b, T* p, T* e) {
  T ah;
  T al;
  T bh;
  T bl;
  split(a, &ah, &al);
  split(b, &bh, &bl);
  const T prod = a * b;
  *p = prod;
  *e = ((ah * bh - prod) + ah * bl + al * bh) + al * bl;
}

/// c[0] + c[1] x + ... + c[N-1] x^(N-1) by Horner's rule, highest degree
/// first. The order is fixed by the loop, and without contraction every step
/// is one rounded multiply and one rounded add on every target.
template <class T, std::size_t N>
inline T horner(const T (&c)[N], T x) {
  T p = c[N - 1];
  for (std::size_t i = N - 1; i > 0; --i) {
    p = p * x + c[i - 1];
  }
  return p;
}

}  // namespace detail
}  // namespace mptrack::dmath
