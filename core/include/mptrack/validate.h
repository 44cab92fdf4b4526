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

/// What a check found: the status, and for the value checks below the value
/// and the bounds it was held to, so a harness can print
/// "window_length = 100: must be <= 7 (Caps::kMaxWindow)" (ParamError).
/// Converts to Status, so existing callers read it as one.
struct [[nodiscard]] CheckResult {
  Status status = Status::kOk;
  bool has_value = false;  ///< false: a plain condition (check()), no figures
  double value = 0.0;      ///< the value checked (converted to double: exact for float and int)
  double lo = 0.0, hi = 0.0;
  bool has_lo = false, has_hi = false;
  bool lo_open = false, hi_open = false;  ///< strict bound (> lo, < hi)
  const char* limit = "";  ///< the constant or field a bound comes from, e.g. "Caps::kMaxWindow"
  constexpr operator Status() const { return status; }  // NOLINT: reads as a Status
  friend constexpr bool operator==(const CheckResult& r, Status s) { return r.status == s; }
  friend constexpr bool operator!=(const CheckResult& r, Status s) { return r.status != s; }
};

/// x checked against [lo, hi] (each bound optional, inclusive or strict)
/// and finite. Compared in double: exact for float, double and integers
/// below 2^53, so a check means the same for every T.
constexpr CheckResult check_interval(double x, bool has_lo, double lo, bool lo_open, bool has_hi, double hi,
                                     bool hi_open, const char* limit = "") {
  bool ok = is_finite(x);
  if (has_lo) ok = ok && (lo_open ? x > lo : !(x < lo));
  if (has_hi) ok = ok && (hi_open ? x < hi : !(x > hi));
  CheckResult r;
  r.status = ok ? Status::kOk : Status::kInvalidArgument;
  r.has_value = true;
  r.value = x;
  r.lo = lo;
  r.hi = hi;
  r.has_lo = has_lo;
  r.has_hi = has_hi;
  r.lo_open = lo_open;
  r.hi_open = hi_open;
  r.limit = limit;
  return r;
}

/// lo <= x <= hi and finite.
template <class X, class L, class H>
constexpr CheckResult check_range(X x, L lo, H hi, const char* limit = "") {
  return check_interval(static_cast<double>(x), true, static_cast<double>(lo), false, true,
                        static_cast<double>(hi), false, limit);
}

/// lo < x <= hi and finite (e.g. a period: > 0, at most an hour).
template <class X, class L, class H>
constexpr CheckResult check_range_above(X x, L lo, H hi, const char* limit = "") {
  return check_interval(static_cast<double>(x), true, static_cast<double>(lo), true, true,
                        static_cast<double>(hi), false, limit);
}

/// lo <= x < hi and finite (e.g. a damping factor in [0, 1)).
template <class X, class L, class H>
constexpr CheckResult check_range_below(X x, L lo, H hi, const char* limit = "") {
  return check_interval(static_cast<double>(x), true, static_cast<double>(lo), false, true,
                        static_cast<double>(hi), true, limit);
}

/// x > 0 and finite.
template <class X>
constexpr CheckResult check_positive(X x) {
  return check_interval(static_cast<double>(x), true, 0.0, true, false, 0.0, false);
}

/// 0 < p < 1 (a probability that must not be degenerate).
template <class X>
constexpr CheckResult check_open_probability(X p) {
  return check_interval(static_cast<double>(p), true, 0.0, true, true, 1.0, true);
}

/// x <= hi (a cap; `limit` names it, e.g. "Caps::kMaxWindow").
template <class X, class H>
constexpr CheckResult check_at_most(X x, H hi, const char* limit = "") {
  return check_interval(static_cast<double>(x), false, 0.0, false, true, static_cast<double>(hi), false, limit);
}

/// x >= lo.
template <class X, class L>
constexpr CheckResult check_at_least(X x, L lo, const char* limit = "") {
  return check_interval(static_cast<double>(x), true, static_cast<double>(lo), false, false, 0.0, false, limit);
}

/// x > lo (e.g. a maximum above its minimum; `limit` names the other field).
template <class X, class L>
constexpr CheckResult check_above(X x, L lo, const char* limit = "") {
  return check_interval(static_cast<double>(x), true, static_cast<double>(lo), true, false, 0.0, false, limit);
}

/// A condition that must hold (no figures to report: ParamError::rule says which).
/// A radar carrier frequency f_c [Hz], 1 MHz (HF) to 10 THz. The bounds are
/// physical, not numerical comfort: with f_c = 1e-40 Hz, lambda = c / f_c and
/// every Doppler velocity overflowed to +-Inf in the front end's detections
/// (docs/reliability.md F15).
inline constexpr double kMinCarrierHz = 1e6;
inline constexpr double kMaxCarrierHz = 1e13;
template <class X>
constexpr CheckResult check_carrier_hz(X f) {
  return check_range(f, kMinCarrierHz, kMaxCarrierHz);
}

constexpr CheckResult check(bool condition) {
  CheckResult r;
  r.status = condition ? Status::kOk : Status::kInvalidArgument;
  return r;
}

}  // namespace mptrack

namespace mptrack {

/// Where a Params validation failed: the field, the rule it broke and,
/// for the value checks, the value and its bounds (CheckResult), so a
/// harness can say "window_length = 100: must be <= 7 (Caps::kMaxWindow)".
/// The strings point at string literals (static storage): safe to keep.
struct ParamError {
  const char* field = "";  ///< the Params member, e.g. "gate_chi2" or "region.range_max_m"
  const char* rule = "";   ///< the failed check as written in validate()
  CheckResult result;      ///< value and bounds (result.has_value false for a plain check())
};

/// Records field, rule and figures in *where (if not null) and returns kInvalidArgument.
inline Status param_error(ParamError* where, const char* field, const char* rule,
                          const CheckResult& result = CheckResult{}) {
  if (where != nullptr) {
    where->field = field;
    where->rule = rule;
    where->result = result;
  }
  return Status::kInvalidArgument;
}

/// A Status-only check (a nested validate()) as a CheckResult without figures.
constexpr CheckResult to_check_result(const CheckResult& r) { return r; }
constexpr CheckResult to_check_result(Status s) {
  CheckResult r;
  r.status = s;
  return r;
}

}  // namespace mptrack

/// One documented constraint of a validate(): if check (a Status
/// expression) fails, names the field and returns kInvalidArgument.
///   MPTRACK_CHECK_PARAM(where, "gate_chi2", check_positive(p.gate_chi2));
#define MPTRACK_CHECK_PARAM(where, field, check)                        \
  do {                                                                  \
    const ::mptrack::CheckResult mptrack_check_ = ::mptrack::to_check_result(check); \
    if (mptrack_check_.status != ::mptrack::Status::kOk) {              \
      return ::mptrack::param_error((where), (field), #check, mptrack_check_); \
    }                                                                   \
  } while (false)
