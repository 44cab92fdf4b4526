// Accuracy of the deterministic elementary functions (mptrack/math/detmath.h)
// against the host's long double libm (x86-64: 64-bit significand, so the
// reference is ~2^11 times finer than double). HOST_ONLY: long double has
// another format on aarch64 and armhf, and this test only has to run once.
//
// Each test case sweeps one function in float and double over its documented
// domain (dense linear grids plus geometric ladders, with a fixed
// pseudo-random jitter so that grid points do not line up with the reduction
// intervals) and checks the maximum error in ulps of the result against the
// bound in detmath.h. The measured maxima are printed with MESSAGE, which is
// the table in detmath.h.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>

#include "mptrack/math/detmath.h"

namespace dm = mptrack::dmath;

static_assert(std::numeric_limits<long double>::digits >= 64,
              "the reference needs x87 extended precision (x86-64 host)");

namespace {

constexpr long kPoints = 1L << 17;  // per sweep and type

/// ulp of `ref` in the format of T (subnormal results: the subnormal spacing).
template <class T>
long double ulp_in(long double ref) {
  constexpr int kDigits = std::numeric_limits<T>::digits;
  constexpr int kMinExp = std::numeric_limits<T>::min_exponent;
  int e = kMinExp;
  if (ref != 0.0L) {
    std::frexp(ref, &e);
    if (e < kMinExp) {
      e = kMinExp;
    }
  }
  return std::ldexp(1.0L, e - kDigits);
}

/// Error of `got` in ulps of the exact value `ref`. A reference beyond the
/// range of T must give the same infinity; NaN must match NaN.
template <class T>
long double ulp_error(T got, long double ref) {
  const long double g = static_cast<long double>(got);
  if (std::isnan(ref) || std::isnan(g)) {
    return std::isnan(ref) && std::isnan(g) ? 0.0L : 1e30L;
  }
  const long double max = static_cast<long double>(std::numeric_limits<T>::max());
  if (std::fabs(ref) > max || std::isinf(g)) {
    return (std::isinf(g) && std::signbit(g) == std::signbit(ref) && std::fabs(ref) > max) ? 0.0L : 1e30L;
  }
  return std::fabs(g - ref) / ulp_in<T>(ref);
}

/// Absolute error in units of ulp(1) of T (used near zeros of the function).
template <class T>
long double abs_error(T got, long double ref) {
  return std::fabs(static_cast<long double>(got) - ref) /
         static_cast<long double>(std::numeric_limits<T>::epsilon());
}

/// Deterministic jitter in [0, 1) (64-bit LCG, Knuth's MMIX constants).
class Jitter {
 public:
  long double next() {
    state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<long double>(state_ >> 11) * 0x1p-53L;
  }

