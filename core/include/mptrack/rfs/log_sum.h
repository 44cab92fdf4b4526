// Log-domain sums in a fixed order, shared by the GM-PHD, GM-CPHD and
// CBMeMBer updates (their weights span e^-100..e^100, beyond float).
#pragma once

#include "mptrack/math/detmath.h"

namespace mptrack::rfs {

/// Online log-sum-exp in a fixed order: add() terms one by one, value() = ln sum e^x.
template <class T>
struct LogSum {
  T max = T(0);
  T sum = T(0);  ///< sum of e^(x - max)
  bool any = false;

  void add(T x) {
    if (!any) {
      max = x;
      sum = T(1);
      any = true;
    } else if (x > max) {
      sum = sum * dmath::dexp(max - x) + T(1);
      max = x;
    } else {
      sum += dmath::dexp(x - max);
    }
  }
  /// ln of the sum; -huge when empty.
  T value() const { return any ? max + dmath::dlog(sum) : T(-1e30); }
};

/// ln(e^a + e^b).
template <class T>
T log_add(T a, T b) {
  const T hi = a > b ? a : b;
  const T lo = a > b ? b : a;
  if (lo - hi < T(-60)) return hi;
  return hi + dmath::dlog1p(dmath::dexp(lo - hi));
}

}  // namespace mptrack::rfs
