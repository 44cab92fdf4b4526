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

namespace mptrack {

/// Where a Params validation failed: the field and the rule it broke, so
/// a harness can say "gate_chi2 = -1: needs check_positive(gate_chi2)".
/// Both point at string literals (static storage): safe to keep.
struct ParamError {
  const char* field = "";  ///< the Params member, e.g. "gate_chi2" or "region.range_max_m"
  const char* rule = "";   ///< the failed check as written in validate()
};

/// Records field and rule in *where (if not null) and returns kInvalidArgument.
inline Status param_error(ParamError* where, const char* field, const char* rule) {
  if (where != nullptr) {
    where->field = field;
    where->rule = rule;
  }
  return Status::kInvalidArgument;
}

}  // namespace mptrack

/// One documented constraint of a validate(): if check (a Status
/// expression) fails, names the field and returns kInvalidArgument.
///   MPTRACK_CHECK_PARAM(where, "gate_chi2", check_positive(p.gate_chi2));
#define MPTRACK_CHECK_PARAM(where, field, check)                        \
  do {                                                                  \
    if ((check) != ::mptrack::Status::kOk) {                            \
      return ::mptrack::param_error((where), (field), #check);          \
    }                                                                   \
  } while (false)