 private:
  std::uint64_t state_ = 0x9e3779b97f4a7c15ULL;
};

struct Worst {
  long double err = 0.0L;
  long double at = 0.0L;
  void take(long double e, long double x) {
    if (e > err) {
      err = e;
      at = x;
    }
  }
};

/// Arguments: n points, linear in [lo, hi] (geometric = false) or geometric
/// between lo and hi of the same sign, each moved by a random fraction of one
/// step, then rounded to T.
template <class T, class Visit>
void sweep(long double lo, long double hi, bool geometric, long n, Visit visit) {
  Jitter jitter;
  for (long i = 0; i < n; ++i) {
    const long double t = (static_cast<long double>(i) + jitter.next()) / static_cast<long double>(n);
    const long double x = geometric ? lo * std::pow(hi / lo, t) : lo + (hi - lo) * t;
    visit(static_cast<T>(x));
  }
  visit(static_cast<T>(lo));
  visit(static_cast<T>(hi));
}

template <class T>
const char* type_name() {
  return sizeof(T) == sizeof(float) ? "float " : "double";
}

template <class T>
void report(const char* fn, const char* domain, const Worst& w, long double bound, const char* unit = "ulp") {
  char line[200];
  std::snprintf(line, sizeof line, "%-9s %s %-34s max %6.3Lf %s at x = %.17Lg (bound %.2Lf)", fn,
                type_name<T>(), domain, w.err, unit, w.at, bound);
  MESSAGE(line);
  CHECK(w.err <= bound);
}

/// Max ulp error of f against ref over one sweep.
template <class T, class F, class R>
Worst measure(F f, R ref, long double lo, long double hi, bool geometric, long n = kPoints) {
  Worst w;
  sweep<T>(lo, hi, geometric, n, [&](T x) {
    w.take(ulp_error<T>(f(x), ref(static_cast<long double>(x))), static_cast<long double>(x));
  });
  return w;
}

Worst worse(Worst a, const Worst& b) {
  a.take(b.err, b.at);
  return a;
}

/// Digamma in long double: recurrence up to x >= 20, then the asymptotic
/// series (error < 1e-21 relative there). It cancels near the root x0, which
/// is why that window is measured in absolute error.
long double ref_digamma(long double x) {
  long double acc = 0.0L;
  while (x < 20.0L) {
    acc -= 1.0L / x;
    x += 1.0L;
  }
  const long double z = 1.0L / (x * x);
  const long double series =
      z * (1.0L / 12 - z * (1.0L / 120 - z * (1.0L / 252 - z * (1.0L / 240 -
      z * (1.0L / 132 - z * (691.0L / 32760 - z * (1.0L / 12)))))));
  return acc + std::log(x) - 0.5L / x - series;
}

constexpr long double kDigammaRoot = 1.461632144968362341262659542325721325L;

}  // namespace

TEST_CASE_TEMPLATE("dexp is within 1 ulp on its whole finite range", T, float, double) {
  const long double lo = sizeof(T) == 4 ? -87.0L : -708.0L;
  const long double hi = sizeof(T) == 4 ? 88.0L : 709.0L;
  auto f = [](T x) { return dm::dexp(x); };
  auto ref = [](long double x) { return std::exp(x); };
  const Worst w = worse(measure<T>(f, ref, lo, hi, false), measure<T>(f, ref, -1.0L, 1.0L, false));
  report<T>("dexp", sizeof(T) == 4 ? "[-87, 88]" : "[-708, 709]", w, 1.0L);
}

TEST_CASE_TEMPLATE("dexpm1 is within 1.5 ulp, also for tiny arguments", T, float, double) {
  const long double lo = sizeof(T) == 4 ? -87.0L : -708.0L;
  const long double hi = sizeof(T) == 4 ? 88.0L : 709.0L;
  auto f = [](T x) { return dm::dexpm1(x); };
  auto ref = [](long double x) { return std::expm1(x); };
  Worst w = measure<T>(f, ref, lo, hi, false);
  w = worse(w, measure<T>(f, ref, -2.0L, 2.0L, false));
  w = worse(w, measure<T>(f, ref, 1e-30L, 2.0L, true));
  w = worse(w, measure<T>(f, ref, -1e-30L, -2.0L, true));
  report<T>("dexpm1", sizeof(T) == 4 ? "[-87, 88]" : "[-708, 709]", w, 1.5L);
}

TEST_CASE_TEMPLATE("dlog is within 1 ulp from the smallest subnormal to max", T, float, double) {
  auto f = [](T x) { return dm::dlog(x); };
  auto ref = [](long double x) { return std::log(x); };
  const long double lo = static_cast<long double>(std::numeric_limits<T>::denorm_min());
  const long double hi = static_cast<long double>(std::numeric_limits<T>::max());
  const Worst w = worse(measure<T>(f, ref, lo, hi, true), measure<T>(f, ref, 0.5L, 2.0L, false));
  report<T>("dlog", "[denorm_min, max]", w, 1.0L);
}

TEST_CASE_TEMPLATE("dlog1p is within 1 ulp on (-0.99, 1e6]", T, float, double) {
  auto f = [](T x) { return dm::dlog1p(x); };
  auto ref = [](long double x) { return std::log1p(x); };
  Worst w = measure<T>(f, ref, -0.99L, 1e6L, false);
  w = worse(w, measure<T>(f, ref, -0.99L, 2.0L, false));
  w = worse(w, measure<T>(f, ref, 1e-30L, 1e6L, true));
  w = worse(w, measure<T>(f, ref, -1e-30L, -0.99L, true));
  report<T>("dlog1p", "(-0.99, 1e6]", w, 1.0L);
}

