// Status codes returned by every core entry point that can fail.
//
// Errors are values (README.md §Conventions a firmware engineer can rely on): no
// exceptions, no errno.
// The enum itself is [[nodiscard]], so ignoring a returned Status is a
// compiler warning (an error under -Werror) at every call site.
#pragma once

#include <cstdint>

namespace mptrack {

enum class [[nodiscard]] Status : std::uint8_t {
  kOk = 0,
  kInvalidArgument,   ///< a parameter or config value is out of its documented range
  kInvalidInput,      ///< input data rejected (NaN/Inf, out of region, bad amplitude)
  kCapacityExceeded,  ///< a compile-time cap was hit; see the call's overflow policy
  kOutOfOrder,        ///< timestamp not after the previous one
  kNumericalError,    ///< a factorisation failed (non-SPD) or a value became non-finite
  kNotInitialized,    ///< init() has not succeeded yet
  kBufferFull,        ///< ring buffer full: the item was not stored (and was counted)
  kBufferEmpty,       ///< ring buffer empty: nothing to read
  kPartial,           ///< the call succeeded but some input items were rejected (see counters)
};

/// Short stable name for logs and reports ("ok", "invalid_argument", ...).
constexpr const char* to_string(Status s) {
  switch (s) {
    case Status::kOk: return "ok";
    case Status::kInvalidArgument: return "invalid_argument";
    case Status::kInvalidInput: return "invalid_input";
    case Status::kCapacityExceeded: return "capacity_exceeded";
    case Status::kOutOfOrder: return "out_of_order";
    case Status::kNumericalError: return "numerical_error";
    case Status::kNotInitialized: return "not_initialized";
    case Status::kBufferFull: return "buffer_full";
    case Status::kBufferEmpty: return "buffer_empty";
    case Status::kPartial: return "partial";
  }
  return "unknown";
}

/// True for kOk only. kPartial is a success with losses and must be looked at.
constexpr bool ok(Status s) { return s == Status::kOk; }

/// Keeps the first failure when a function chains several checks.
constexpr Status first_error(Status a, Status b) { return a != Status::kOk ? a : b; }

}  // namespace mptrack

/// Early return for status chains: MPTRACK_TRY(validate(p));
#define MPTRACK_TRY(expr)                                   \
  do {                                                      \
    const ::mptrack::Status mptrack_try_status_ = (expr);   \
    if (mptrack_try_status_ != ::mptrack::Status::kOk) {    \
      return mptrack_try_status_;                           \
    }                                                       \
  } while (false)
