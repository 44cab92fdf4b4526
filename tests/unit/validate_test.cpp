#include <doctest/doctest.h>

#include <limits>

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