TEST_CASE_TEMPLATE("dsin and dcos are within 1 ulp for |x| <= 1e5", T, float, double) {
  auto fs = [](T x) { return dm::dsin(x); };
  auto rs = [](long double x) { return std::sin(x); };
  auto fc = [](T x) { return dm::dcos(x); };
  auto rc = [](long double x) { return std::cos(x); };
  Worst ws = measure<T>(fs, rs, -10.0L, 10.0L, false);
  ws = worse(ws, measure<T>(fs, rs, -1e5L, 1e5L, false));
  ws = worse(ws, measure<T>(fs, rs, 1e-30L, 1e5L, true));
  ws = worse(ws, measure<T>(fs, rs, -1e-30L, -1e5L, true));
  Worst wc = measure<T>(fc, rc, -10.0L, 10.0L, false);
  wc = worse(wc, measure<T>(fc, rc, -1e5L, 1e5L, false));
  wc = worse(wc, measure<T>(fc, rc, 1e-30L, 1e5L, true));
  wc = worse(wc, measure<T>(fc, rc, -1e-30L, -1e5L, true));
  report<T>("dsin", "|x| <= 1e5", ws, 1.0L);
  report<T>("dcos", "|x| <= 1e5", wc, 1.0L);
}

TEST_CASE_TEMPLATE("dsin and dcos stay accurate next to multiples of pi/2", T, float, double) {
  // The hardest arguments for the reduction: the representable neighbours of
  // k pi/2, where sin or cos is tiny and its relative error exposes any loss.
  Worst w;
  for (int k = 1; k <= 60000; k += (k < 100 ? 1 : 97)) {
    const long double target = static_cast<long double>(k) * 1.5707963267948966192313216916397514L;
    T x = static_cast<T>(target);
    for (int step = 0; step < 3; ++step) {
      w.take(ulp_error<T>(dm::dsin(x), std::sin(static_cast<long double>(x))), static_cast<long double>(x));
      w.take(ulp_error<T>(dm::dcos(x), std::cos(static_cast<long double>(x))), static_cast<long double>(x));
      x = std::nextafter(x, std::numeric_limits<T>::infinity());
    }
  }
  report<T>("dsin/dcos", "x next to k pi/2, k <= 60000", w, 1.0L);
}

TEST_CASE_TEMPLATE("datan is within 1.5 ulp for all x", T, float, double) {
  auto f = [](T x) { return dm::datan(x); };
  auto ref = [](long double x) { return std::atan(x); };
  Worst w = measure<T>(f, ref, -4.0L, 4.0L, false);
  w = worse(w, measure<T>(f, ref, 1e-30L, 1e30L, true));
  w = worse(w, measure<T>(f, ref, -1e-30L, -1e30L, true));
  report<T>("datan", "all x", w, 1.5L);
}

TEST_CASE_TEMPLATE("datan2 is within 2 ulp in all four quadrants", T, float, double) {
  Worst w;
  Jitter jitter;
  for (long i = 0; i < kPoints; ++i) {
    // Angles all around the circle, on radii from 1e-20 to 1e20.
    const long double angle = -3.2L + 6.4L * (static_cast<long double>(i) + jitter.next()) / kPoints;
    const long double radius = std::pow(10.0L, static_cast<long double>(i % 41 - 20));
    const T y = static_cast<T>(radius * std::sin(angle));
    const T x = static_cast<T>(radius * std::cos(angle));
    w.take(ulp_error<T>(dm::datan2(y, x), std::atan2(static_cast<long double>(y), static_cast<long double>(x))),
           angle);
  }
  for (long i = 0; i < kPoints / 4; ++i) {
    // Extreme ratios: |y/x| from 1e-30 to 1e30 with all sign combinations.
    const long double ratio = std::pow(10.0L, -30.0L + 60.0L * (static_cast<long double>(i) + jitter.next()) /
                                                         (kPoints / 4));
    const T y = static_cast<T>((i & 1) ? -ratio : ratio);
    const T x = static_cast<T>((i & 2) ? -1.0L : 1.0L);
    w.take(ulp_error<T>(dm::datan2(y, x), std::atan2(static_cast<long double>(y), static_cast<long double>(x))),
           ratio);
  }
  report<T>("datan2", "all quadrants (x = angle / ratio)", w, 2.0L);
}

