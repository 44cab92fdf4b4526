// Small helpers for validating run-time Params structs in init().
//
// Each returns kOk or kInvalidArgument, so a validate() reads as a list of
// MPTRACK_TRY(...) lines, one per documented constraint. They classify by
// bit pattern (std::isfinite), which is exact on every target.
#pragma once


#include "mptrack/status.h"

namespace mptrack {

template <class T>
constexpr bool is_finite(T x) {
  return x == x && x - x == x - x;  // false for NaN and +-Inf, no libm needed
}

/// lo <= x <= hi and finite.
template <class T>
Status check_range(T x, T lo, T hi) {
  return (is_finite(x) && !(x < lo) && !(x > hi)) ? Status::kOk : Status::kInvalidArgument;
}

/// x > 0 and finite.
template <class T>
Status check_positive(T x) {
  return (is_finite(x) && x > T(0)) ? Status::kOk : Status::kInvalidArgument;
}

/// 0 < p < 1 (a probability that must not be degenerate).
template <class T>
Status check_open_probability(T p) {
  return (is_finite(p) && p > T(0) && p < T(1)) ? Status::kOk : Status::kInvalidArgument;
}

/// A condition that must hold.
inline Status check(bool condition) { return condition ? Status::kOk : Status::kInvalidArgument; }

}  // namespace mptrack
