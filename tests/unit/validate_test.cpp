#include <doctest/doctest.h>

#include <cstddef>
#include <limits>
#include <string>

#include "mptrack/validate.h"

using mptrack::Status;

TEST_CASE("is_finite rejects NaN and infinities in float and double") {
  CHECK(mptrack::is_finite(1.0f));
  CHECK(mptrack::is_finite(-std::numeric_limits<double>::max()));
  CHECK(mptrack::is_finite(std::numeric_limits<float>::denorm_min()));
  CHECK_FALSE(mptrack::is_finite(std::numeric_limits<float>::quiet_NaN()));
  CHECK_FALSE(mptrack::is_finite(std::numeric_limits<double>::infinity()));
  CHECK_FALSE(mptrack::is_finite(-std::numeric_limits<float>::infinity()));
}

TEST_CASE("check_range is inclusive and rejects NaN") {
  CHECK(mptrack::check_range(0.0, 0.0, 1.0) == Status::kOk);
  CHECK(mptrack::check_range(1.0, 0.0, 1.0) == Status::kOk);
  CHECK(mptrack::check_range(1.0000001, 0.0, 1.0) == Status::kInvalidArgument);
  CHECK(mptrack::check_range(std::numeric_limits<double>::quiet_NaN(), 0.0, 1.0) ==
        Status::kInvalidArgument);
}

TEST_CASE("check_positive and check_open_probability exclude their bounds") {
  CHECK(mptrack::check_positive(1e-30f) == Status::kOk);
  CHECK(mptrack::check_positive(0.0f) == Status::kInvalidArgument);
  CHECK(mptrack::check_positive(std::numeric_limits<float>::infinity()) == Status::kInvalidArgument);
  CHECK(mptrack::check_open_probability(0.5) == Status::kOk);
  CHECK(mptrack::check_open_probability(0.0) == Status::kInvalidArgument);
  CHECK(mptrack::check_open_probability(1.0) == Status::kInvalidArgument);
}

namespace {
mptrack::Status validate_window(std::size_t window, mptrack::ParamError* where) {
  constexpr std::size_t kMaxWindow = 7;
  MPTRACK_CHECK_PARAM(where, "window_length", mptrack::check_at_most(window, kMaxWindow, "Caps::kMaxWindow"));
  MPTRACK_CHECK_PARAM(where, "window_length", mptrack::check(window != 3));
  return Status::kOk;
}
}  // namespace

TEST_CASE("MPTRACK_CHECK_PARAM records field, value, bound and limit name of a refused value") {
  mptrack::ParamError where;
  CHECK(validate_window(7, &where) == Status::kOk);
  CHECK(validate_window(100, &where) == Status::kInvalidArgument);
  CHECK(std::string(where.field) == "window_length");
  CHECK(where.result.has_value);
  CHECK(where.result.value == 100.0);
  CHECK(where.result.has_hi);
  CHECK_FALSE(where.result.has_lo);
  CHECK(where.result.hi == 7.0);
  CHECK(std::string(where.result.limit) == "Caps::kMaxWindow");
  // A plain condition has no figures; the rule text says which.
  CHECK(validate_window(3, &where) == Status::kInvalidArgument);
  CHECK_FALSE(where.result.has_value);
  CHECK(std::string(where.rule) == "mptrack::check(window != 3)");
}

TEST_CASE("check helpers: strict and inclusive bounds, float compared exactly") {
  CHECK(mptrack::check_range_above(0.0, 0.0, 1.0) == Status::kInvalidArgument);
  CHECK(mptrack::check_range_above(1.0, 0.0, 1.0) == Status::kOk);
  CHECK(mptrack::check_range_below(1.0, 0.0, 1.0) == Status::kInvalidArgument);
  CHECK(mptrack::check_at_least(std::size_t{1}, 1) == Status::kOk);
  CHECK(mptrack::check_above(2.0f, 2.0f) == Status::kInvalidArgument);
  CHECK(mptrack::check_at_most(0.1f, 0.1f) == Status::kOk);  // float 0.1 vs itself: exact in double
  const mptrack::CheckResult r = mptrack::check_open_probability(2.0f);
  CHECK(r.value == 2.0);
  CHECK(r.lo_open);
  CHECK(r.hi_open);
}