TEST_CASE_TEMPLATE("dlgamma is within 2 ulp on [1e-6, 1e6]", T, float, double) {
  auto f = [](T x) { return dm::dlgamma(x); };
  auto ref = [](long double x) { return std::lgamma(x); };
  // Relative error away from the zeros at 1 and 2; absolute error near them.
  Worst rel;
  Worst abs;
  auto visit = [&](T x) {
    const long double xl = static_cast<long double>(x);
    const T got = f(x);
    if (std::fabs(xl - 1.0L) < 0.0625L || std::fabs(xl - 2.0L) < 0.0625L) {
      abs.take(abs_error<T>(got, ref(xl)), xl);
    } else {
      rel.take(ulp_error<T>(got, ref(xl)), xl);
    }
  };
  sweep<T>(1e-6L, 1e6L, true, kPoints, visit);
  sweep<T>(0.01L, 10.0L, false, kPoints, visit);
  report<T>("dlgamma", "[1e-6, 1e6] minus |x-1|,|x-2| < 1/16", rel, 2.0L);
  report<T>("dlgamma", "|x-1|, |x-2| < 1/16 (absolute)", abs, 0.5L, "ulp(1)");
}

TEST_CASE_TEMPLATE("ddigamma is within 2 ulp on [1e-6, 1e6]", T, float, double) {
  auto f = [](T x) { return dm::ddigamma(x); };
  Worst rel;
  Worst abs;
  auto visit = [&](T x) {
    const long double xl = static_cast<long double>(x);
    const T got = f(x);
    if (std::fabs(xl - kDigammaRoot) < 0.0625L) {
      abs.take(abs_error<T>(got, ref_digamma(xl)), xl);
    } else {
      rel.take(ulp_error<T>(got, ref_digamma(xl)), xl);
    }
  };
  sweep<T>(1e-6L, 1e6L, true, kPoints, visit);
  sweep<T>(0.01L, 10.0L, false, kPoints, visit);
  report<T>("ddigamma", "[1e-6, 1e6] minus |x-x0| < 1/16", rel, 2.0L);
  report<T>("ddigamma", "|x-x0| < 1/16 (absolute)", abs, 0.5L, "ulp(1)");
}

TEST_CASE_TEMPLATE("derf is within 1 ulp on [-10, 10]", T, float, double) {
  auto f = [](T x) { return dm::derf(x); };
  auto ref = [](long double x) { return std::erf(x); };
  Worst w = measure<T>(f, ref, -10.0L, 10.0L, false);
  w = worse(w, measure<T>(f, ref, 1e-30L, 10.0L, true));
  w = worse(w, measure<T>(f, ref, -1e-30L, -10.0L, true));
  report<T>("derf", "[-10, 10]", w, 1.0L);
}

TEST_CASE_TEMPLATE("derfc is within 1.5 ulp down to its underflow", T, float, double) {
  auto f = [](T x) { return dm::derfc(x); };
  auto ref = [](long double x) { return std::erfc(x); };
  // float erfc is subnormal beyond 9.19, double beyond 26.5: stop before.
  const long double top = sizeof(T) == 4 ? 9.1L : 26.5L;
  Worst w = measure<T>(f, ref, -10.0L, 10.0L < top ? 10.0L : top, false);
  w = worse(w, measure<T>(f, ref, 0.5L, top, false));
  w = worse(w, measure<T>(f, ref, 1e-30L, 0.75L, true));
  report<T>("derfc", sizeof(T) == 4 ? "[-10, 9.1]" : "[-10, 26.5]", w, 1.5L);
}
